// Synthetic cycles for the loop tests: a constant-velocity full turn and a
// sinusoidal swing with root drift, in closed or open form, with known truth.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/clip/loop.h"

#include <cmath>
#include <string>

namespace rotinterp::test {

// Joints: root (translated, drifting forward along x), "spin" (a full turn about a
// fixed axis per period, constant velocity) and "swing" (sinusoids in two axes).
struct CycleTruth {
  double period;   // seconds
  Vec3 drift;      // root's per-cycle offset, clip units (metres)
  Quat spin(double t) const { return exp(RotVec(Vec3(0.3, 1.0, -0.2).normalized() * (kTwoPi * t / period))); }
  Quat swing(double t) const {
    const double p = kTwoPi * t / period;
    return exp(RotVec(Vec3(0.8 * std::sin(p), 0.3 * std::sin(2.0 * p + 0.5), 0.2 * std::cos(p))));
  }
  Vec3 root(double t) const {
    const double p = kTwoPi * t / period;
    return Vec3(drift.x() * t / period + 0.05 * std::sin(p), 1.0 + 0.03 * std::sin(2.0 * p), 0.02 * std::cos(p));
  }
};

// `frames_per_period` frames at 1/frame_time per second over one period, in `form`.
inline Clip cycle_clip(const CycleTruth& truth, std::size_t frames_per_period, LoopForm form) {
  Clip c;
  c.name = "cycle";
  c.skeleton.joints = {{"root", -1, Vec3::Zero(), Quat::Identity()},
                       {"spin", 0, Vec3(0.0, 0.5, 0.0), Quat::Identity()},
                       {"swing", 1, Vec3(0.0, 0.6, 0.0), Quat::Identity()}};
  c.frame_time = truth.period / static_cast<double>(frames_per_period);
  c.unit.metres_per_unit = 1.0;
  c.rotations.resize(3);
  c.translations.resize(3);
  TranslationTrack root;
  const std::size_t frames = frames_per_period + (form == LoopForm::closed ? 1 : 0);
  for (std::size_t k = 0; k < frames; ++k) {
    const double t = truth.period * static_cast<double>(k) / static_cast<double>(frames_per_period);
    c.rotations[0].times.push_back(t);
    c.rotations[0].keys.push_back(Quat::Identity());
    c.rotations[1].times.push_back(t);
    c.rotations[1].keys.push_back(truth.spin(t));
    c.rotations[2].times.push_back(t);
    c.rotations[2].keys.push_back(truth.swing(t));
    root.times.push_back(t);
    root.keys.push_back(truth.root(t));
  }
  for (RotationTrack& r : c.rotations) r.make_sign_continuous();
  c.translations[0] = root;
  return c;
}

}  // namespace rotinterp::test
