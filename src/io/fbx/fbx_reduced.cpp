// encode_reduced_fbx: a reduced clip's kept keys as FBX Euler curves replaying its method, keys added until our reader's replay is within budget.
#include "rotinterp/io/fbx/fbx_reduced.h"

#include "fbx_replay.h"
#include "rotinterp/io/fbx/fbx_write.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/io/files/euler.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace rotinterp {

namespace {

constexpr double kDegrees = 180.0 / kPi;
// The step of the one-sided slopes, as a fraction of the shortest frame spacing: far
// inside the segment on that side, far above round-off (second-order differences).
constexpr double kSlopeStep = 1e-3;

// One joint's keys as frame indices (sorted), and which take the source's value.
struct TrackKeys {
  std::vector<std::size_t> frames;
  std::vector<bool> source_value;  // per frame of the grid
  bool has(std::size_t f) const { return std::binary_search(frames.begin(), frames.end(), f); }
  void add(std::size_t f) { frames.insert(std::upper_bound(frames.begin(), frames.end(), f), f); }
};

// A joint's rotation through its method, as its Lcl Rotation in Euler angles
// (radians, in the sequence's order) continuous from frame to frame.
class EulerCurve {
 public:
  EulerCurve(std::unique_ptr<Interpolator> m, const FbxJointFrame& joint, const std::vector<double>& times, double step)
      : method_(std::move(m)), joint_(joint), times_(times), step_(step) {
    Vec3 previous = Vec3::Zero();
    for (double t : times) {
      rotations_.push_back(method_->evaluate(t));
      frames_.push_back(previous = euler_nearest(joint_.lcl_rotation(rotations_.back()), joint_.axes, previous));
    }
  }
  const EulerAxes& axes() const { return joint_.axes; }
  const FbxJointFrame& joint() const { return joint_; }
  const Vec3& frame(std::size_t f) const { return frames_[f]; }
  const Quat& rotation(std::size_t f) const { return rotations_[f]; }  // the clip's, not the Lcl one
  // One-sided slopes (radians per second) at frame f, from the curve left or right of it.
  Vec3 slope(std::size_t f, double side) const {
    const double h = side * step_, t = times_[f];
    const Vec3& e0 = frames_[f];
    const Vec3 e1 = at(t + h, e0), e2 = at(t + 2.0 * h, e1);
    return (-3.0 * e0 + 4.0 * e1 - e2) / (2.0 * h);
  }

