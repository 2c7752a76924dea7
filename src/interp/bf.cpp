// bf: the Buss–Fillmore spherical cubic B-spline through the keys.
#include "rotinterp/interp/bf.h"

#include "bf_knots.h"
#include "detail.h"
#include "rotinterp/core/so3_jacobian.h"
#include "rotinterp/interp/c2.h"
#include "rotinterp/interp/slerp.h"

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace rotinterp {

// ---- the spline ------------------------------------------------------------------------

namespace {

class BfInterpolator final : public detail::SegmentInterpolator<BfInterpolator> {
 public:
  BfInterpolator(detail::Keys keys, const BfSplineOptions& o) : SegmentInterpolator(std::move(keys)), avg_(o.average) {}

  // Solves the control points; returns the largest key miss (rad).
  double solve(const BfSplineOptions& o) {
    const std::size_t nk = k_.size();
    if (nk < 2) return 0.0;
    const auto n = static_cast<std::ptrdiff_t>(nk - 1);  // segments
    build_knots(n);
    // B-spline weights at key j on its three control points cⱼ₋₁, cⱼ, cⱼ₊₁.
    weights_at_keys_.resize(nk);
    for (std::ptrdiff_t j = 0; j <= n; ++j) {
      double N[4], dN[4];
      basis(j < n ? j : n - 1, tau(j), N, dN);
      const int first = j < n ? 0 : 1;
      for (int k = 0; k < 3; ++k) weights_at_keys_[j][k] = N[first + k];
    }
    c_.assign(nk + 2, Quat::Identity());
    for (std::size_t j = 0; j < nk; ++j) c_[j + 1] = k_.q[j];
    reflect_ends();

    const bool newton = o.solver == BfSplineOptions::Solver::newton;
    std::vector<Vec3> r(nk), r_try(nk), d(nk), y(nk);
    std::vector<Quat> p(nk), p_try(nk);
    std::vector<std::array<Mat3, 3>> G(nk);
    int short_steps = 0;
    std::vector<Mat3> Dinv(nk);
    double worst = key_misses(r, p);
    for (int it = 0; it < o.max_iterations && worst > o.tolerance; ++it) {
      if (newton) {
        // The Jacobian only here, for a step still to take (not for the final misses).
        key_jacobian(r, p, G);
        // Block Thomas on Σₖ Gⱼₖ δₖ = rⱼ (k = j−1, j, j+1).
        for (std::ptrdiff_t j = 0; j <= n; ++j) {
          Mat3 D = G[j][1];
          y[j] = r[j];
          if (j > 0) {
            const Mat3 Lm = G[j][0] * Dinv[j - 1];
            D -= Lm * G[j - 1][2];
            y[j] -= Lm * y[j - 1];
          }
          Dinv[j] = D.inverse();
        }
        d[n] = Dinv[n] * y[n];
        for (std::ptrdiff_t j = n - 1; j >= 0; --j) d[j] = Dinv[j] * (y[j] - G[j][2] * d[j + 1]);
        bool finite = true;
        for (const Vec3& v : d) finite = finite && v.allFinite();
        if (!finite) d = r;  // singular Jacobian: plain S1 step
      } else {
        d = r;
      }
      // Backtracking: halve the step until the largest key miss decreases. A
      // solve that keeps needing short steps is abandoned (make_bf then refines
      // the knots further and starts again).
      const std::vector<Quat> saved = c_;
      double tried = worst, lambda = 1.0;
      for (int halving = 0; halving <= 8; ++halving, lambda *= 0.5) {
        for (std::ptrdiff_t j = 0; j <= n; ++j) c_[j + 1] = apply_fixed(RotVec(lambda * d[j]), saved[j + 1]);
        reflect_ends();
        tried = key_misses(r_try, p_try);
        if (tried < worst) break;
      }
      if (!(tried < worst)) {  // no progress at any step length: keep the best
        c_ = saved;
        break;
      }
      short_steps = lambda < 1.0 / 16.0 ? short_steps + 1 : 0;
      worst = tried;
      std::swap(r, r_try);
      std::swap(p, p_try);
      if (newton && short_steps >= 3) break;
    }
    return worst;
  }

  Quat segment(std::size_t i, double u) const {
    const auto s = static_cast<std::ptrdiff_t>(i);
    return point(s, x_of(i, u));
  }

  // m(t) solves F = Σ Nₖ(t)·log(m⁻¹cₖ) = 0; implicit differentiation with
  // m → m·exp(δ): body rate δ̇ = H⁻¹·Σ Ṅₖ vₖ, H = Σ Nₖ J_l⁻¹(vₖ).
  Vec3 segment_velocity(std::size_t i, double u) const { return velocity(i, u, false); }
  // The quotient of the velocity written with the accurate J_l⁻¹ (so3_jacobian_c):
  // segment_velocity's coarser c_newton switches form at |v| = 0.5 rad, a step of up
  // to 1.6e-7 of ω that a quotient over 1e-5 of a segment would amplify 10⁴-fold.
  Vec3 segment_acceleration(std::size_t i, double u) const {
    return difference_quotient(i, u, [this, i](double x) { return velocity(i, x, true); });
  }

 private:
  Vec3 velocity(std::size_t i, double u, bool accurate) const {
    const auto s = static_cast<std::ptrdiff_t>(i);
    const double x = x_of(i, u);
    double N[4], dN[4];
    basis(s, x, N, dN);
    const Quat m = average(s, N);
    const Quat mi = m.conjugate();
    Mat3 H = Mat3::Zero();
    Vec3 g = Vec3::Zero();
    for (int k = 0; k < 4; ++k) {
      const Vec3 v = log_s3(mi * c_[s + k]);
      H += N[k] * so3_left_jacobian_inverse_with(v, accurate ? so3_jacobian_c(v.norm())
                                                             : so3_jacobian_c_newton(v.squaredNorm()));
      g += dN[k] * v;
    }
    return m * Vec3(H.fullPivLu().solve(g));
  }

  double x_of(std::size_t i, double u) const { return u >= 1.0 ? k_.t[i + 1] : k_.t[i] + u * dt(i); }
  double tau(std::ptrdiff_t j) const { return knot_[static_cast<std::size_t>(j + 3)]; }

  // Knots τ₋₃ … τₙ₊₃: the key times, reflected past both ends (for short tracks the
  // reflections use already-extended knots, which continues the spacing uniformly).
  void build_knots(std::ptrdiff_t n) {
    knot_.assign(static_cast<std::size_t>(n + 7), 0.0);
    for (std::ptrdiff_t j = 0; j <= n; ++j) knot_[j + 3] = k_.t[static_cast<std::size_t>(j)];
    auto at = [&](std::ptrdiff_t j) -> double& { return knot_[static_cast<std::size_t>(j + 3)]; };
    for (std::ptrdiff_t j = 1; j <= 3; ++j) {
      at(-j) = 2.0 * at(0) - at(j);
      at(n + j) = 2.0 * at(n) - at(n - j);
    }
  }

  void reflect_ends() {
    const std::size_t e = c_.size() - 1;  // cₙ₊₁
    c_[0] = (c_[1] * c_[2].conjugate() * c_[1]).normalized();
    c_[e] = (c_[e - 1] * c_[e - 2].conjugate() * c_[e - 1]).normalized();
    for (std::size_t j = 1; j < c_.size(); ++j) c_[j] = detail::align_pair(c_[j - 1], c_[j]);
  }

  // Cubic B-spline basis (The NURBS Book A2.2) on span s (τₛ ≤ x ≤ τₛ₊₁): N[k] and
  // dN[k] = dN/dx for the basis functions of c_{s−1+k}, k = 0…3.
  void basis(std::ptrdiff_t s, double x, double N[4], double dN[4]) const {
    double left[4], right[4], N2[3] = {0, 0, 0};
    // N depends only on ratios of knot differences: scaled by a power of two near
    // 1/span (exact, so no change elsewhere) so that on subnormal spans (keys
    // 1e-310 s apart) N[r]/(right + left) cannot overflow to inf and NaN weights.
    const double span = tau(s + 1) - tau(s);
    const int scale = span > 0.0 && std::isfinite(span) ? -std::ilogb(span) : 0;
    N[0] = 1.0;
    for (int j = 1; j <= 3; ++j) {
      left[j] = std::ldexp(x - tau(s + 1 - j), scale);
      right[j] = std::ldexp(tau(s + j) - x, scale);
      double saved = 0.0;
      for (int r = 0; r < j; ++r) {
        const double temp = N[r] / (right[r + 1] + left[j - r]);
        N[r] = saved + right[r + 1] * temp;
        saved = left[j - r] * temp;
      }
      N[j] = saved;
      if (j == 2) N2[0] = N[0], N2[1] = N[1], N2[2] = N[2];
    }
    // B′ₖ,₃ = 3(Bₖ,₂/(τₖ₊₃ − τₖ) − Bₖ₊₁,₂/(τₖ₊₄ − τₖ₊₁)), Bₖ ↔ N[k − s + 3].
    for (int j = 0; j < 4; ++j) {
      const std::ptrdiff_t k = s - 3 + j;
      const double lo = j > 0 ? N2[j - 1] / (tau(k + 3) - tau(k)) : 0.0;
      const double hi = j < 3 ? N2[j] / (tau(k + 4) - tau(k + 1)) : 0.0;
      dN[j] = 3.0 * (lo - hi);
    }
  }

  Quat point(std::ptrdiff_t s, double x) const {
    double N[4], dN[4];
    basis(s, x, N, dN);
    return average(s, N);
  }

  // BF average of c_{s−1} … c_{s+2} (stored at c_[s … s+3]) with weights N.
  Quat average(std::ptrdiff_t s, const double N[4]) const {
    const Quat* c = &c_[static_cast<std::size_t>(s)];
    return bf_average_of_points(c, N, 4, avg_);
  }

  // Key misses rⱼ = log(qⱼ·pⱼ⁻¹) (fixed frame) and pⱼ, the curve at tⱼ. Returns max |rⱼ|.
  double key_misses(std::vector<Vec3>& r, std::vector<Quat>& p) const {
    double worst = 0.0;
    for (std::size_t j = 0; j < k_.size(); ++j) {
      p[j] = average3(&c_[j], weights_at_keys_[j].data());
      r[j] = log(k_.q[j] * p[j].conjugate()).vec();
      worst = std::max(worst, r[j].norm());
    }
    return worst;
  }

  // The Jacobian G of the misses r (at the curve points p) w.r.t. fixed-frame
  // control point corrections δ (cₖ ← exp(δₖ)·cₖ), with the phantom points'
  // dependence folded in:
  //   pⱼ moves by R(pⱼ)·H⁻¹·wₖJ_l⁻¹(vₖ)·R(pⱼ)ᵀ·δₖ (implicit function of
  //   Σ wₖ log(p⁻¹cₖ) = 0, H = Σ wₖJ_l⁻¹(vₖ)), and rⱼ by −J_r⁻¹(rⱼ) times that.
  void key_jacobian(const std::vector<Vec3>& r, const std::vector<Quat>& p, std::vector<std::array<Mat3, 3>>& G) const {
    const auto n = static_cast<std::ptrdiff_t>(k_.size() - 1);
    for (std::ptrdiff_t j = 0; j <= n; ++j) {
      const Quat* c = &c_[static_cast<std::size_t>(j)];
      const double* w = weights_at_keys_[j].data();
      const Quat pi = p[j].conjugate();
      Mat3 H = Mat3::Zero(), Jinv[3];
      for (int k = 0; k < 3; ++k) {
        const Vec3 v = log_s3(pi * c[k]);
        Jinv[k] = so3_left_jacobian_inverse_with(v, so3_jacobian_c_newton(v.squaredNorm()));
        H += w[k] * Jinv[k];
      }
      const Mat3 Rp = p[j].toRotationMatrix();
      const Mat3 front = so3_right_jacobian_inverse(r[j]) * Rp * H.inverse();
      auto& g = G[j];
      for (int k = 0; k < 3; ++k) g[k] = front * (w[k] * Jinv[k]) * Rp.transpose();
      if (j == 0) {  // c₋₁ = c₀c₁⁻¹c₀ moves by (I + P)δ₀ − Pδ₁, P = R(c₀c₁⁻¹)
        const Mat3 P = (c_[1] * c_[2].conjugate()).toRotationMatrix();
        g[1] += g[0] * (Mat3::Identity() + P);
        g[2] -= g[0] * P;
        g[0].setZero();
      }
      if (j == n) {  // cₙ₊₁ = cₙcₙ₋₁⁻¹cₙ moves by (I + P)δₙ − Pδₙ₋₁, P = R(cₙcₙ₋₁⁻¹)
        const Mat3 P = (c_[n + 1] * c_[n].conjugate()).toRotationMatrix();
        g[1] += g[2] * (Mat3::Identity() + P);
        g[0] -= g[2] * P;
        g[2].setZero();
      }
    }
  }

  Quat average3(const Quat* c, const double* w) const {
    return bf_average_of_points(c, w, 3, avg_);
  }

  BfAverageOptions avg_;
  std::vector<std::array<double, 3>> weights_at_keys_;
  std::vector<double> knot_;  // τ₋₃ … τₙ₊₃ at [j + 3]
  std::vector<Quat> c_;       // c₋₁ … cₙ₊₁ at [j + 1], sign-continuous
};

}  // namespace

Result<std::unique_ptr<Interpolator>> make_bf(RotationTrack track, const BfSplineOptions& options) {
  auto keys = detail::prepare(std::move(track));
  if (!keys) return keys.failure();
  RotationTrack original;
  original.times = keys->t;
  original.keys = keys->q;
  double miss = 0.0;
  auto attempt = [&](const Interpolator* along, double max_step) {
    auto p = std::make_unique<BfInterpolator>(along ? detail::refine_bf_knots(*keys, max_step, *along) : *keys, options);
    miss = p->solve(options);
    // 1e-9 rad: the promise every interpolator makes about passing through the keys.
    return miss <= 1e-9 ? std::move(p) : nullptr;
  };
  // In-between knots on the c2 curve, where only wide steps need them. Where
  // intervals also need grading (c2 loops on an interval 1e10 times its neighbour),
  // or the c2 points do not let the control points converge, on the geodesics (as
  // slerp), halving the step up to 3 times.
  if (!detail::bf_knots_need_refinement(*keys, options.max_key_step)) {
    if (auto p = attempt(nullptr, 0.0)) return std::unique_ptr<Interpolator>(std::move(p));
  } else if (!detail::bf_knots_need_grading(*keys)) {
    auto c2 = make_c2(original);
    if (!c2) return c2.failure();
    if (auto p = attempt(c2->get(), options.max_key_step)) return std::unique_ptr<Interpolator>(std::move(p));
  }
  auto geodesic = detail::make_exact_slerp(original);
  if (!geodesic) return geodesic.failure();
  double max_step = options.max_key_step;
  for (int halving = 0; halving < 4; ++halving, max_step *= 0.5)
    if (auto p = attempt(geodesic->get(), max_step)) return std::unique_ptr<Interpolator>(std::move(p));
  return make_error("bf: control points did not converge (keys missed by " + std::to_string(miss) + " rad)");
}

}  // namespace rotinterp
