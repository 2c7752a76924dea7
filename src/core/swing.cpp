// Grassia's exp derivatives and the swing parameterization with its elliptical limit.
#include "rotinterp/core/swing.h"

#include <cmath>

namespace rotinterp {

namespace {

// sin(θ/2)/θ, the factor that maps v to the vector part of exp(v).
double sinc_half(double theta) {
  if (theta < kExpTaylorThreshold) return 0.5 - theta * theta / 48.0;
  return std::sin(0.5 * theta) / theta;
}

}  // namespace

Eigen::Matrix<double, 4, 3> dq_dv(const Vec3& v) {
  Eigen::Matrix<double, 4, 3> J;
  const double theta = v.norm();
  if (!std::isfinite(theta)) return J.setZero();
  const double s = sinc_half(theta);
  // d(sin(θ/2)/θ)/dθ / θ: series below kDqDvSeries (see header).
  double ds_over_theta;
  if (theta < kDqDvSeries) {
    const double t2 = theta * theta;
    ds_over_theta = -1.0 / 24.0 + t2 / 960.0 - t2 * t2 / 107520.0;
  } else {
    ds_over_theta = (0.5 * theta * std::cos(0.5 * theta) - std::sin(0.5 * theta)) / (theta * theta * theta);
  }
  J.row(0) = -0.5 * s * v.transpose();
  J.bottomRows<3>() = s * Mat3::Identity() + ds_over_theta * v * v.transpose();
  return J;
}

std::array<Mat3, 3> dR_dv(const Vec3& v) {
  const Quat q = exp(RotVec(v));
  const double w = q.w(), x = q.x(), y = q.y(), z = q.z();
  // ∂R/∂(w, x, y, z) of R = [[1−2(y²+z²), 2(xy−wz), 2(xz+wy)], …] (Grassia eq. 3).
  std::array<Mat3, 4> dR_dq;
  dR_dq[0] << 0, -2 * z, 2 * y,  //
      2 * z, 0, -2 * x,          //
      -2 * y, 2 * x, 0;
  dR_dq[1] << 0, 2 * y, 2 * z,  //
      2 * y, -4 * x, -2 * w,    //
      2 * z, 2 * w, -4 * x;
  dR_dq[2] << -4 * y, 2 * x, 2 * w,  //
      2 * x, 0, 2 * z,               //
      -2 * w, 2 * z, -4 * y;
  dR_dq[3] << -4 * z, -2 * w, 2 * x,  //
      2 * w, -4 * z, 2 * y,           //
      2 * x, 2 * y, 0;
  const Eigen::Matrix<double, 4, 3> J = dq_dv(v);
  std::array<Mat3, 3> out;
  for (int i = 0; i < 3; ++i) {
    out[i] = J(0, i) * dR_dq[0] + J(1, i) * dR_dq[1] + J(2, i) * dR_dq[2] + J(3, i) * dR_dq[3];
  }
  return out;
}

SwingParam SwingParam::perpendicular_to(const Vec3& twist_axis) {
  Vec3 a = twist_axis.norm() > 0.0 ? Vec3(twist_axis.normalized()) : Vec3::UnitZ();
  // Start from the coordinate axis least aligned with a.
  Eigen::Index i;
  a.cwiseAbs().minCoeff(&i);
  Vec3 e = Vec3::Zero();
  e[i] = 1.0;
  SwingParam p;
  p.s = (e - e.dot(a) * a).normalized();
  p.t = a.cross(p.s);
  return p;
}

Eigen::Matrix<double, 4, 2> SwingParam::dq_dswing(double alpha, double beta) const {
  Eigen::Matrix<double, 3, 2> B;
  B.col(0) = s;
  B.col(1) = t;
  return dq_dv(vector(alpha, beta)) * B;
}

bool within_swing_limit(double alpha, double beta, double a, double b) {
  if (!(a > 0.0) || !(b > 0.0)) return false;
  const double u = alpha / a, w = beta / b;
  return u * u + w * w <= 1.0;
}

}  // namespace rotinterp