 private:
  Vec3 at(double t, const Vec3& near) const {
    return euler_nearest(joint_.lcl_rotation(method_->evaluate(t)), joint_.axes, near);
  }
  std::unique_ptr<Interpolator> method_;
  FbxJointFrame joint_;
  const std::vector<double>& times_;
  double step_;
  std::vector<Quat> rotations_;
  std::vector<Vec3> frames_;
};

FbxOutKey out_key(std::int64_t ticks, double value) { return {ticks, static_cast<float>(value), false, 0.0f, 0.0f}; }

// The Lcl Rotation curves (degrees) of one joint through `keys`.
std::array<FbxOutCurve, 3> rotation_curves(const EulerCurve& curve, const TrackKeys& keys, const std::vector<Quat>& source,
                                           const std::vector<std::int64_t>& ticks, bool cubic) {
  std::array<FbxOutCurve, 3> out;
  const EulerAxes& axes = curve.axes();
  const std::size_t last = ticks.size() - 1;
  for (std::size_t k = 0; k < keys.frames.size(); ++k) {
    const std::size_t f = keys.frames[k];
    const Vec3 value =
        keys.source_value[f] ? euler_nearest(curve.joint().lcl_rotation(source[f]), axes, curve.frame(f)) : curve.frame(f);
    const Vec3 right = cubic && f < last ? curve.slope(f, 1.0) : Vec3::Zero();
    const bool has_next = k + 1 < keys.frames.size();
    const Vec3 next_left = cubic && has_next ? curve.slope(keys.frames[k + 1], -1.0) : Vec3::Zero();
    for (std::size_t i = 0; i < 3; ++i) {
      const auto s = static_cast<Eigen::Index>(i);
      FbxOutKey key = out_key(ticks[f], value[s] * kDegrees);
      key.cubic = cubic;
      key.right_slope = static_cast<float>(right[s] * kDegrees);
      key.next_left_slope = static_cast<float>(next_left[s] * kDegrees);
      out[static_cast<std::size_t>(axes[i])].push_back(key);
    }
  }
  return out;
}

// The Lcl Translation curves of one joint through `keys`: the translation curve's
// values and Hermite tangents (exact in FBX's cubic where the joint's frame has no
// rotated pivot), or linear keys; each value through the joint's frame with the
// rotation of `rotations` there.
std::array<FbxOutCurve, 3> translation_curves(const TranslationCurve& curve, const TrackKeys& keys,
                                              const std::vector<Vec3>& source, const std::vector<double>& times,
                                              const std::vector<std::int64_t>& ticks, bool cubic,
                                              const EulerCurve& rotations) {
  const FbxJointFrame& joint = rotations.joint();
  std::array<FbxOutCurve, 3> out;
  const double end = times[keys.frames.back()];
  // The curve's slope at a key time (its last key's from inside).
  auto slope = [&](std::size_t f) { return curve.derivative(f == keys.frames.back() ? std::nextafter(end, -1e300) : times[f]); };
  for (std::size_t k = 0; k < keys.frames.size(); ++k) {
    const std::size_t f = keys.frames[k];
    const Vec3 value = joint.lcl_translation(keys.source_value[f] ? source[f] : curve.evaluate(times[f]), rotations.rotation(f));
    const Vec3 right = cubic ? Vec3(slope(f) / joint.parent_scale) : Vec3::Zero();
    const Vec3 next_left =
        cubic && k + 1 < keys.frames.size() ? Vec3(slope(keys.frames[k + 1]) / joint.parent_scale) : Vec3::Zero();
    for (std::size_t a = 0; a < 3; ++a) {
      const auto s = static_cast<Eigen::Index>(a);
      FbxOutKey key = out_key(ticks[f], value[s]);
      key.cubic = cubic;
      key.right_slope = static_cast<float>(right[s]);
      key.next_left_slope = static_cast<float>(next_left[s]);
      out[a].push_back(key);
    }
  }
  return out;
}

Result<TrackKeys> frames_of(const std::vector<double>& times, const FrameGrid& grid, const std::string& what) {
  TrackKeys keys;
  keys.source_value.assign(grid.size(), false);
  for (double t : times) {
    const std::optional<std::size_t> f = grid.frame_at(t);
    if (!f) return make_error(what + ": a key at " + std::to_string(t) + " s lies on no source frame");
    if (keys.frames.empty() || *f > keys.frames.back()) keys.frames.push_back(*f);
  }
  if (keys.frames.empty()) return make_error(what + ": no keys");
  return keys;
}

// How far over its budget (> 1: over) a joint is at a frame, rotation and shell.
double over_rotation(const FbxReplayErrors& e, const FbxJointBudget& b, std::size_t j, std::size_t f) {
  double r = 0.0;
  if (b.rotation_deg > 0.0) r = e.rotation_deg[j][f] / b.rotation_deg;
  if (b.shell > 0.0) r = std::max(r, e.shell[j][f] / b.shell);
  return r;
}

// Adds, in every interval of `keys`, its worst frame over budget (ratio > 1;
// `skip` frames left out); makes key frames over budget take the source's value.
// Returns the key frames over budget that already did, and whether anything changed.
bool repair(TrackKeys& keys, const std::vector<double>& ratio, const std::vector<bool>& skip,
            std::vector<std::size_t>& stuck, std::size_t& added, std::size_t& corrected) {
  bool changed = false;
  const std::vector<std::size_t> frames = keys.frames;
  for (std::size_t k = 0; k + 1 < frames.size(); ++k) {
    std::size_t worst = 0;
    double worst_ratio = 1.0;
    for (std::size_t f = frames[k] + 1; f < frames[k + 1]; ++f)
      if (!skip[f] && ratio[f] > worst_ratio) worst = f, worst_ratio = ratio[f];
    if (worst) keys.add(worst), ++added, changed = true;
  }
  for (std::size_t f : frames) {
    if (skip[f] || ratio[f] <= 1.0) continue;
    if (!keys.source_value[f]) keys.source_value[f] = true, ++corrected, changed = true;
    else stuck.push_back(f);
  }
  return changed;
}

}  // namespace

