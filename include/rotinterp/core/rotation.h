// Rotation core: orientations, rotations and the maps between them.
//
// Conventions (stated once, used everywhere in rotinterp):
//  * Quaternions are Hamilton quaternions q = w + xi + yj + zk, multiplied with
//    Hamilton's rule (ij = k). Storage is Eigen's: coeffs() = (x, y, z, w), but
//    the constructor Quat(w, x, y, z) takes w first.
//  * Vectors are column vectors; a quaternion acts on a vector as q v q⁻¹, i.e.
//    as the matrix q.toRotationMatrix() applied on the left.
//  * An ORIENTATION (Lee) is a unit quaternion `Quat`; q and −q are the same
//    orientation. A ROTATION (a displacement, Lee) is a `RotVec`: a vector in R³
//    whose direction is the axis and whose length is the angle in radians
//    (right-hand rule). exp maps v ↦ q = (cos(|v|/2), sin(|v|/2)·v̂).
//  * Angular velocity ω is in the fixed (world, "spatial") frame: q̇ = ½ ω̃ q with
//    ω̃ = (0, ω). Displacement "in the fixed frame" is q′q⁻¹ (applied on the left),
//    "in the moving frame" q⁻¹q′ (applied on the right).
//  * Non-unit input quaternions are normalized; a zero or non-finite quaternion is
//    read as the identity, and a non-finite vector as the zero rotation, so that no
//    NaN ever leaves these functions.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <limits>

namespace rotinterp {

// Scalar exp/log stay usable inside the namespace next to the rotation ones.
using std::exp;
using std::log;

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;

// Below this angle (rad) exp sums the series of cos(θ/2) and sin(θ/2)/θ instead of
// calling libm: through the θ¹² terms they are exact to < 1e-19 there, and nearly
// every rotation a spline or a metric exponentiates (a step between nearby keys or
// frames, 29° at most) is this small.
constexpr double kExpSeriesThreshold = 0.5;

// A rotation (displacement) as a rotation vector: axis · angle.
class RotVec {
 public:
  RotVec() : v_(Vec3::Zero()) {}
  explicit RotVec(const Vec3& v) : v_(v) {}
  RotVec(double x, double y, double z) : v_(x, y, z) {}
  static RotVec from_axis_angle(const Vec3& axis, double angle) { return RotVec(axis.normalized() * angle); }

  const Vec3& vec() const { return v_; }
  double angle() const { return v_.norm(); }  // radians, ≥ 0
  double x() const { return v_.x(); }
  double y() const { return v_.y(); }
  double z() const { return v_.z(); }

  RotVec operator-() const { return RotVec(-v_); }
  RotVec operator*(double s) const { return RotVec(v_ * s); }  // scale the angle
  RotVec operator/(double s) const { return RotVec(v_ / s); }
  friend RotVec operator*(double s, const RotVec& r) { return r * s; }
  // Sum/difference of rotation vectors: a tangent-space (Lie algebra) operation,
  // NOT composition of rotations (use compose()).
  RotVec operator+(const RotVec& o) const { return RotVec(v_ + o.v_); }
  RotVec operator-(const RotVec& o) const { return RotVec(v_ - o.v_); }

