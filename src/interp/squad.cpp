// squad: Shoemake's spherical quadrangle with control points for non-uniform times.
#include "rotinterp/interp/squad.h"

#include "detail.h"
#include "rotinterp/core/so3_jacobian.h"
#include "rotinterp/interp/slerp.h"

#include <vector>

namespace rotinterp {

Quat squad(const Quat& q0, const Quat& q1, const Quat& a, const Quat& b, double h) {
  return great_arc_slerp(great_arc_slerp(q0, q1, h), great_arc_slerp(a, b, h), 2.0 * h * (1.0 - h));
}

namespace {

// log of q along its great arc from the identity, as stored: for w < 0 the angle
// is in (π, 2π] — what great_arc_slerp(1, q, ·) turns through. (The core log
// flips to the short side.)
Vec3 log_great_arc(const Quat& q) {
  if (q.w() >= 0.0) return log(q).vec();
  const Vec3 r = log(detail::negated(q)).vec();  // the same orientation, short side
  const double n = r.norm();
  return n > 0.0 ? Vec3(r * (1.0 - kTwoPi / n)) : Vec3::Zero();
}

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
      // The signs are fixed here, once per segment: each control is within 45° (in
      // S³) of its key, and the blends between them follow great arcs as stored.
      M_.push_back(log_great_arc(a_[s].conjugate() * b_[s]));
      K_.push_back(L[s]);
    }
  }

  Quat segment(std::size_t i, double u) const {
    if (u <= 0.0) return k_.q[i];  // squad(…, 0) is qᵢ bit for bit; skip its three slerps
    if (u >= 1.0) return k_.q[i + 1];
    return squad(k_.q[i], k_.q[i + 1], a_[i], b_[i], u);
  }

  // q(u) = P·exp(g·X): P = qᵢexp(uL), Q = aᵢexp(uM), g = 2u(1−u), X = log(P⁻¹Q)
  // along the great arc (|X| up to 2π, as the blend turns).
  // World rates per unit u: ω_P = P·L, ω_Q = Q·M; Y = P⁻¹Q moves with
  // y = P⁻¹(ω_Q − ω_P); Ẋ = J_l⁻¹(X)·y; ω_E = J_l(gX)(ġX + gẊ); ω = ω_P + P·ω_E.
  Vec3 segment_velocity(std::size_t i, double u) const {
    const Quat P = great_arc_slerp(k_.q[i], k_.q[i + 1], u);
    const Quat Q = great_arc_slerp(a_[i], b_[i], u);
    const Vec3 wP = P * K_[i];
    const Vec3 wQ = Q * M_[i];
    const Vec3 X = log_great_arc(P.conjugate() * Q);
    const Vec3 y = P.conjugate() * (wQ - wP);
    const Vec3 Xdot = so3_left_jacobian_inverse_times(X, y);
    const double g = 2.0 * u * (1.0 - u), gdot = 2.0 - 4.0 * u;
    const Vec3 wE = so3_left_jacobian_times(g * X, gdot * X + g * Xdot);
    return (wP + P * wE) / dt(i);
  }

 private:
  std::vector<Quat> a_, b_;  // per segment: outgoing control at its start, incoming at its end
  std::vector<Vec3> K_, M_;  // per segment: log(qᵢ⁻¹qᵢ₊₁), log(aᵢ⁻¹bᵢ₊₁) along its great arc
};

}  // namespace

Result<std::unique_ptr<Interpolator>> make_squad(RotationTrack track) {
  auto keys = detail::prepare(std::move(track));
  if (!keys) return keys.failure();
  return std::unique_ptr<Interpolator>(new SquadInterpolator(std::move(*keys)));
}

}  // namespace rotinterp
