// bf's in-between knots: where keys are too far apart, in angle or in time, for a BF spline through them.
#include "bf_knots.h"

#include "rotinterp/core/rotation.h"

#include <cmath>
#include <utility>
#include <vector>

namespace rotinterp::detail {

namespace {

// An interval more than 1.5·kGrading times a neighbouring one is graded: a piece
// kGrading times the short neighbour is split off next to it, repeatedly.
constexpr double kGrading = 2.0;

// The knot that grades interval i of `t` (a piece kGrading times the short
// neighbour split off next to it), or NaN when the interval is no more than
// 1.5·kGrading times either neighbour. Split only beyond 1.5·kGrading so the pieces
// (kGrading·short and a rest ≥ 0.5·kGrading·short) are not split again by
// round-off. The new knot's time is measured from the end next to the short
// neighbour: as a fraction of the interval it would round to that end once
// interval/short passes 2⁵³ (keys at −1, −1e-20 and 0: the fuzzer's crash-860848d6).
double grading_knot(const std::vector<double>& t, std::size_t i) {
  const double len = t[i + 1] - t[i];
  const double left = i > 0 ? t[i] - t[i - 1] : len;
  const double right = i + 2 < t.size() ? t[i + 2] - t[i + 1] : len;
  double t_new = NAN;
  if (len > 1.5 * kGrading * left) {
    t_new = t[i] + kGrading * left;
  } else if (len > 1.5 * kGrading * right) {
    t_new = t[i + 1] - kGrading * right;
  }
  return t_new > t[i] && t_new < t[i + 1] ? t_new : NAN;
}


}  // namespace

Keys refine_bf_knots(const Keys& k, double max_step, const Interpolator& along) {
  if (k.size() < 2) return k;
  Keys out;
  for (std::size_t i = 0; i + 1 < k.size(); ++i) {
    out.t.push_back(k.t[i]);
    out.q.push_back(k.q[i]);
    const double angle = angular_distance(k.q[i], k.q[i + 1]);
    const int parts = static_cast<int>(std::ceil(angle / max_step));
    for (int p = 1; p < parts; ++p) {
      const double u = static_cast<double>(p) / parts;
      out.t.push_back(k.t[i] + u * (k.t[i + 1] - k.t[i]));
      out.q.push_back(align_pair(out.q.back(), along.evaluate(out.t.back())));
    }
  }
  out.t.push_back(k.t.back());
  out.q.push_back(align_pair(out.q.back(), k.q.back()));
  // Grading. Each pass splits every too-long interval once; the number of passes
  // grows with log(largest ratio)/log(kGrading) (≈ 17 for 1e-6 s next to 1e4 s).
  for (bool changed = true; changed;) {
    changed = false;
    Keys g;
    for (std::size_t i = 0; i + 1 < out.size(); ++i) {
      g.t.push_back(out.t[i]);
      g.q.push_back(out.q[i]);
      const double t_new = grading_knot(out.t, i);
      if (!std::isnan(t_new)) {
        g.t.push_back(t_new);
        g.q.push_back(align_pair(out.q[i], along.evaluate(t_new)));
        changed = true;
      }
    }
    g.t.push_back(out.t.back());
    g.q.push_back(out.q.back());
    out = std::move(g);
  }
  return out;
}

bool bf_knots_need_grading(const Keys& k) {
  for (std::size_t i = 0; i + 1 < k.size(); ++i)
    if (!std::isnan(grading_knot(k.t, i))) return true;
  return false;
}

bool bf_knots_need_refinement(const Keys& k, double max_step) {
  for (std::size_t i = 0; i + 1 < k.size(); ++i)
    if (angular_distance(k.q[i], k.q[i + 1]) > max_step) return true;
  return bf_knots_need_grading(k);
}

}  // namespace rotinterp::detail
