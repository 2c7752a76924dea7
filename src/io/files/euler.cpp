// Euler angles over three axes: orders, to a quaternion, and back nearest the previous angles.
#include "rotinterp/io/files/euler.h"

#include "rotinterp/core/result.h"

#include <cctype>
#include <cmath>

namespace rotinterp {

namespace {

Quat axis_rotation(int axis, double angle) {
  return Quat(Eigen::AngleAxisd(angle, Vec3::Unit(axis)));
}

// `angle` + 2πk nearest to `target`.
double nearest_shift(double angle, double target) {
  return angle + kTwoPi * std::round((target - angle) / kTwoPi);
}

Vec3 shifted_near(const Vec3& angles, const Vec3& previous) {
  return Vec3(nearest_shift(angles[0], previous[0]), nearest_shift(angles[1], previous[1]),
              nearest_shift(angles[2], previous[2]));
}

}  // namespace

bool is_valid_euler_axes(const EulerAxes& axes) {
  for (int a : axes)
    if (a < 0 || a > 2) return false;
  return axes[0] != axes[1] && axes[1] != axes[2];
}

std::optional<EulerAxes> parse_euler_order(std::string_view order) {
  if (order.size() != 3) return std::nullopt;
  EulerAxes axes{};
  for (int i = 0; i < 3; ++i) {
    const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(order[i])));
    if (c < 'X' || c > 'Z') return std::nullopt;
    axes[i] = c - 'X';
  }
  if (!is_valid_euler_axes(axes)) return std::nullopt;
  return axes;
}

Quat euler_to_quat(const EulerAxes& axes, const Vec3& angles) {
  return axis_rotation(axes[0], angles[0]) * axis_rotation(axes[1], angles[1]) * axis_rotation(axes[2], angles[2]);
}

Vec3 euler_nearest(const Quat& q_in, const EulerAxes& axes, const Vec3& previous) {
  ROTINTERP_ASSERT(is_valid_euler_axes(axes));
  const Quat q = normalized_or_identity(q_in);
  const bool proper = axes[0] == axes[2];
  // One solution from Eigen (θ₀ ∈ [0, π]); the other is (θ₀ + π, π − θ₁, θ₂ + π)
  // for Tait–Bryan and (θ₀ + π, −θ₁, θ₂ + π) for proper Euler sequences.
  const Vec3 first = q.toRotationMatrix().eulerAngles(axes[0], axes[1], axes[2]);
  const double lock = proper ? std::abs(std::sin(first[1])) : std::abs(std::cos(first[1]));
  if (lock < kGimbalLockThreshold) {
    // Only θ₀ ± θ₂ is determined: keep θ₀, solve θ₂ from the residual rotation.
    Vec3 best;
    double best_d = INFINITY;
    for (double middle : {first[1], proper ? -first[1] : kPi - first[1]}) {
      const double a = previous[0];
      const double b = nearest_shift(middle, previous[1]);
      const Quat rest = (axis_rotation(axes[0], a) * axis_rotation(axes[1], b)).conjugate() * q;
      const double c = nearest_shift(2.0 * std::atan2(rest.vec()[axes[2]], rest.w()), previous[2]);
      const Vec3 cand(a, b, c);
      const double d = (cand - previous).squaredNorm();
      if (d < best_d) best_d = d, best = cand;
    }
    return best;
  }
  const Vec3 second(first[0] + kPi, proper ? -first[1] : kPi - first[1], first[2] + kPi);
  const Vec3 a = shifted_near(first, previous);
  const Vec3 b = shifted_near(second, previous);
  return (a - previous).squaredNorm() <= (b - previous).squaredNorm() ? a : b;
}

}  // namespace rotinterp
