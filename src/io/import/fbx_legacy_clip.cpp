// FBX 6.1 files as clips from our own FBX reader (fbx_legacy.h): joints from the
// Models, keys from the take's curves evaluated at its frames.
#include "fbx_legacy.h"

#include "rotinterp/io/files/distinct_names.h"
#include "rotinterp/io/files/file_record.h"
#include "rotinterp/io/files/key_times.h"

#include "rotinterp/io/fbx/fbx_nodes.h"
#include "rotinterp/io/fbx/fbx_transform.h"
#include "rotinterp/io/files/file_errors.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <set>
#include <utility>

namespace rotinterp {

namespace {

namespace fs = std::filesystem;

// A take longer than this many frames is refused (a hostile LocalTime).
constexpr double kMaxFrames = 1 << 22;
// A translation within this fraction of the figure's size of its offset is still.
constexpr double kStillTranslation = 1e-7;

// Frames per second of GlobalSettings TimeMode (the FBX SDK's FbxTime::EMode); 0: none.
double time_mode_rate(int mode, double custom) {
  static const double rates[] = {0,
                                 120,
                                 100,
                                 60,
                                 50,
                                 48,
                                 30,
                                 30,
                                 30000.0 / 1001,
                                 30000.0 / 1001,
                                 25,
                                 24,
                                 1000,
                                 24000.0 / 1001,
                                 0,
                                 96,
                                 72,
                                 60000.0 / 1001,
                                 120000.0 / 1001};
  if (mode == 14) return custom > 0.0 && std::isfinite(custom) ? custom : 0.0;
  return mode >= 0 && mode < static_cast<int>(std::size(rates)) ? rates[mode] : 0.0;
}

// A GlobalSettings Properties60 value (6.1 keeps GlobalSettings in Objects).
double global_setting(const FbxDocument& doc, const char* name, double fallback) {
  const FbxNode* settings = doc.node("GlobalSettings");
  if (const FbxNode* objects = doc.node("Objects"); !settings && objects) settings = objects->child("GlobalSettings");
  if (!settings) return fallback;
  // 6.1: Property: name, type, flags, value; 7.x: P: name, type, label, flags, value.
  for (const auto& [block, at] : {std::pair{"Properties60", 3u}, std::pair{"Properties70", 4u}})
    if (const FbxNode* props = settings->child(block))
      for (const FbxNode& p : props->children)
        if (p.properties.size() > at && p.properties[0].is_string() && p.properties[0].text == name &&
            p.properties[at].is_number())
          return p.properties[at].as_double();
  return fallback;
}

bool carries_content(const FbxModel& m) {
  static const std::set<std::string> kContent = {"Mesh", "Camera",     "Light", "CameraSwitcher",
                                                 "Nurb", "NurbsCurve", "Patch", "Line"};
  return kContent.count(m.type) > 0;
}

Result<std::size_t> select_take(const FbxAnimation& anim, const std::string& want, const std::string& label) {
  const std::size_t n = anim.takes.size();
  if (want.empty()) return std::size_t{0};
  for (std::size_t t = 0; t < n; ++t)
    if (anim.takes[t].name == want) return t;
  if (std::all_of(want.begin(), want.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); })) {
    const std::size_t index = want.size() > 9 ? n : static_cast<std::size_t>(std::stoul(want));
    if (index < n) return index;
    return make_error(label + ": there is no animation " + want + " (the file has " + std::to_string(n) +
                      ", numbered from 0)");
  }
  std::string names;
  for (std::size_t t = 0; t < n; ++t) names += (t ? ", '" : "'") + anim.takes[t].name + "'";
  return make_error(label + ": no animation named '" + want + "' (the file has " + names + ")");
}

// The joints' models, parents first (depth-first in file order), and each one's parent joint.
std::vector<std::pair<const FbxModel*, int>> select_joints(const FbxAnimation& anim,
                                                           const std::map<std::string, FbxNodeLayers>& animated) {
  const std::size_t n = anim.models.size();
  std::vector<bool> keep(n, false);
  auto index_of = [&](std::int64_t id) {
    return id >= 1 && static_cast<std::size_t>(id) <= n ? static_cast<std::size_t>(id - 1) : n;
  };
  for (std::size_t m = 0; m < n; ++m) {
    const FbxModel& model = anim.models[m];
    const auto a = animated.find(model.name);
    if (!(a != animated.end() && a->second.keyed()) && carries_content(model)) continue;
    // The model and its ancestors (a parent chain is at most n long).
    for (std::size_t at = m, steps = 0; at < n && !keep[at] && steps <= n;
         at = index_of(anim.models[at].parent), ++steps)
      keep[at] = true;
  }
  std::vector<std::vector<std::size_t>> children(n + 1);  // [n]: the roots
  for (std::size_t m = 0; m < n; ++m) {
    const std::size_t parent = index_of(anim.models[m].parent);
    if (keep[m]) children[parent < n && keep[parent] ? parent : n].push_back(m);
  }
  std::vector<std::pair<const FbxModel*, int>> out;
  std::vector<int> joint_of(n, -1);
  std::vector<std::size_t> todo(children[n].rbegin(), children[n].rend());
  while (!todo.empty()) {
    const std::size_t m = todo.back();
    todo.pop_back();
    if (joint_of[m] >= 0) continue;  // a cycle of parents
    const std::size_t p = index_of(anim.models[m].parent);
    joint_of[m] = static_cast<int>(out.size());
    out.emplace_back(&anim.models[m], p < n ? joint_of[p] : -1);
    for (auto c = children[m].rbegin(); c != children[m].rend(); ++c) todo.push_back(*c);
  }
  return out;
}

