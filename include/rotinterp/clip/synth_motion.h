// A motion known in closed form at every time: the synthetic clips' (clip/synth.h).
//
// Every joint's local rotation is a product of exponentials of closed-form
// rotation-vector curves times a fixed rotation,
//     q_j(t) = exp(v_j1(t)) · exp(v_j2(t)) · … · q0_j,
// each v(t) = c0 + c1·t + c2·t² + Σ aᵢ·sin(ωᵢ t + φᵢ) (vectors c, a), and a root
// translation of the same form. truth() evaluates that exactly at any t; sample()
// gives the clip at a rate.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/clip/sampling.h"

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp {

// A closed-form vector curve c0 + c1·t + c2·t² + Σ amp·sin(omega·t + phase).
struct VectorCurve {
  struct Wave {
    Vec3 amp = Vec3::Zero();
    double omega = 0.0;  // rad/s
    double phase = 0.0;  // rad
  };
  Vec3 c0 = Vec3::Zero(), c1 = Vec3::Zero(), c2 = Vec3::Zero();
  std::vector<Wave> waves;

  Vec3 at(double t) const;
};

// One joint's analytic motion.
struct JointMotion {
  std::vector<VectorCurve> factors;        // q(t) = Π exp(factors[m](t)) · base
  Quat base = Quat::Identity();
  std::optional<VectorCurve> translation;  // set for joints with position channels
};

class SynthMotion {
 public:
  // Per joint, the axes (0 x, 1 y, 2 z; the first outermost) of the Euler angles its
  // rotation is keyed in: what a writer of angles keeps. Empty for none.
  using RotationOrders = std::vector<std::array<int, 3>>;
  SynthMotion(Skeleton skeleton, std::vector<JointMotion> motion, RotationOrders rotation_orders = {});

  const Skeleton& skeleton() const { return skeleton_; }
  const std::vector<JointMotion>& motion() const { return motion_; }
  const RotationOrders& rotation_orders() const { return rotation_orders_; }

  // Exact local rotation / translation of joint j at time t (seconds). The
  // translation of a joint without position channels is its rest offset.
  Quat rotation(std::size_t j, double t) const;
  Vec3 translation(std::size_t j, double t) const;
  // All joints at once.
  void truth(double t, std::vector<Quat>& rotation, std::vector<Vec3>& translation) const;

  // The clip sampled at t_k = k/rate, k = 0 … floor(seconds·rate + 1e-9):
  // quaternion keys made sign-continuous, frame_time = 1/rate.
  Clip sample(double seconds, const Rate& rate, std::string name) const;

 private:
  Skeleton skeleton_;
  std::vector<JointMotion> motion_;
  RotationOrders rotation_orders_;
};

}  // namespace rotinterp
