#include "rotinterp/interp/squad.h"

#include "detail.h"
#include "rotinterp/interp/slerp.h"

#include <vector>

namespace rotinterp {

Quat squad(const Quat& q0, const Quat& q1, const Quat& a, const Quat& b, double h) {
  return slerp(slerp(q0, q1, h), slerp(a, b, h), 2.0 * h * (1.0 - h));
}

namespace {

class SquadInterpolator final : public detail::SegmentInterpolator<SquadInterpolator> {
 public:
  explicit SquadInterpolator(detail::Keys keys) : SegmentInterpolator(std::move(keys)) {
    const std::size_t n = k_.size();
    if (n < 2) return;
    const std::size_t segs = n - 1;
    std::vector<Vec3> L(segs);
    for (std::size_t i = 0; i < segs; ++i) L[i] = log(k_.q[i].conjugate() * k_.q[i + 1]).vec();
    // Phantom keys: L₋₁ = L₀ over Δ₀, Lₙ = Lₙ₋₁ over Δₙ₋₁ (see the header).
    auto Lat = [&](std::ptrdiff_t i) -> const Vec3& {
      return L[static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(i, 0, static_cast<std::ptrdiff_t>(segs) - 1))];
    };
    auto Dat = [&](std::ptrdiff_t i) {
      const auto j = static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(i, 0, static_cast<std::ptrdiff_t>(segs) - 1));
      return dt(j);
    };
    a_.resize(segs);
    b_.resize(segs);
    for (std::size_t s = 0; s < segs; ++s) {
      const auto i = static_cast<std::ptrdiff_t>(s);
      const double D = dt(s);
      a_[s] = apply_moving(k_.q[s], RotVec(0.25 * (Lat(i - 1) * (D / Dat(i - 1)) - L[s])));
      b_[s] = apply_moving(k_.q[s + 1], RotVec(0.25 * (L[s] - Lat(i + 1) * (D / Dat(i + 1)))));
      // Keep the controls in their key's hemisphere (the curve does not depend on it).
      a_[s] = detail::align_pair(k_.q[s], a_[s]);
      b_[s] = detail::align_pair(k_.q[s + 1], b_[s]);
      M_.push_back(log(a_[s].conjugate() * b_[s]).vec());
      K_.push_back(L[s]);
    }
  }

  Quat segment(std::size_t i, double u) const {
    if (u <= 0.0) return k_.q[i];  // squad(…, 0) is qᵢ bit for bit; skip its three slerps
    if (u >= 1.0) return k_.q[i + 1];
    return squad(k_.q[i], k_.q[i + 1], a_[i], b_[i], u);
  }

  // q(u) = P·exp(g·X): P = qᵢexp(uL), Q = aᵢexp(uM), g = 2u(1−u), X = log(P⁻¹Q).
  // World rates per unit u: ω_P = P·L, ω_Q = Q·M; Y = P⁻¹Q moves with
  // y = P⁻¹(ω_Q − ω_P); Ẋ = J_l⁻¹(X)·y; ω_E = J_l(gX)(ġX + gẊ); ω = ω_P + P·ω_E.
  Vec3 segment_velocity(std::size_t i, double u) const {
    const Quat P = slerp(k_.q[i], k_.q[i + 1], u);
    const Quat Q = slerp(a_[i], b_[i], u);
    const Vec3 wP = P * K_[i];
    const Vec3 wQ = Q * M_[i];
    const Vec3 X = log(P.conjugate() * Q).vec();
    const Vec3 y = P.conjugate() * (wQ - wP);
    const Vec3 Xdot = rotvec_derivative(X, y);
    const double g = 2.0 * u * (1.0 - u), gdot = 2.0 - 4.0 * u;
    const Vec3 wE = detail::left_jacobian_times(g * X, gdot * X + g * Xdot);
    return (wP + P * wE) / dt(i);
  }

 private:
  std::vector<Quat> a_, b_;  // per segment: outgoing control at its start, incoming at its end
  std::vector<Vec3> K_, M_;  // per segment: log(qᵢ⁻¹qᵢ₊₁), log(aᵢ⁻¹bᵢ₊₁)
};

}  // namespace

Result<std::unique_ptr<Interpolator>> make_squad(const RotationTrack& track) {
  auto keys = detail::prepare(track);
  if (!keys) return make_error(keys.error());
  return std::unique_ptr<Interpolator>(new SquadInterpolator(std::move(*keys)));
}

}  // namespace rotinterp
