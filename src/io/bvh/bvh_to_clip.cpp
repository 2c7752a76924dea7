// A parsed BVH file as a clip: its skeleton, layout and every frame's rotations
// and translations (BvhFile's accessors; long files on two threads).
#include "rotinterp/io/files/huge_pages.h"
#include "rotinterp/io/bvh/bvh.h"
#include "rotinterp/io/files/formats.h"
#include "rotinterp/core/work_queue.h"

#include <cmath>
#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace rotinterp {

namespace {

// The value columns of a joint's rotation channels, in file order.
std::vector<std::size_t> rotation_columns(const BvhJoint& j) {
  std::vector<std::size_t> out;
  for (std::size_t c = 0; c < j.channels.size(); ++c)
    if (is_rotation(j.channels[c])) out.push_back(j.first_column + c);
  return out;
}

}  // namespace

Quat BvhFile::rotation(std::size_t frame, std::size_t joint) const {
  Quat q = Quat::Identity();
  const BvhJoint& j = joints[joint];
  for (std::size_t c = 0; c < j.channels.size(); ++c)
    if (is_rotation(j.channels[c]))
      q = q * Quat(Eigen::AngleAxisd(value(frame, joint, c) * (kPi / 180.0), Vec3::Unit(axis_of(j.channels[c]))));
  return q.normalized();
}

Vec3 BvhFile::translation(std::size_t frame, std::size_t joint) const {
  Vec3 t = joints[joint].offset;
  const BvhJoint& j = joints[joint];
  for (std::size_t c = 0; c < j.channels.size(); ++c)
    if (!is_rotation(j.channels[c])) t[axis_of(j.channels[c])] = value(frame, joint, c);
  return t;
}

bool BvhFile::has_position_channels(std::size_t joint) const {
  for (Channel c : joints[joint].channels)
    if (!is_rotation(c)) return true;
  return false;
}

Skeleton bvh_skeleton(const BvhFile& file) {
  Skeleton s;
  for (const BvhJoint& j : file.joints) s.joints.push_back(Joint{j.name, j.parent, j.offset, Quat::Identity()});
  for (const BvhEndSite& e : file.end_sites)
    s.end_sites.push_back(EndSite{e.parent, e.offset, "EndSite_" + file.joints[static_cast<std::size_t>(e.parent)].name});
  return s;
}

BvhLayout bvh_layout(const BvhFile& file) {
  BvhLayout layout;
  auto angles = std::make_shared<BvhSourceAngles>();
  angles->frame_time = file.frame_time;
  angles->frames = file.frames;
  for (const BvhJoint& j : file.joints) {
    layout.channels.push_back(j.channels);
    const std::vector<std::size_t> columns = rotation_columns(j);
    std::vector<double>& degrees = angles->degrees.emplace_back();
    degrees.reserve(file.frames * columns.size());
    for (std::size_t f = 0; f < file.frames; ++f)
      for (std::size_t column : columns) degrees.push_back(file.values[f * file.columns + column]);
  }
  layout.source_angles = std::move(angles);
  layout.frame_time_text = file.frame_time_text;
  return layout;
}

namespace {

struct RotationLayout {
  std::vector<std::size_t> column;  // value column of each rotation channel, in order
  std::vector<int> axis;
};

// Frames [f0, f1) of every joint, row by row (the values are row-major: going
// joint by joint would stream the whole table once per joint). Each rotation is
// the product of the joint's rotation channels (as BvhFile::rotation), normalized
// and on the side of the previous frame's key within the range.
void convert_frames(const BvhFile& file, const std::vector<RotationLayout>& layouts, std::size_t f0, std::size_t f1,
                    Clip& clip) {
  const std::size_t n = file.joints.size();
  for (std::size_t f = f0; f < f1; ++f) {
    const double* row = file.values.data() + f * file.columns;
    for (std::size_t j = 0; j < n; ++j) {
      const RotationLayout& l = layouts[j];
      Quat q = Quat::Identity();
      for (std::size_t i = 0; i < l.column.size(); ++i) {
        const double half = 0.5 * (row[l.column[i]] * (kPi / 180.0));
        Quat a(std::cos(half), 0.0, 0.0, 0.0);
        a.vec()[l.axis[i]] = std::sin(half);
        q = q * a;
      }
      q.normalize();  // a product of unit quaternions: its norm is 1 up to round-off
      std::vector<Quat>& keys = clip.rotations[j].keys;
      if (f > f0 && q.dot(keys[f - 1]) < 0.0) q.coeffs() = -q.coeffs();
      keys[f] = q;
      if (clip.translations[j]) clip.translations[j]->keys[f] = file.translation(f, j);
    }
  }
}

}  // namespace

Clip bvh_to_clip(const BvhFile& file, const std::string& name, unsigned threads) {
  Clip clip;
  clip.name = name;
  clip.skeleton = bvh_skeleton(file);
  clip.frame_time = file.frame_time;
  set_bvh_layout(clip, bvh_layout(file));
  clip.source_format = format_info(FormatId::bvh).name;
  const std::size_t n = file.joints.size();
  const std::size_t frames = file.frames;
  std::vector<double> times(frames);
  for (std::size_t f = 0; f < frames; ++f) times[f] = static_cast<double>(f) * file.frame_time;
  std::vector<RotationLayout> layouts(n);
  clip.rotations.resize(n);
  clip.translations.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    const BvhJoint& joint = file.joints[j];
    layouts[j].column = rotation_columns(joint);
    for (std::size_t column : layouts[j].column) layouts[j].axis.push_back(axis_of(joint.channels[column - joint.first_column]));
    clip.rotations[j].times = times;
    clip.rotations[j].keys.resize(frames);  // not touched yet: a Quat's default constructor leaves it
    advise_huge_pages(clip.rotations[j].keys.data(), frames * sizeof(Quat));
    if (file.has_position_channels(j)) clip.translations[j] = TranslationTrack{times, std::vector<Vec3>(frames)};
  }
  // Long files convert on two threads, each half of the frames (the work is
  // trigonometry and first-touch page faults of the new tracks).
  constexpr std::size_t kMinValuesForThreads = 200000;
  std::size_t split = frames;
  std::exception_ptr helper_error;  // e.g. bad_alloc, rethrown here for read_clip to report
  std::optional<std::thread> helper;
  if (file.values.size() >= kMinValuesForThreads && thread_count(threads) > 1) {
    split = frames / 2;
    try {
      helper.emplace([&] {
        try {
          convert_frames(file, layouts, split, frames, clip);
        } catch (...) {
          helper_error = std::current_exception();
        }
      });
    } catch (const std::system_error&) {
      split = frames;  // no thread available: this one does all the work
    }
  }
  try {
    convert_frames(file, layouts, 0, split, clip);
  } catch (...) {
    if (helper) helper->join();
    throw;
  }
  if (helper) helper->join();
  if (helper_error) std::rethrow_exception(helper_error);
  // The second half joins the first one's sign.
  if (split > 0 && split < frames)
    for (RotationTrack& r : clip.rotations)
      if (r.keys[split].dot(r.keys[split - 1]) < 0.0)
        for (std::size_t f = split; f < frames; ++f) r.keys[f].coeffs() = -r.keys[f].coeffs();
  return clip;
}

}  // namespace rotinterp
