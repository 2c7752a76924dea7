// Euler angles over a sequence of three axes, as BVH rotation channels use them.
//
// Axes are 0 = x, 1 = y, 2 = z. An axis sequence (a₀, a₁, a₂) means the rotation
// R_a₀(θ₀)·R_a₁(θ₁)·R_a₂(θ₂): the first axis is outermost (applied last to a
// vector), as in a BVH CHANNELS line. Valid sequences have a₀ ≠ a₁ ≠ a₂: the six
// Tait–Bryan orders (XYZ, …) and the six proper Euler orders (XYX, …). Angles in
// radians.
#pragma once

#include "rotinterp/core/rotation.h"

#include <array>
#include <optional>
#include <string_view>

namespace rotinterp {

using EulerAxes = std::array<int, 3>;

// "ZXY" → {2, 0, 1}; case-insensitive; nullopt unless three valid axis letters
// forming a valid sequence.
std::optional<EulerAxes> parse_euler_order(std::string_view order);
bool is_valid_euler_axes(const EulerAxes& axes);

// R_a₀(θ₀)·R_a₁(θ₁)·R_a₂(θ₂) as a unit quaternion.
Quat euler_to_quat(const EulerAxes& axes, const Vec3& angles);

// Below this |cos θ₁| (Tait–Bryan) or |sin θ₁| (proper Euler) the sequence is at
// gimbal lock: only θ₀ ± θ₂ is determined. There θ₀ keeps its previous value and θ₂
// takes the rest, so the curves stay continuous. 1e-9 is far below what a 6-decimal
// file resolves (1e-6° ≈ 1.7e-8 rad) and far above double round-off in the matrix.
constexpr double kGimbalLockThreshold = 1e-9;

// Angles of q in the sequence `axes`, chosen among both Euler solutions and all
// 2π shifts of each angle as the one nearest `previous` (Euclidean distance in
// R³): a sequence of calls following a smooth motion gives curves without ±180°
// wraps or branch flips. euler_to_quat(axes, result) equals ±q to round-off.
Vec3 euler_nearest(const Quat& q, const EulerAxes& axes, const Vec3& previous);

}  // namespace rotinterp
