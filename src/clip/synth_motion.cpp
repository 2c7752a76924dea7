// A closed-form motion: evaluated exactly at any time, and sampled into a clip.
#include "rotinterp/clip/synth_motion.h"

#include "rotinterp/core/result.h"
#include "rotinterp/core/rotation.h"

#include <cmath>
#include <cstdint>
#include <utility>

namespace rotinterp {

Vec3 VectorCurve::at(double t) const {
  Vec3 v = c0 + t * (c1 + t * c2);
  for (const Wave& w : waves) v += w.amp * std::sin(w.omega * t + w.phase);
  return v;
}

SynthMotion::SynthMotion(Skeleton skeleton, std::vector<JointMotion> motion, RotationOrders rotation_orders)
    : skeleton_(std::move(skeleton)), motion_(std::move(motion)), rotation_orders_(std::move(rotation_orders)) {
  ROTINTERP_ASSERT(motion_.size() == skeleton_.joints.size());
}

Quat SynthMotion::rotation(std::size_t j, double t) const {
  const JointMotion& m = motion_[j];
  Quat q = Quat::Identity();
  for (const VectorCurve& f : m.factors) q = q * rotinterp::exp(RotVec(f.at(t)));
  return normalized_or_identity(q * m.base);
}

Vec3 SynthMotion::translation(std::size_t j, double t) const {
  const JointMotion& m = motion_[j];
  return m.translation ? m.translation->at(t) : skeleton_.joints[j].offset;
}

void SynthMotion::truth(double t, std::vector<Quat>& rotation, std::vector<Vec3>& translation) const {
  const std::size_t n = motion_.size();
  rotation.resize(n);
  translation.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    rotation[j] = this->rotation(j, t);
    translation[j] = this->translation(j, t);
  }
}

Clip SynthMotion::sample(double seconds, const Rate& rate, std::string name) const {
  const std::size_t frames = sample_count(seconds, rate);
  std::vector<double> times(frames);
  for (std::size_t k = 0; k < frames; ++k) times[k] = rate.time_of(static_cast<std::int64_t>(k));
  Clip clip;
  clip.name = std::move(name);
  clip.skeleton = skeleton_;
  clip.frame_time = rate.period();
  clip.source_format = "synth";
  const std::size_t n = motion_.size();
  clip.rotations.resize(n);
  clip.translations.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    RotationTrack& r = clip.rotations[j];
    r.times = times;
    r.keys.resize(frames);
    for (std::size_t k = 0; k < frames; ++k) r.keys[k] = rotation(j, times[k]);
    r.make_sign_continuous();
    if (motion_[j].translation) {
      TranslationTrack& tr = clip.translations[j].emplace();
      tr.times = times;
      tr.keys.resize(frames);
      for (std::size_t k = 0; k < frames; ++k) tr.keys[k] = motion_[j].translation->at(times[k]);
    }
  }
  return clip;
}

}  // namespace rotinterp
