// The rotation core: exp/log, displacements, angular distance and velocity, swing–twist.
#include "rotinterp/core/rotation.h"

#include <cmath>

namespace rotinterp {

namespace {

bool finite(const Vec3& v) { return v.allFinite(); }

}  // namespace

Quat normalized_or_identity(const Quat& q) {
  const double n = q.norm();
  if (!(n > 0.0) || !std::isfinite(n)) return Quat::Identity();
  return Quat(q.w() / n, q.x() / n, q.y() / n, q.z() / n);
}

Quat align_to(const Quat& q, const Quat& ref) {
  return q.dot(ref) < 0.0 ? Quat(-q.w(), -q.x(), -q.y(), -q.z()) : q;
}

Mat3 hat(const Vec3& v) {
  Mat3 m;
  m << 0.0, -v.z(), v.y(),  //
      v.z(), 0.0, -v.x(),   //
      -v.y(), v.x(), 0.0;
  return m;
}

Vec3 vee(const Mat3& m) { return Vec3(m(2, 1) - m(1, 2), m(0, 2) - m(2, 0), m(1, 0) - m(0, 1)) * 0.5; }

Quat exp(const RotVec& r) {
  const Vec3& v = r.vec();
  if (!finite(v)) return Quat::Identity();
  const double theta2 = v.squaredNorm();
  if (!std::isfinite(theta2)) return Quat::Identity();  // |v| overflowed: no meaningful angle
  if (theta2 < kExpSeriesThreshold * kExpSeriesThreshold) {
    // Nested Taylor series in h² = (θ/2)² ≤ 1/16, through h¹² (truncation < 5e-20):
    // no square root, and |q| = 1 to rounding without renormalizing.
    const double h2 = 0.25 * theta2;
    constexpr double k2 = 1.0 / 2.0, k12 = 1.0 / 12.0, k30 = 1.0 / 30.0, k56 = 1.0 / 56.0, k90 = 1.0 / 90.0,
                     k132 = 1.0 / 132.0, k6 = 1.0 / 6.0, k20 = 1.0 / 20.0, k42 = 1.0 / 42.0, k72 = 1.0 / 72.0,
                     k110 = 1.0 / 110.0, k156 = 1.0 / 156.0;
    const double c = 1.0 - h2 * k2 * (1.0 - h2 * k12 * (1.0 - h2 * k30 * (1.0 - h2 * k56 * (1.0 - h2 * k90 * (1.0 - h2 * k132)))));
    const double s = 0.5 * (1.0 - h2 * k6 * (1.0 - h2 * k20 * (1.0 - h2 * k42 * (1.0 - h2 * k72 * (1.0 - h2 * k110 * (1.0 - h2 * k156))))));
    return Quat(c, s * v.x(), s * v.y(), s * v.z());
  }
  const double theta = std::sqrt(theta2);
  Quat q(std::cos(0.5 * theta), 0.0, 0.0, 0.0);
  q.vec() = (std::sin(0.5 * theta) / theta) * v;  // θ ≥ kExpSeriesThreshold
  // cos/sin are each correct to an ulp; renormalizing keeps |q| = 1 exactly enough.
  return q.normalized();
}

RotVec log(const Quat& q_in) {
  // The angle 2·atan2(|v|, w) and the axis v/|v| do not depend on |q|: a unit-ish q
  // (every interpolator's output) is used as it is; others are normalized first so
  // that tiny or huge ones neither underflow nor overflow below.
  const double n2 = q_in.coeffs().squaredNorm();
  const Quat q = (n2 >= 0.25 && n2 <= 4.0) ? q_in : normalized_or_identity(q_in);
  Vec3 xyz = q.vec();
  double w = q.w();
  // Canonical sign: w ≥ 0, and at w = 0 the first non-zero vector component positive,
  // so q and −q (the same orientation) give the same vector.
  bool flip = w < 0.0;
  if (w == 0.0) {
    for (int i = 0; i < 3; ++i) {
      if (xyz[i] != 0.0) {
        flip = xyz[i] < 0.0;
        break;
      }
    }
  }
  if (flip) {
    w = -w;
    xyz = -xyz;
  }
  const double s2 = xyz.squaredNorm();
  if (s2 == 0.0) return RotVec();
  if (s2 <= (1.0 / 64.0) * w * w) {
    return RotVec(xyz * angle_over_sine_series(s2, w));  // |v| ≤ w/8
  }
  // θ = 2·atan2(s, w) is accurate for every s.
  const double s = std::sqrt(s2);
  return RotVec(xyz * (2.0 * std::atan2(s, w) / s));
}

RotVec log_nearest(const Quat& q, const RotVec& previous) {
  const Vec3& p = previous.vec();
  const RotVec principal = log(q);
  if (!finite(p)) return principal;
  const double theta = principal.angle();
  if (theta == 0.0) {
    // Identity: candidates are the shells |v| = 2πk in any direction.
    const double pn = p.norm();
    if (pn == 0.0) return principal;
    const double k = std::round(pn / kTwoPi);
    return RotVec(p * (k * kTwoPi / pn));
  }
  const Vec3 axis = principal.vec() / theta;
  // Candidates v̂·(θ + 2πk) lie on one line; the nearest to p is the one nearest
  // p's projection on it.
  const double along = p.dot(axis);
  const double k = std::round((along - theta) / kTwoPi);
  return RotVec(axis * (theta + k * kTwoPi));
}

RotVec reparameterize(const RotVec& r) {
  const double theta = r.angle();
  if (!(theta > kPi) || !std::isfinite(theta)) return r;
  return RotVec(r.vec() * (1.0 - kTwoPi / theta));
}

RotVec compose(const RotVec& a, const RotVec& b) { return log(exp(a) * exp(b)); }

RotVec displacement_fixed(const Quat& q, const Quat& q2) {
  return log(normalized_or_identity(q2) * normalized_or_identity(q).conjugate());
}

RotVec displacement_moving(const Quat& q, const Quat& q2) {
  return log(normalized_or_identity(q).conjugate() * normalized_or_identity(q2));
}

Quat apply_fixed(const RotVec& r, const Quat& q) { return (exp(r) * normalized_or_identity(q)).normalized(); }

Quat apply_moving(const Quat& q, const RotVec& r) { return (normalized_or_identity(q) * exp(r)).normalized(); }

double angular_distance(const Quat& a_in, const Quat& b_in) {
  const Eigen::Vector4d a = normalized_or_identity(a_in).coeffs();
  Eigen::Vector4d b = normalized_or_identity(b_in).coeffs();
  if (a.dot(b) < 0.0) b = -b;
  // |a − b| = 2 sin(θ/4), |a + b| = 2 cos(θ/4) for a rotation by θ.
  return 4.0 * half_angle((a - b).norm(), (a + b).norm());
}

Vec3 angular_velocity(const Quat& q0, const Quat& q1, double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt)) return Vec3::Zero();
  const Vec3 w = displacement_fixed(q0, q1).vec() / dt;
  return w.allFinite() ? w : Vec3::Zero();
}

Quat integrate_angular_velocity(const Quat& q, const Vec3& omega, double dt) {
  return apply_fixed(RotVec(omega * dt), q);
}

SwingTwist swing_twist(const Quat& q_in, const Vec3& axis_in) {
  const Quat q = normalized_or_identity(q_in);
  const double an = axis_in.norm();
  if (!(an > 0.0) || !std::isfinite(an)) return {q, Quat::Identity()};
  const Vec3 axis = axis_in / an;
  const Vec3 proj = q.vec().dot(axis) * axis;
  Quat twist(q.w(), proj.x(), proj.y(), proj.z());
  const double tn = twist.norm();
  if (tn < kSwingTwistDegenerate) {
    twist = Quat::Identity();  // a pure 180° swing: no twist
  } else {
    twist.coeffs() /= tn;
  }
  Quat swing = (q * twist.conjugate()).normalized();
  return {swing, twist};
}

}  // namespace rotinterp
