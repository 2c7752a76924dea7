// The Buss–Fillmore spherical weighted average and Markley's chordal mean of orientations.
#include "rotinterp/core/average.h"

#include "rotinterp/core/so3_jacobian.h"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace rotinterp {

namespace {

// Solves H·x = g by the adjugate (H is 3×3: cheaper than a factorization). False,
// x untouched, when |det H| ≤ 1e-6: near singular.
bool solve3(const Mat3& H, const Vec3& g, Vec3& x) {
  const Vec3 c0 = H.col(1).cross(H.col(2)), c1 = H.col(2).cross(H.col(0)), c2 = H.col(0).cross(H.col(1));
  const double det = H.col(0).dot(c0);
  if (!(std::abs(det) > 1e-6)) return false;
  // H⁻¹ has the rows c0, c1, c2 divided by det.
  x = Vec3(c0.dot(g), c1.dot(g), c2.dot(g)) / det;
  return true;
}

// The spline averages' start: the normalized weighted sum of the points (the
// chordal estimate), or p[1] where that is zero or not finite — weights overflow
// on knots a denormal time apart, and the iteration keeps a finite start finite.
Quat chordal_start(const Quat* p, const double* w, int n) {
  Eigen::Vector4d sum = Eigen::Vector4d::Zero();
  for (int k = 0; k < n; ++k) sum += w[k] * p[k].coeffs();
  const double sn = sum.norm();
  return sn > 0.0 && std::isfinite(sn) ? Quat(sum / sn) : p[1];
}

// m·exp(step) for a unit m (apply_moving without renormalizing m first).
Quat step_from(const Quat& m, const Vec3& step) { return (m * exp(RotVec(step))).normalized(); }

struct AverageOutcome {
  Quat m;
  double residual;  // |Σ wᵢ log(m⁻¹pᵢ)|, rad
  bool converged;
};

// Below this residual (rad) a Newton step lands within K·residual² ≈ 1e-15 rad of
// the mean (quadratic convergence; H exact to 1e-10 relative), so the spline's
// averages take it without evaluating the residual once more. K ≤ 1.2e-3 for
// residuals below 1e-5 from the chordal start: measured over 2·10⁵ random sets of
// four points spread 1e-3 to 1 rad (small residuals come from tight sets, where
// the log is nearly linear). About half of a clip's curve points start below it.
constexpr double kFinalNewtonStep = 1e-6;

// The BF iteration on points p (any signs: the core log takes the nearer one) with
// positive weights summing to 1, from the start point m. With `final_step`, a
// Newton step from a residual below kFinalNewtonStep is the last one (its
// residual, reported as the square of the previous one, is not evaluated).
AverageOutcome average_iterate(const Quat* p, const double* w, std::size_t n, Quat m, const BfAverageOptions& o,
                               bool final_step = false) {
  bool newton = o.algorithm == BfAverageOptions::Algorithm::a2;
  double previous = std::numeric_limits<double>::infinity();
  double gn = previous;
  for (int it = 0;; ++it) {
    // g = Σ wᵢvᵢ and, for Newton, H = Σ wᵢJ_l⁻¹(vᵢ) = (Σwᵢ)I − ½[g]× + Σ wᵢcᵢ(vᵢvᵢᵀ − θᵢ²I),
    // accumulated without 3×3 products.
    Vec3 g = Vec3::Zero();
    Mat3 S = Mat3::Zero();
    double trace = 0.0, wsum = 0.0;
    const Quat mi = m.conjugate();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 v = log_s3(mi * p[i]);
      g += w[i] * v;
      if (newton) {
        const double th2 = v.squaredNorm();
        const double wc = w[i] * so3_jacobian_c_newton(th2);
        S.noalias() += wc * (v * v.transpose());
        trace += wc * th2;
        wsum += w[i];
      }
    }
    gn = g.norm();
    if (gn <= o.tolerance) return {m, gn, true};
    if (gn >= previous) {
      if (gn <= o.stall_tolerance) return {m, gn, true};  // round-off floor
      newton = false;                                     // Newton overshot: plain A1 from here
    }
    if (it >= o.max_iterations) break;
    previous = gn;
    Vec3 step = g;
    if (newton) {
      // H = Σ wᵢJ_l⁻¹(vᵢ) is I + O(spread²): a near-zero determinant means the
      // points are spread over most of the hemisphere; A1 is safe there.
      Mat3 H = S;
      const double d = wsum - trace;
      H(0, 0) += d, H(1, 1) += d, H(2, 2) += d;
      H(0, 1) += 0.5 * g.z(), H(1, 0) -= 0.5 * g.z();
      H(0, 2) -= 0.5 * g.y(), H(2, 0) += 0.5 * g.y();
      H(1, 2) += 0.5 * g.x(), H(2, 1) -= 0.5 * g.x();
      if (solve3(H, g, step) && final_step && gn <= kFinalNewtonStep) return {step_from(m, step), gn * gn, true};
    }
    m = step_from(m, step);
  }
  return {m, gn, gn <= o.stall_tolerance};
}

}  // namespace