Vec3 matrix_translation(const Eigen::Matrix4d& m) { return m.block<3, 1>(0, 3); }

std::string short_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// The sample times (seconds from the take's start) of the take: its frames at
// `rate`, or without a rate the union of its key times.
Result<std::vector<double>> sample_times(const FbxTake& take, double rate, const std::string& label) {
  std::vector<double> out;
  const FbxTickSpan ticks_span = fbx_take_span(take);
  const double span = static_cast<double>(ticks_span.stop - ticks_span.start) / static_cast<double>(kFbxTicksPerSecond);
  if (rate > 0.0) {
    if (!(span >= 0.0) || span * rate > kMaxFrames)
      return make_error(label + ": take '" + take.name + "' spans " + short_number(span) +
                        " s, which is not a frame range rotinterp reads");
    const auto frames = static_cast<std::size_t>(std::floor(span * rate + 1e-6));
    for (std::size_t k = 0; k <= frames; ++k) out.push_back(static_cast<double>(k) / rate);
    if (span - out.back() > 1e-6) out.push_back(span);  // a stop off the grid ends the take there
    return out;
  }
  std::set<std::int64_t> ticks;
  for (const FbxCurve& c : take.curves)
    for (const FbxKey& k : c.keys) ticks.insert(k.ticks);
  ticks.insert(ticks_span.start);  // the span's ends are frames, keyed or not
  ticks.insert(ticks_span.stop);
  for (std::int64_t t : ticks)
    if (t >= ticks_span.start && t <= ticks_span.stop)
      out.push_back(static_cast<double>(t - ticks_span.start) / static_cast<double>(kFbxTicksPerSecond));
  if (out.empty()) out.push_back(0.0);
  return out;
}

// Every key time of the take, seconds.
std::vector<double> key_seconds(const FbxTake& take) {
  std::vector<double> out;
  for (const FbxCurve& c : take.curves)
    for (const FbxKey& k : c.keys) out.push_back(static_cast<double>(k.ticks) / static_cast<double>(kFbxTicksPerSecond));
  return out;
}

}  // namespace

bool is_legacy_fbx(const fs::path& path) {
  std::ifstream f(path, std::ios::binary);
  std::string head(4096, '\0');
  f.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(f.gcount()));
  if (is_binary_fbx(head)) {
    if (head.size() < 27) return false;
    const auto byte = [&](std::size_t i) { return static_cast<std::uint32_t>(static_cast<unsigned char>(head[i])); };
    const std::uint32_t version = byte(23) | byte(24) << 8 | byte(25) << 16 | byte(26) << 24;
    return version < 7000;
  }
  for (const char* mark : {"; FBX ", "FBXVersion: "}) {
    const std::size_t at = head.find(mark);
    if (at != std::string::npos && at + std::strlen(mark) < head.size()) {
      const char digit = head[at + std::strlen(mark)];
      return digit >= '1' && digit <= '6';
    }
  }
  return false;
}