 private:
  Vec3 v_;
};

// ---- basic helpers ----------------------------------------------------------

// q / |q|; the identity for a zero or non-finite q.
Quat normalized_or_identity(const Quat& q);
// ±q, whichever is in the hemisphere of ref (dot ≥ 0).
Quat align_to(const Quat& q, const Quat& ref);
// The skew matrix [v]× (hat) and its inverse (vee).
Mat3 hat(const Vec3& v);
Vec3 vee(const Mat3& m);

// ---- exp and log --------------------------------------------------------------

// R³ → S³. Smooth everywhere, series branch below kExpSeriesThreshold.
Quat exp(const RotVec& r);

// atan x = x + x·x²·p(x²) for |x| ≤ 1/8, p(y) = −1/3 + y/5 − y²/7 + … + y⁷/17:
// half_angle's series, also for callers that have x² but not x.
inline double atan_series_tail(double x2) {
  // Estrin's scheme: four independent pairs, then two levels (a short dependency chain).
  const double y2 = x2 * x2, y4 = y2 * y2;
  const double p01 = -1.0 / 3.0 + x2 * (1.0 / 5.0), p23 = -1.0 / 7.0 + x2 * (1.0 / 9.0);
  const double p45 = -1.0 / 11.0 + x2 * (1.0 / 13.0), p67 = -1.0 / 15.0 + x2 * (1.0 / 17.0);
  return (p01 + y2 * p23) + y4 * (p45 + y2 * p67);
}
// atan2(s, w) for s ≥ 0: the half angle of a quaternion (w, v) with s = |v|, under
// every log and every error angle. For 0 ≤ s ≤ w/8 (rotations below 14°: nearly all
// steps between frames and nearly all interpolation errors) it sums the series of
// atan(s/w) through the x¹⁷ term (truncation < 3e-18 relative), within 2 ulp of
// std::atan2 and several times cheaper than libm's correctly rounded atan2, which
// it calls everywhere else (and for NaN).
// 2·atan(s/w)/s from s² for 0 ≤ s ≤ w/8 (the caller checks s² ≤ w²/64): the series
// branch of half_angle, without the square root — what log needs to scale v.
inline double angle_over_sine_series(double s2, double w) {
  const double iw = 1.0 / w, x2 = s2 * iw * iw;
  return 2.0 * iw * (1.0 + x2 * atan_series_tail(x2));
}
inline double half_angle(double s, double w) {
  if (!(w > 0.0 && s >= 0.0 && s <= 0.125 * w)) return std::atan2(s, w);
  const double x = s / w, x2 = x * x;
  return x + x * (x2 * atan_series_tail(x2));
}

// S³ → R³ with |v| ≤ π, via atan2 (no acos). Exact near the identity. For exactly
// 180° (w = 0) the result is the same for q and −q: the axis whose first non-zero
// component is positive.
RotVec log(const Quat& q);
// Grassia §4.2: the preimage of ±q nearest to `previous` among v̂·(θ + 2πk). Lets a
// sequence of logs follow spins past π and 2π without jumps. For q = identity the
// candidates are the shells |v| = 2πk; the one nearest `previous` is returned.
RotVec log_nearest(const Quat& q, const RotVec& previous);
// Grassia §3 dynamic reparameterization: for |v| > π return (1 − 2π/|v|)·v, the
// same rotation further from the singular shell |v| = 2π; otherwise v unchanged.
RotVec reparameterize(const RotVec& r);

// ---- Lee's operations ----------------------------------------------------------

// exp(a)·exp(b) as a rotation vector: a applied after b.
RotVec compose(const RotVec& a, const RotVec& b);
// Displacement from q to q2 in the fixed frame: log(q2 q⁻¹), so q2 = exp(d)·q.
RotVec displacement_fixed(const Quat& q, const Quat& q2);
// Displacement from q to q2 in the moving (body) frame: log(q⁻¹ q2), so q2 = q·exp(d).
RotVec displacement_moving(const Quat& q, const Quat& q2);
// exp(r)·q: rotate q by r about fixed-frame axes.
Quat apply_fixed(const RotVec& r, const Quat& q);
// q·exp(r): rotate q by r about its own (moving) axes.
Quat apply_moving(const Quat& q, const RotVec& r);
// Geodesic distance (the angle of the rotation between them) in radians, in [0, π]:
// 4·atan2(|a − b|, |a + b|) after hemisphere alignment. (|a − b| = 2 sin(θ/4) and
// |a + b| = 2 cos(θ/4): 2·atan2 — as sometimes printed — is the 4-D angle between
// the quaternions, half the rotation angle. The 2·acos|a·b| form reads float
// round-off as ~0.05°.)
double angular_distance(const Quat& a, const Quat& b);

// ---- angular velocity -----------------------------------------------------------
// (The rate of a rotation vector, v̇ = J_l⁻¹(v)·ω, and the other SO(3) Jacobians:
// so3_jacobian.h.)

// Constant fixed-frame angular velocity taking q0 to q1 in dt: log(q1 q0⁻¹)/dt.
// Returns zero for dt ≤ 0.
Vec3 angular_velocity(const Quat& q0, const Quat& q1, double dt);
// exp(ω·dt)·q: integrate a constant fixed-frame angular velocity over dt.
Quat integrate_angular_velocity(const Quat& q, const Vec3& omega, double dt);

// ---- swing and twist ----------------------------------------------------------------

// q = swing · twist, twist a rotation about `axis` (in the moving frame), swing a
// rotation about an axis perpendicular to it. For a pure 180° swing the twist is
// the identity; so it is when the twist part (w, q·axis) has a norm below
// kSwingTwistDegenerate: there the twist is ill-conditioned (round-off δ ≈ 1e-16
// turns it by δ/norm), and a swing within √ε of 180° carries the whole rotation.
constexpr double kSwingTwistDegenerate = 1.5e-8;  // ≈ √ε: kept twists are exact to ~1e-8 rad
struct SwingTwist {
  Quat swing;
  Quat twist;
};
SwingTwist swing_twist(const Quat& q, const Vec3& axis);

}  // namespace rotinterp
