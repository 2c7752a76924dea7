// expmap: a cubic spline of the keys' rotation vectors.
#include "rotinterp/interp/expmap.h"

#include "detail.h"
#include "rotinterp/core/average.h"
#include "rotinterp/core/so3_jacobian.h"

#include <vector>

namespace rotinterp {

namespace {

class ExpmapInterpolator final : public detail::SegmentInterpolator<ExpmapInterpolator> {
 public:
  ExpmapInterpolator(detail::Keys keys, const ExpmapOptions& opt) : SegmentInterpolator(std::move(keys)) {
    const std::size_t n = k_.size();
    if (opt.relative_to_mean && n > 1) {
      std::vector<double> w(n, 1.0 / static_cast<double>(n));
      auto m = bf_average(k_.q, w);
      ref_ = m ? *m : chordal_mean(k_.q, w);
    }
    const Quat ref_inv = ref_.conjugate();
    v_.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
      const Quat local = ref_inv * k_.q[k];
      v_[k] = log(local).vec();
      if (opt.unwrap && k > 0) {
        // Nearest branch; on an exact tie (e.g. a 180° key after the identity) the
        // principal log, so the half-turn goes the way slerp documents.
        const Vec3 near = log_nearest(local, RotVec(v_[k - 1])).vec();
        if ((near - v_[k - 1]).norm() < (v_[k] - v_[k - 1]).norm()) v_[k] = near;
      }
    }
    if (n < 2) return;
    m_.resize(n);
    if (opt.spline == ExpmapOptions::Spline::catmull_rom || n == 2) {
      m_[0] = (v_[1] - v_[0]) / dt(0);
      m_[n - 1] = (v_[n - 1] - v_[n - 2]) / dt(n - 2);
      for (std::size_t k = 1; k + 1 < n; ++k) m_[k] = (v_[k + 1] - v_[k - 1]) / (k_.t[k + 1] - k_.t[k - 1]);
    } else {
      natural_tangents();
    }
  }

  Quat segment(std::size_t i, double u) const { return ref_ * exp(RotVec(value(i, u))); }

  Vec3 segment_velocity(std::size_t i, double u) const {
    // q = m·exp(v): ω = m·J_l(v)·v̇.
    const double h = dt(i);
    const double u2 = u * u;
    const Vec3 vdot = ((6.0 * u2 - 6.0 * u) * v_[i] + (3.0 * u2 - 4.0 * u + 1.0) * h * m_[i] +
                       (-6.0 * u2 + 6.0 * u) * v_[i + 1] + (3.0 * u2 - 2.0 * u) * h * m_[i + 1]) /
                      h;
    return ref_ * so3_left_jacobian_times(value(i, u), vdot);
  }

 private:
  Vec3 value(std::size_t i, double u) const {
    const double h = dt(i);
    const double u2 = u * u, u3 = u2 * u;
    return (2.0 * u3 - 3.0 * u2 + 1.0) * v_[i] + (u3 - 2.0 * u2 + u) * h * m_[i] + (-2.0 * u3 + 3.0 * u2) * v_[i + 1] +
           (u3 - u2) * h * m_[i + 1];
  }

  // Natural cubic spline: second derivatives Mₖ from the tridiagonal system
  // hₖ₋₁Mₖ₋₁ + 2(hₖ₋₁ + hₖ)Mₖ + hₖMₖ₊₁ = 6(dₖ − dₖ₋₁), M₀ = Mₙ = 0 (dₖ the slopes),
  // then the knot tangents of the same curve in Hermite form.
  void natural_tangents() {
    const std::size_t n = k_.size();
    std::vector<Vec3> d(n - 1), M(n, Vec3::Zero()), rhs(n);
    std::vector<double> diag(n), sup(n);
    for (std::size_t k = 0; k + 1 < n; ++k) d[k] = (v_[k + 1] - v_[k]) / dt(k);
    // Thomas algorithm on the interior unknowns M₁ … Mₙ₋₂.
    for (std::size_t k = 1; k + 1 < n; ++k) {
      diag[k] = 2.0 * (dt(k - 1) + dt(k));
      sup[k] = dt(k);
      rhs[k] = 6.0 * (d[k] - d[k - 1]);
      if (k > 1) {
        const double f = dt(k - 1) / diag[k - 1];
        diag[k] -= f * sup[k - 1];
        rhs[k] -= f * rhs[k - 1];
      }
    }
    for (std::size_t k = n - 2; k >= 1; --k) {
      M[k] = (rhs[k] - (k + 2 < n ? Vec3(sup[k] * M[k + 1]) : Vec3::Zero())) / diag[k];
      if (k == 1) break;
    }
    for (std::size_t k = 0; k + 1 < n; ++k) m_[k] = d[k] - dt(k) * (2.0 * M[k] + M[k + 1]) / 6.0;
    m_[n - 1] = d[n - 2] + dt(n - 2) * (M[n - 2] + 2.0 * M[n - 1]) / 6.0;
  }

  Quat ref_ = Quat::Identity();
  std::vector<Vec3> v_;  // key rotation vectors (relative to ref_)
  std::vector<Vec3> m_;  // knot tangents dv/dt
};

}  // namespace

Result<std::unique_ptr<Interpolator>> make_expmap(RotationTrack track, const ExpmapOptions& options) {
  auto keys = detail::prepare(std::move(track));
  if (!keys) return keys.failure();
  return std::unique_ptr<Interpolator>(new ExpmapInterpolator(std::move(*keys), options));
}

}  // namespace rotinterp