Status read_legacy_fbx(const fs::path& path, const ReadOptions& options, ClipFileInfo& info, const Warnings& warn) {
  const std::string label = path.string();
  Result<FbxDocument> doc = read_fbx_file(path, label);
  if (!doc) return make_error(doc.error(), file_error::unreadable);
  Result<FbxAnimation> anim = read_fbx_animation(*doc, label);
  if (!anim) return make_error(anim.error(), file_error::unreadable);
  const double rate = time_mode_rate(static_cast<int>(global_setting(*doc, "TimeMode", 0)),
                                     global_setting(*doc, "CustomFrameRate", -1));
  std::size_t meshes = 0;
  for (const FbxModel& m : anim->models) meshes += m.type == "Mesh";
  bool any_curve = false;
  for (const FbxTake& t : anim->takes) any_curve = any_curve || !t.curves.empty();
  if (!any_curve) {
    info.holds = std::to_string(meshes) + (meshes == 1 ? " mesh, " : " meshes, ") +
                 std::to_string(anim->models.size()) + " models";
    return make_error(label + ": the file has no animation (it holds " + info.holds + ")", file_error::no_animation);
  }
  for (const FbxTake& t : anim->takes) {
    AnimationSummary s;
    s.name = t.name;
    s.ticks_per_second = rate > 0.0 ? rate : static_cast<double>(kFbxTicksPerSecond);
    const FbxTickSpan span = fbx_take_span(t);
    s.duration = static_cast<double>(span.stop - span.start) / static_cast<double>(kFbxTicksPerSecond);
    s.channels = 0;
    for (const auto& [node, layers] : fbx_node_layers(t)) s.channels += layers.keyed();
    s.start = static_cast<double>(span.start) / static_cast<double>(kFbxTicksPerSecond);
    std::set<std::int64_t> keys;
    for (const FbxCurve& c : t.curves)
      for (const FbxKey& k : c.keys)
        if (k.ticks >= span.start && k.ticks <= span.stop) keys.insert(k.ticks);
    s.keys = keys.size();
    s.rate_stated = rate > 0.0;
    if (rate > 0.0) {
      s.frame_rate_hz = rate;
    } else if (const double step = uniform_frame_time(key_seconds(t)); step > 0.0) {
      s.frame_rate_hz = 1.0 / step;
    }
    info.animations.push_back(s);
  }
  Result<std::size_t> selected = select_take(*anim, options.animation, label);
  if (!selected) return selected.failure();
  info.selected = *selected;
  const FbxTake& take = anim->takes[info.selected];
  const std::map<std::string, FbxNodeLayers> animated = fbx_node_layers(take);
  const auto joints = select_joints(*anim, animated);
  Result<std::vector<double>> times = sample_times(take, rate, label);
  if (!times) return times.failure();

  Clip& clip = info.clip;
  clip.name = take.name.empty() ? path.stem().string() : take.name;
  DistinctNames names;
  std::vector<const FbxNodeLayers*> layers_of;
  for (const auto& [model, parent] : joints) {
    Joint joint;
    joint.name = names.take(model->name.empty() ? "model" + std::to_string(model->id) : model->name);
    joint.parent = parent;
    joint.offset = matrix_translation(fbx_node_matrix(*model, fbx_lcl_values(take, *model, nullptr, 0.0)));
    joint.rest_rotation = fbx_node_rotation(*model, model->rotation);
    clip.skeleton.joints.push_back(joint);
    const auto a = animated.find(model->name);
    layers_of.push_back(a != animated.end() && a->second.keyed() ? &a->second : nullptr);
  }
  double size = 0.0;
  for (const Joint& j : clip.skeleton.joints) size = std::max(size, j.offset.norm());
  clip.rotations.assign(joints.size(), RotationTrack{});
  clip.translations.assign(joints.size(), std::nullopt);
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const FbxModel& model = *joints[j].first;
    RotationTrack& rotation = clip.rotations[j];
    if (!layers_of[j]) {
      rotation.times = {times->front()};
      rotation.keys = {clip.skeleton.joints[j].rest_rotation};
      continue;
    }
    TranslationTrack translation;
    bool moves = false, scaled = false;
    for (double t : *times) {
      const double ticks = static_cast<double>(fbx_take_span(take).start) + t * static_cast<double>(kFbxTicksPerSecond);
      const FbxLclValues values = fbx_lcl_values(take, model, layers_of[j], ticks);
      rotation.times.push_back(t);
      rotation.keys.push_back(fbx_node_rotation(model, values.rotation));
      translation.times.push_back(t);
      translation.keys.push_back(matrix_translation(fbx_node_matrix(model, values)));
      moves = moves || (translation.keys.back() - clip.skeleton.joints[j].offset).norm() >
                           kStillTranslation * std::max(size, 1e-9);
      for (double s : values.scaling) scaled = scaled || std::abs(s - 1.0) > 1e-5;
    }
    rotation.make_sign_continuous();
    if (moves) clip.translations[j] = std::move(translation);
    if (scaled) warn(label + ": joint '" + clip.skeleton.joints[j].name + "' is scaled; the scale is ignored");
  }
  if (rate > 0.0)
    clip.frame_time = 1.0 / rate, set_file_rate_hz(clip, rate);
  else
    clip.frame_time = uniform_frame_time(*times);  // as the assimp path infers it
  clip.source_meshes = meshes;
  if (const double f = global_setting(*doc, "UnitScaleFactor", 0.0); f > 0.0 && std::isfinite(f))
    clip.unit = {f * 0.01, UnitOrigin::declared, "declared by the file: FBX UnitScaleFactor " + short_number(f)};
  if (options.read_curves) info.curves = std::move(*anim);
  return Ok{};
}

}  // namespace rotinterp