Quat bf_average_of_points(const Quat* p, const double* w, int n, const BfAverageOptions& options) {
  return average_iterate(p, w, static_cast<std::size_t>(n), chordal_start(p, w, n), options, true).m;
}

Quat chordal_mean(const std::vector<Quat>& q, const std::vector<double>& w) {
  if (q.empty() || q.size() != w.size()) return Quat::Identity();
  Eigen::Matrix4d M = Eigen::Matrix4d::Zero();
  for (std::size_t i = 0; i < q.size(); ++i) {
    if (!(w[i] >= 0.0) || !std::isfinite(w[i])) return Quat::Identity();
    const Eigen::Vector4d c = normalized_or_identity(q[i]).coeffs();
    M += w[i] * c * c.transpose();
  }
  if (!M.allFinite() || M.isZero(0.0)) return Quat::Identity();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> es(M);
  const Eigen::Vector4d v = es.eigenvectors().col(3);  // eigenvalues ascending
  return normalized_or_identity(Quat(v));
}

Result<Quat> bf_average(const std::vector<Quat>& q_in, const std::vector<double>& w_in, const BfAverageOptions& o) {
  if (q_in.empty()) return make_error("bf average: no orientations");
  if (q_in.size() != w_in.size())
    return make_error("bf average: " + std::to_string(q_in.size()) + " orientations but " +
                      std::to_string(w_in.size()) + " weights");
  double total = 0.0;
  for (std::size_t i = 0; i < w_in.size(); ++i) {
    if (!std::isfinite(w_in[i])) return make_error("bf average: weight " + std::to_string(i) + " is not finite");
    if (w_in[i] < 0.0) return make_error("bf average: weight " + std::to_string(i) + " is negative");
    const double n = q_in[i].norm();
    if (!q_in[i].coeffs().allFinite() || !(n > 0.0))
      return make_error("bf average: orientation " + std::to_string(i) + " is zero or not finite");
    total += w_in[i];
  }
  if (!(total > 0.0) || !std::isfinite(total)) return make_error("bf average: the weights sum to zero");
  std::vector<Quat> q;
  std::vector<double> w;
  std::size_t heaviest = 0;
  for (std::size_t i = 0; i < q_in.size(); ++i) {
    if (w_in[i] == 0.0) continue;
    q.push_back(normalized_or_identity(q_in[i]));
    w.push_back(w_in[i] / total);
    if (w.back() > w[heaviest]) heaviest = w.size() - 1;
  }
  // Orientation semantics: every input is taken as ±qᵢ in the heaviest input's
  // hemisphere. An input exactly 180° from it (dot 0) has two equally near signs
  // and the mean two equally good values: refused.
  std::vector<Quat> aligned(q.size());
  Eigen::Vector4d sum = Eigen::Vector4d::Zero();
  for (std::size_t i = 0; i < q.size(); ++i) {
    aligned[i] = align_to(q[i], q[heaviest]);  // a dot of 0 is refused just below
    if (!(aligned[i].dot(q[heaviest]) > 0.0))
      return make_error("bf average: orientation " + std::to_string(i) +
                        " is 180° from the heaviest one: the inputs do not fit in an open hemisphere");
    sum += w[i] * aligned[i].coeffs();
  }
  const Quat center(sum / sum.norm());
  const AverageOutcome r = average_iterate(aligned.data(), w.data(), aligned.size(), center, o);
  for (std::size_t i = 0; i < aligned.size(); ++i)
    if (!(std::abs(aligned[i].dot(r.m)) > 0.0))
      return make_error("bf average: orientation " + std::to_string(i) +
                        " is 180° from the mean: the inputs do not fit in an open hemisphere");
  if (!r.converged)
    return make_error("bf average: no convergence in " + std::to_string(o.max_iterations) +
                      " iterations (residual " + std::to_string(r.residual) + " rad)");
  return r.m;
}

}  // namespace rotinterp