Result<FbxReducedResult> encode_reduced_fbx(const Clip& reduced, const Clip& source, const FbxReducedOptions& options) {
  if (Status s = reduced.validate(); !s) return s.failure("cannot write an invalid clip: ");
  if (Status s = source.validate(); !s) return s.failure("cannot write an invalid clip: ");
  const Skeleton& sk = reduced.skeleton;
  const std::size_t n = sk.joints.size();
  if (source.skeleton.joints.size() != n || options.budgets.size() != n)
    return make_error("FBX curves: the reduced clip, its source and the budgets differ in joints");
  const MethodInfo* method = find_method(options.method);
  if (!method) return make_error(unknown_method_message(options.method));
  const bool cubic_rotations = method->name != "slerp" && method->name != "nlerp";
  const bool cubic_translations = options.translation == TranslationInterp::cubic;

  const DenseClip dense = dense_clip(source);
  const FrameGrid& grid = dense.grid;
  const std::size_t frames = grid.size();
  if (frames < 2) return make_error("FBX curves: the source has fewer than two frames");
  // Each joint's frame: a character's models' conventions, else our writer's own.
  FbxCharacterJoints joints;
  const FbxTake* take = options.character ? fbx_character_source_take(*options.character, reduced.name) : nullptr;
  if (options.character) {
    auto models = fbx_character_joints(reduced, *options.character, take);
    if (!models) return models.failure();
    joints = std::move(*models);
  } else {
    joints.frames.resize(n);
    for (std::size_t j = 0; j < n; ++j) joints.frames[j].axes = fbx_joint_axes(reduced, j);
  }
  // A character's keys lie on its source take's time axis (io/fbx/fbx_character.h).
  std::vector<std::int64_t> ticks = fbx_ticks(grid.times, grid.rate);
  if (take)
    for (std::int64_t& t : ticks) t += fbx_take_span(*take).start;
  const bool ascii = options.ascii || (options.character && !options.character->doc.binary);
  double spacing = grid.times.back() - grid.times.front();
  for (std::size_t f = 1; f < frames; ++f) spacing = std::min(spacing, grid.times[f] - grid.times[f - 1]);

  std::vector<EulerCurve> curves;
  std::vector<std::optional<TranslationTrack>> tracks(n);
  std::vector<std::optional<TranslationCurve>> moves(n);
  std::vector<TrackKeys> rot_keys(n), pos_keys(n);
  curves.reserve(n);
  for (std::size_t j = 0; j < n; ++j) {
    auto m = method->make(reduced.rotations[j]);
    if (!m) return m.failure();
    curves.emplace_back(std::move(*m), joints.frames[j], grid.times, kSlopeStep * spacing);
    auto keys = frames_of(reduced.rotations[j].times, grid, sk.joints[j].name);
    if (!keys) return keys.failure();
    rot_keys[j] = std::move(*keys);
    tracks[j] = reduced.translations[j];
    if (!tracks[j] && joints.frames[j].keyed_translation)  // the rest offset, keyed where the rotation is
      tracks[j] = TranslationTrack{reduced.rotations[j].times,
                                   std::vector<Vec3>(reduced.rotations[j].times.size(), sk.joints[j].offset)};
    if (const auto& tr = tracks[j]) {
      moves[j].emplace(*tr, options.translation);
      auto pk = frames_of(tr->times, grid, sk.joints[j].name);
      if (!pk) return pk.failure();
      pos_keys[j] = std::move(*pk);
    }
  }

  FbxReducedResult result;
  for (;;) {
    std::vector<FbxOutJoint> out(n);
    for (std::size_t j = 0; j < n; ++j) {
      out[j].axes = curves[j].axes();
      out[j].rotation = rotation_curves(curves[j], rot_keys[j], dense.rotation[j], ticks, cubic_rotations);
      out[j].has_translation = moves[j].has_value();
      if (moves[j])
        out[j].translation = translation_curves(*moves[j], pos_keys[j], dense.translation[j], grid.times, ticks,
                                                cubic_translations && tracks[j]->times.size() > 1, curves[j]);
    }
    Result<std::string> bytes = make_error("");
    if (options.character) {
      keep_source_scaling(out, joints, take);
      FbxCharacterTake written{fbx_character_out_take(reduced.name, std::move(out), take), {}};
      for (const FbxModel* m : joints.models) written.model_ids.push_back(m->id);
      unkey_resting_joints(written, *options.character, take);
      auto file = encode_fbx_character(*options.character, {written}, grid.rate, ascii ? FbxEncoding::ascii : FbxEncoding::binary);
      if (!file) return file.failure();
      result.kept = file->kept;
      bytes = std::move(file->bytes);
    } else {
      bytes = encode_fbx_curves(reduced, out, ascii ? FbxEncoding::ascii : FbxEncoding::binary);
    }
    if (!bytes) return bytes.failure();
    auto errors = fbx_replay_errors(*bytes, sk, dense, ticks, options.budgets, options.shell_distance, joints.frames);
    if (!errors) return errors.failure();

    // Parents before children (the skeleton's order): a frame an ancestor repaired
    // in this round is left to the next, since its error may have been theirs.
    bool changed = false;
    std::vector<std::vector<bool>> touched(n, std::vector<bool>(frames, false));
    result.within_budget = true;
    result.max_rotation_error_deg = result.max_shell_error = result.max_translation_error = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
      const FbxJointBudget& b = options.budgets[j];
      const int parent = sk.joints[j].parent;
      std::vector<bool> skip(frames, false);
      if (parent >= 0)
        for (std::size_t f = 0; f < frames; ++f) skip[f] = touched[static_cast<std::size_t>(parent)][f];
      std::vector<double> ratio(frames), move_ratio(frames, 0.0);
      for (std::size_t f = 0; f < frames; ++f) {
        ratio[f] = over_rotation(*errors, b, j, f);
        result.max_rotation_error_deg = std::max(result.max_rotation_error_deg, errors->rotation_deg[j][f]);
        result.max_shell_error = std::max(result.max_shell_error, errors->shell[j][f]);
        if (moves[j]) {
          result.max_translation_error = std::max(result.max_translation_error, errors->translation[j][f]);
          if (b.translation > 0.0) move_ratio[f] = errors->translation[j][f] / b.translation;
        }
        if (ratio[f] > 1.0 || move_ratio[f] > 1.0) result.within_budget = false;
      }
      std::vector<std::size_t> stuck, stuck_moves;
      const TrackKeys before = rot_keys[j];
      changed |= repair(rot_keys[j], ratio, skip, stuck, result.added_keys, result.corrected_keys);
      if (moves[j]) changed |= repair(pos_keys[j], move_ratio, skip, stuck_moves, result.added_keys, result.corrected_keys);
      for (std::size_t f : rot_keys[j].frames)
        if (!before.has(f) || rot_keys[j].source_value[f] != before.source_value[f]) touched[j][f] = true;
      for (std::size_t f = 0; f < frames; ++f) touched[j][f] = touched[j][f] || skip[f];
      // A key frame at the source's value still over budget: its own translation,
      // then its ancestors' keys there take the source's value, nearest first.
      for (std::size_t f : stuck) {
        for (int a = static_cast<int>(j); a >= 0; a = sk.joints[static_cast<std::size_t>(a)].parent) {
          const auto i = static_cast<std::size_t>(a);
          bool fixed = false;
          for (TrackKeys* keys : {moves[i] ? &pos_keys[i] : nullptr, a == static_cast<int>(j) ? nullptr : &rot_keys[i]}) {
            if (!keys || (keys->has(f) && keys->source_value[f])) continue;
            if (!keys->has(f)) keys->add(f), ++result.added_keys;
            keys->source_value[f] = true, ++result.corrected_keys;
            fixed = true;
          }
          if (fixed) {
            changed = true;
            break;
          }
        }
      }
    }
    if (!changed || result.within_budget) {
      result.bytes = std::move(*bytes);
      break;
    }
  }
  for (std::size_t j = 0; j < n; ++j) {
    result.rotation_keys += rot_keys[j].frames.size();
    if (moves[j]) result.translation_keys += pos_keys[j].frames.size();
  }
  return result;
}

}  // namespace rotinterp
