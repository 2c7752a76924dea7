// Synthetic clips whose motion is known analytically at every time, for tests,
// benchmarks, the bundled sample and `eval --truth`.
//
// Every joint's motion is a closed form (clip/synth_motion.h), known exactly at any
// t, so resampled clips can be compared with the motion itself, between frames too;
// its spec line and file (clip/synth_spec.h) rebuild it.
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
#include "rotinterp/clip/synth_motion.h"
#include "rotinterp/core/result.h"

#include <cstdint>
#include <string>
#include <string_view>

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

// The motion for `options` (validated: seconds > 0, joints ≥ 1, ≤ 10 000 000 frames).
Result<SynthMotion> make_synth_motion(const SynthOptions& options);
// make_synth_motion(options) sampled at options.fps for options.seconds.
Result<Clip> make_synth_clip(const SynthOptions& options);

}  // namespace rotinterp
