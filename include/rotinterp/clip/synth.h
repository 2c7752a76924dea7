// Synthetic clips whose motion is known analytically at every time, for tests,
// benchmarks, the bundled sample and `eval --truth`.
//
// Every joint's local rotation is a product of exponentials of closed-form
// rotation-vector curves times a fixed rotation,
//     q_j(t) = exp(v_j1(t)) · exp(v_j2(t)) · … · q0_j,
// each v(t) = c0 + c1·t + c2·t² + Σ aᵢ·sin(ωᵢ t + φᵢ) (vectors c, a), and a root
// translation of the same form. truth() evaluates that exactly at any t, so
// resampled clips can be compared with the motion itself, between frames too.
//
// Kinds:
//  * constant — constant fixed-frame angular velocity per joint: q_j(t) = exp(ω_j t)·q0_j,
//               |ω_j| ≤ 3 rad/s; root moving on a straight line at constant speed.
//  * smooth   — smooth random rotation-vector curves (three sinusoids per joint,
//               0.2–1.5 Hz, |v| ≲ 1.5 rad); root on a smooth curve.
//  * spin     — spins about a fixed random axis, 1–2 turns per second and
//               accelerating, so every joint passes 2π many times, with a small
//               wobble about a perpendicular axis; root on a straight line.
//  * walk     — a 31-joint walking figure (CMU naming: Hips, LeftUpLeg, …, RThumb)
//               with a 1 Hz gait: hip/knee/ankle flexion, arm swing, pelvis
//               rotation and bob, walking along +Z at ~1.2 units·100/s.
// Every joint gets a random Euler rotation order (SynthMotion::rotation_orders,
// seeded), which `rotinterp synth` writes as its BVH channels, roots' positions
// first (io/files/file_record.h). The same options always give the same clip.
// Keep the per-frame rotation below π: spin at fps < 8 Hz aliases.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/clip/sampling.h"
#include "rotinterp/core/result.h"

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rotinterp {

enum class SynthKind { constant, smooth, spin, walk };

const char* synth_kind_name(SynthKind k);  // "constant", "smooth", "spin", "walk"
Result<SynthKind> parse_synth_kind(std::string_view name);
std::string synth_kind_names();  // "constant, smooth, spin, walk"

struct SynthOptions {
  SynthKind kind = SynthKind::walk;
  double seconds = 4.0;     // duration; frames = floor(seconds·fps + 1e-9) + 1
  Rate fps{30, 1};          // frame rate of the sampled clip
  std::uint64_t seed = 1;   // drives every random choice (orders, axes, amplitudes)
  int joints = 12;          // joints for constant/smooth/spin (≥ 1); walk always has 31
};

// One line that reproduces the options: "kind=walk seconds=4 fps=30 seed=1 joints=31".
std::string synth_spec(const SynthOptions& options);
// Parses synth_spec()'s output (keys in any order, missing keys at their defaults).
Result<SynthOptions> parse_synth_spec(std::string_view spec);

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

// The spec file `rotinterp synth` writes next to a clip: "<clip_file>.synth".
std::filesystem::path synth_spec_path(const std::filesystem::path& clip_file);
// Rebuilds the analytic motion of a clip file from its spec file (for eval --truth):
// an error naming the file when there is none or it does not parse. The motion's
// truth(t, rotation, translation) gives the exact local pose at any t.
Result<SynthMotion> read_synth_spec(const std::filesystem::path& clip_file);

// The motion for `options` (validated: seconds > 0, joints ≥ 1, ≤ 10 000 000 frames).
Result<SynthMotion> make_synth_motion(const SynthOptions& options);
// make_synth_motion(options) sampled at options.fps for options.seconds.
Result<Clip> make_synth_clip(const SynthOptions& options);

}  // namespace rotinterp
