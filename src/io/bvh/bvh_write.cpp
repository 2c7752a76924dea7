// The BVH writer: the clip's hierarchy and channel layout, Euler angles nearest the
// previous frame, 6 decimals.
#include "rotinterp/io/bvh/bvh.h"
#include "rotinterp/core/work_queue.h"
#include "rotinterp/io/files/euler.h"
#include "rotinterp/clip/frames.h"
#include "rotinterp/io/files/fixed6.h"
#include "rotinterp/io/files/written_names.h"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <exception>
#include <cmath>
#include <optional>
#include <ostream>
#include <set>
#include <string>
#include <system_error>
#include <thread>
#include <unordered_set>

namespace rotinterp {

namespace {

// A multi-key track must sit on the grid start + k·frame_time within this fraction
// of a frame: resamplers compute times as start + k/rate, so anything beyond
// round-off means the clip was not resampled.
constexpr double kGridTolerance = 1e-6;

// A joint whose rotation channels cannot express every rotation (one or two axes,
// or none) must reproduce the clip's rotation within this angle (radians, 1e-6 rad
// = 5.7e-5°, below the 1e-4° round-trip promise).
constexpr double kReducedLayoutTolerance = 1e-6;

// A rotation to write is the source file's own (BvhSourceAngles) when its Euler
// triple gives it within this angle: the 1e-9 rad every method keeps at its keys.
constexpr double kSameRotation = 1e-9;

// HIERARCHY indentation stops growing past this depth (it is whitespace to every
// reader): a chain thousands of joints deep would otherwise make the file
// quadratic in its depth (20 000 joints: 400 MB of tabs).
constexpr std::size_t kMaxIndent = 64;

Channel rotation_channel(int axis) { return static_cast<Channel>(3 + axis); }
Channel position_channel(int axis) { return static_cast<Channel>(axis); }

void append_number(std::string& out, double v, bool fixed) {
  char buf[kFixed6MaxChars];
  if (fixed) {
    // Round first so that a value that prints as zero prints as "0.000000", not "-0.000000".
    if (std::abs(v) < 5e-7) v = 0.0;
    out.append(buf, write_fixed6(buf, buf + sizeof buf, v));
  } else {
    auto r = std::to_chars(buf, buf + sizeof buf, v);  // shortest text that reads back exactly
    out.append(buf, r.ptr);
  }
}

// How one joint's rotation becomes its rotation channel values.
struct RotationPlan {
  std::vector<std::size_t> columns;  // indices into the joint's channels, in order
  std::vector<int> axes;             // axis of each rotation channel
  // Exact case: a valid Euler triple at these positions of `columns`; other rotation
  // channels stay 0.
  int triple[3] = {-1, -1, -1};
  EulerAxes triple_axes{};
  // Reduced case (no valid triple): the distinct axes used (1 or 2), at these positions.
  std::vector<int> reduced_pos;
};

RotationPlan plan_rotation(const std::vector<Channel>& channels) {
  RotationPlan p;
  for (std::size_t c = 0; c < channels.size(); ++c)
    if (is_rotation(channels[c])) {
      p.columns.push_back(c);
      p.axes.push_back(axis_of(channels[c]));
    }
  const int n = static_cast<int>(p.axes.size());
  for (int i = 0; i < n && p.triple[0] < 0; ++i)
    for (int j = i + 1; j < n && p.triple[0] < 0; ++j)
      for (int k = j + 1; k < n && p.triple[0] < 0; ++k) {
        const EulerAxes a{p.axes[i], p.axes[j], p.axes[k]};
        if (is_valid_euler_axes(a)) {
          p.triple[0] = i, p.triple[1] = j, p.triple[2] = k;
          p.triple_axes = a;
        }
      }
  if (p.triple[0] < 0) {
    // First occurrence of each distinct axis (at most two distinct axes here, or
    // the same axis twice in a row).
    std::set<int> seen;
    for (int i = 0; i < n; ++i)
      if (seen.insert(p.axes[i]).second) p.reduced_pos.push_back(i);
  }
  return p;
}

// The source file's rotation numbers for joint j (BvhSourceAngles) where the writer
// can give them back: its layout is the file's, with three rotation channels that
// make a triple; null otherwise.
const std::vector<double>* source_degrees(const Clip& clip, std::size_t j, const RotationPlan& p) {
  const BvhLayout* layout = bvh_layout(clip);
  const BvhSourceAngles* angles = layout ? layout->source_angles.get() : nullptr;
  if (!angles || j >= angles->degrees.size() || p.columns.size() != 3 || p.triple[0] < 0) return nullptr;
  if (bvh_channels(clip, j).empty() || angles->degrees[j].size() != 3 * angles->frames) return nullptr;
  return &angles->degrees[j];
}

// The source frame at the writer's frame f, for each f; -1 where the source has none.
// At the source's frame time, frame f is the source's source_first_frame + f; at
// another rate, the source frame within kFrameSnap of f's time, if any (every 4th
// frame of 120 Hz at 30 Hz). Only a match: joint_values checks the rotation.
std::vector<std::ptrdiff_t> source_frames(const Clip& clip, std::size_t frames) {
  std::vector<std::ptrdiff_t> out(frames, -1);
  const BvhLayout* layout = bvh_layout(clip);
  const BvhSourceAngles* angles = layout ? layout->source_angles.get() : nullptr;
  if (!angles || !(angles->frame_time > 0.0)) return out;
  const std::size_t first = layout->source_first_frame;
  for (std::size_t f = 0; f < frames; ++f) {
    const double t = static_cast<double>(f) * clip.frame_time;
    const double at = clip.frame_time == angles->frame_time ? static_cast<double>(f) : std::round(t / angles->frame_time);
    if (std::abs(t - at * angles->frame_time) > kFrameSnap * angles->frame_time) continue;
    const double i = at + static_cast<double>(first);
    if (i < static_cast<double>(angles->frames)) out[f] = static_cast<std::ptrdiff_t>(i);
  }
  return out;
}

// One joint's channel values at frame f, in its layout's order, into `out`.
// `previous` is the joint's Euler angles at the frame before (updated). `source`:
// the file's own three rotation numbers at this time, given back where they make
// the rotation to write (or null).
Status joint_values(const Clip& clip, std::size_t j, std::size_t f, const std::vector<Channel>& layout,
                    const RotationPlan& p, const double* source, Vec3& previous, const std::string& label,
                    double* out) {
  const Skeleton& sk = clip.skeleton;
  const RotationTrack& rt = clip.rotations[j];
  const Quat q = rt.keys[rt.keys.size() == 1 ? 0 : f];
  Vec3 t = sk.joints[j].offset;
  if (clip.translations[j]) t = clip.translations[j]->keys[clip.translations[j]->keys.size() == 1 ? 0 : f];
  for (std::size_t c = 0; c < layout.size(); ++c) out[c] = is_rotation(layout[c]) ? 0.0 : t[axis_of(layout[c])];
  if (p.triple[0] >= 0 && source) {
    const Vec3 e = Vec3(source[p.triple[0]], source[p.triple[1]], source[p.triple[2]]) * (kPi / 180.0);
    if (angular_distance(q, euler_to_quat(p.triple_axes, e)) <= kSameRotation) {
      previous = e;
      for (int i = 0; i < 3; ++i) out[p.columns[static_cast<std::size_t>(p.triple[i])]] = source[p.triple[i]];
      return Ok{};
    }
  }
  if (p.triple[0] >= 0) {
    const Vec3 e = euler_nearest(q, p.triple_axes, previous);
    previous = e;
    for (int i = 0; i < 3; ++i) out[p.columns[static_cast<std::size_t>(p.triple[i])]] = e[i] * (180.0 / kPi);
    return Ok{};
  }
  Quat written = Quat::Identity();
  if (!p.reduced_pos.empty()) {
    // One or two distinct axes: complete them to a Tait–Bryan triple, keep the
    // leading angles and check that the dropped one is zero.
    const int a0 = p.axes[static_cast<std::size_t>(p.reduced_pos[0])];
    const int a1 = p.reduced_pos.size() > 1 ? p.axes[static_cast<std::size_t>(p.reduced_pos[1])] : (a0 + 1) % 3;
    const EulerAxes full{a0, a1, 3 - a0 - a1};
    Vec3 e = euler_nearest(q, full, previous);
    if (p.reduced_pos.size() == 1) {
      // A hinge: the twist angle about its axis.
      const double twist = 2.0 * std::atan2(q.vec()[a0], q.w());
      e = Vec3(previous[0] + std::remainder(twist - previous[0], kTwoPi), 0.0, 0.0);
    } else {
      e[2] = 0.0;
    }
    previous = e;
    for (std::size_t i = 0; i < p.reduced_pos.size(); ++i)
      out[p.columns[static_cast<std::size_t>(p.reduced_pos[i])]] = e[static_cast<Eigen::Index>(i)] * (180.0 / kPi);
    written = euler_to_quat(full, e);
  }
  const double off = angular_distance(q, written);
  if (off > kReducedLayoutTolerance)
    return make_error(label + ": frame " + std::to_string(f) + ", joint '" + sk.joints[j].name +
                      "': its BVH channels cannot express the rotation (off by " + std::to_string(off * 180.0 / kPi) +
                      " degrees)");
  return Ok{};
}

}  // namespace

Status write_bvh(const Clip& clip, std::ostream& out, const WriteOptions& options, const std::string& label) {
  if (Status s = clip.validate(); !s) return s.failure(label + ": cannot write an invalid clip: ");
  const Skeleton& sk = clip.skeleton;
  const std::size_t n = sk.joints.size();
  const double ft = clip.frame_time;
  if (!(ft > 0.0))
    return make_error(label + ": BVH needs a uniform frame time; the clip has none (resample it first)");
  const auto default_axes = parse_euler_order(options.bvh_order);
  if (!default_axes) return make_error(label + ": '" + options.bvh_order + "' is not a rotation order (e.g. ZXY)");

  // The uniform grid every multi-key track must sit on.
  const double start = clip.start_time();
  const std::size_t frames = clip.frame_count();
  auto on_grid = [&](const std::vector<double>& times, const std::string& joint) -> Status {
    if (times.size() == 1) return Ok{};
    if (times.size() != frames)
      return make_error(label + ": joint '" + joint + "' has " + std::to_string(times.size()) + " keys, the frame grid " +
                        std::to_string(frames) + " frames; BVH needs every track sampled on one uniform grid (resample first)");
    for (std::size_t k = 0; k < times.size(); ++k)
      if (std::abs(times[k] - (start + static_cast<double>(k) * ft)) > kGridTolerance * ft)
        return make_error(label + ": joint '" + joint + "' key " + std::to_string(k) + " at " + std::to_string(times[k]) +
                          " s is not on the frame grid (frame time " + std::to_string(ft) + " s); resample first");
    return Ok{};
  };

  // Channel layout per joint.
  std::vector<std::vector<Channel>> layout(n);
  const std::vector<std::string> names = written_joint_names(sk, NameForm::bvh_token);
  for (std::size_t j = 0; j < n; ++j) {
    const Joint& joint = sk.joints[j];
    if (Status s = on_grid(clip.rotations[j].times, joint.name); !s) return s;
    if (clip.translations[j])
      if (Status s = on_grid(clip.translations[j]->times, joint.name); !s) return s;
    if (const std::vector<Channel>& channels = bvh_channels(clip, j); !channels.empty()) {
      layout[j] = channels;
      bool has_position = false;
      for (Channel c : channels) has_position = has_position || !is_rotation(c);
      if (clip.translations[j] && !has_position)
        return make_error(label + ": joint '" + joint.name +
                          "' has a translation track but its BVH channels have no position channel");
    } else {
      if (clip.translations[j])
        for (int a = 0; a < 3; ++a) layout[j].push_back(position_channel(a));
      for (int a : *default_axes) layout[j].push_back(rotation_channel(a));
    }
  }

  // Children lists (clip order), End Sites per joint.
  std::vector<std::vector<std::size_t>> children(n), sites(n);
  std::vector<std::size_t> roots;
  for (std::size_t j = 0; j < n; ++j) {
    if (sk.joints[j].parent < 0) roots.push_back(j);
    else children[static_cast<std::size_t>(sk.joints[j].parent)].push_back(j);
  }
  for (std::size_t e = 0; e < sk.end_sites.size(); ++e) sites[static_cast<std::size_t>(sk.end_sites[e].parent)].push_back(e);

  // Several roots (an FBX with IK targets beside the skeleton): one synthetic ROOT at
  // the origin above them, 6 channels all zero, so that every BVH reader takes the
  // file; the clip's roots become its JOINTs.
  std::string synthetic_root;
  if (roots.size() > 1) {
    const std::unordered_set<std::string> taken(names.begin(), names.end());
    synthetic_root = "rotinterp_root";
    for (int k = 2; taken.count(synthetic_root); ++k) synthetic_root = "rotinterp_root#" + std::to_string(k);
  }
  const std::size_t lead_columns = synthetic_root.empty() ? 0 : 6;

  // HIERARCHY, recording the emission order (the motion columns follow it). An
  // explicit stack, not recursion: skeletons may be thousands of joints deep.
  std::string text = "HIERARCHY\n";
  std::vector<std::size_t> order;
  auto offset_line = [&](const std::string& indent, const Vec3& o) {
    text += indent + "OFFSET";
    for (int a = 0; a < 3; ++a) {
      text += ' ';
      append_number(text, o[a], false);
    }
    text += '\n';
  };
  const std::size_t base_depth = lead_columns ? 1 : 0;
  if (lead_columns)
    text += "ROOT " + synthetic_root + "\n{\n\tOFFSET 0 0 0\n\tCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n";
  struct Step {
    std::size_t joint, depth;
    bool close;
  };
  std::vector<Step> stack;
  for (auto r = roots.rbegin(); r != roots.rend(); ++r) stack.push_back({*r, base_depth, false});
  while (!stack.empty()) {
    const Step step = stack.back();
    stack.pop_back();
    const std::size_t j = step.joint;
    const std::string in(std::min(step.depth, kMaxIndent), '\t');
    if (step.close) {
      for (std::size_t e : sites[j]) {
        text += in + "\tEnd Site\n" + in + "\t{\n";
        offset_line(in + "\t\t", sk.end_sites[e].offset);
        text += in + "\t}\n";
      }
      text += in + "}\n";
      continue;
    }
    order.push_back(j);
    text += in + (step.depth == 0 ? "ROOT " : "JOINT ") + names[j] + "\n" + in + "{\n";
    offset_line(in + "\t", sk.joints[j].offset);
    text += in + "\tCHANNELS " + std::to_string(layout[j].size());
    for (Channel c : layout[j]) text += std::string(" ") + channel_name(c);
    text += '\n';
    stack.push_back({j, step.depth, true});
    for (auto c = children[j].rbegin(); c != children[j].rend(); ++c) stack.push_back({*c, step.depth + 1, false});
  }
  if (lead_columns) text += "}\n";

  text += "MOTION\nFrames: " + std::to_string(frames) + "\nFrame Time: ";
  double parsed = 0.0;
  const std::string& ftt = frame_time_text(clip);
  if (!ftt.empty() && std::from_chars(ftt.data(), ftt.data() + ftt.size(), parsed).ec == std::errc() && parsed == ft)
    text += ftt;
  else
    append_number(text, ft, false);
  text += '\n';
  out << text;
  text.clear();

  // MOTION rows, in blocks of frames: first every joint's values for the block
  // (joints are independent: two threads for long clips; each joint's Euler angles
  // follow its previous frame), then the text, row by row.
  std::vector<RotationPlan> plans(n);
  std::vector<Vec3> previous(n, Vec3::Zero());
  std::vector<const std::vector<double>*> sources(n);
  for (std::size_t j = 0; j < n; ++j) {
    plans[j] = plan_rotation(layout[j]);
    sources[j] = source_degrees(clip, j, plans[j]);
  }
  const std::vector<std::ptrdiff_t> source_frame = source_frames(clip, frames);
  std::vector<std::size_t> first_column(n);  // of each joint in a row
  std::size_t columns = lead_columns;  // the synthetic root's columns stay 0
  for (std::size_t j : order) first_column[j] = columns, columns += layout[j].size();
  constexpr std::size_t kBlockFrames = 4096;
  constexpr std::size_t kMinValuesForThreads = 200000;
  const bool two_threads = frames * columns >= kMinValuesForThreads && n > 1 && thread_count(options.threads) > 1;
  std::vector<double> block(std::min(frames, kBlockFrames) * columns);
  std::vector<Status> status(n, Status(Ok{}));
  std::vector<std::size_t> failed_frame(n, frames);
  for (std::size_t f0 = 0; f0 < frames; f0 += kBlockFrames) {
    const std::size_t f1 = std::min(frames, f0 + kBlockFrames);
    std::atomic<std::size_t> next{0};
    auto work = [&] {
      for (std::size_t j = next++; j < n; j = next++)
        for (std::size_t f = f0; f < f1; ++f)
          if (Status s = joint_values(clip, j, f, layout[j], plans[j],
                                      sources[j] && source_frame[f] >= 0
                                          ? sources[j]->data() + 3 * static_cast<std::size_t>(source_frame[f])
                                          : nullptr,
                                      previous[j], label, block.data() + (f - f0) * columns + first_column[j]);
              !s) {
            status[j] = s;
            failed_frame[j] = f;
            break;
          }
    };
    std::exception_ptr helper_error;  // e.g. bad_alloc, rethrown here
    std::optional<std::thread> helper;
    if (two_threads) {
      try {
        helper.emplace([&] {
          try {
            work();
          } catch (...) {
            helper_error = std::current_exception();
            next = n;
          }
        });
      } catch (const std::system_error&) {
        // No thread available: this one does all the work.
      }
    }
    try {
      work();
    } catch (...) {
      next = n;
      if (helper) helper->join();
      throw;
    }
    if (helper) helper->join();
    if (helper_error) std::rethrow_exception(helper_error);
    // The first failure in row order, as a frame-by-frame writer meets it.
    const std::size_t* first = nullptr;
    for (const std::size_t& j : order)
      if (!status[j] && (!first || failed_frame[j] < failed_frame[*first])) first = &j;
    if (first) return status[*first];
    for (std::size_t f = f0; f < f1; ++f) {
      const double* row = block.data() + (f - f0) * columns;
      for (std::size_t c = 0; c < columns; ++c) {
        if (c > 0) text += ' ';
        append_number(text, row[c], true);
      }
      text += '\n';
    }
    if (text.size() > (1u << 20)) {
      out << text;
      text.clear();
    }
  }
  out << text;
  return Ok{};
}

}  // namespace rotinterp
