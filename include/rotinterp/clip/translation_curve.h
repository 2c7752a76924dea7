// Interpolating a translation track (root motion, joints with position channels).
//
// Two methods:
//  * linear: piecewise linear, C⁰. Never leaves the segment between two keys.
//  * cubic (default): piecewise cubic Hermite per coordinate with Steffen's
//    tangents (M. Steffen, "A simple method for monotonic interpolation in one
//    dimension", A&A 239, 1990). C¹; works for non-uniform key times; reproduces a
//    straight line at constant speed exactly (every secant equal ⇒ every tangent
//    equal to it); and, per coordinate, the curve between two keys never leaves the
//    interval of their values — no overshoot: a root that stops does not slide past
//    its stop, a foot on the floor does not dip below it. Local extrema sit on keys
//    (a coordinate that turns around turns around at a key, tangent 0 there).
//    The price against Catmull-Rom or a natural (C²) spline: the curve is C¹, not
//    C², and flattens slightly at keys where a coordinate turns; those two
//    overshoot by up to ~1/8 of a step at sharp stops, which reads as foot sliding.
//    Steffen end tangents use the one-sided parabola through the first (last)
//    three keys, limited the same way.
// Outside the key range the curve is clamped to the first/last key.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"

#include <optional>
#include <string_view>
#include <vector>

namespace rotinterp {

enum class TranslationInterp { linear, cubic };

const char* translation_interp_name(TranslationInterp m);  // "linear", "cubic"
// "linear" or "cubic"; an error naming the valid names otherwise.
Result<TranslationInterp> parse_translation_interp(std::string_view name);

class TranslationCurve {
 public:
  // The track must be valid (TranslationTrack::validate()).
  TranslationCurve(const TranslationTrack& track, TranslationInterp method);

  Vec3 evaluate(double t) const;
  // dp/dt (units per second); 0 outside the key range.
  Vec3 derivative(double t) const;
  // The cubic's Hermite tangent dp/dt at each key (units per second), what a glTF
  // CUBICSPLINE sampler stores as in- and out-tangent; empty for linear and for one key.
  const std::vector<Vec3>& tangents() const { return tangents_; }

 private:
  std::size_t segment(double t) const;  // i with times[i] ≤ t < times[i+1], clamped

  TranslationInterp method_;
  std::vector<double> times_;
  std::vector<Vec3> keys_;
  std::vector<Vec3> tangents_;  // cubic only
};

// A cycle's translation (resample --loop, reduce --loop; clip/loop.h): the track moves by
// its per-cycle offset D every period P, p(t) = r(t) + D·(t − t₀)/P with r periodic. `open`
// holds the keys of one period in open form (times in [t₀, t₀ + P)); r is the curve through
// them with the drift taken out, unrolled over whole periods, so it is as smooth across
// the seam as between keys, and a run keeps its forward motion. Defined at every t.
class PeriodicTranslationCurve {
 public:
  PeriodicTranslationCurve(const TranslationTrack& open, Vec3 offset, double t0, double period, TranslationInterp method);
  Vec3 evaluate(double t) const;

 private:
  Vec3 drift(double t) const { return offset_ * ((t - t0_) / period_); }
  Vec3 offset_;
  double t0_, period_;
  std::optional<TranslationCurve> curve_;
};

}  // namespace rotinterp
