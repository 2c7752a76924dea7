// Fitted key values: Gauss–Newton on the budget's residuals of the frames around a removed key.
#include "reducer.h"

#include "rotinterp/core/rotation.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <utility>

namespace rotinterp::detail {

// Values at the key frames `free` of j's curve through `keys` that bring the frames
// [lo, hi] within budget: Gauss–Newton on the residuals (`residual(f, q, out)`
// fills 3·blocks numbers and returns the frame's error, the largest block norm),
// each frame weighted by its error to the 6th power relative to the worst (Lawson's
// reweighting: the sum of squares leans towards the largest error, the bound that
// matters). Jacobians by forward differences of rotations of the values about their
// own axes. True with the values stored if it gets there; else they are restored.
Result<bool> Reducer::refit_values(std::size_t j, const std::vector<std::size_t>& keys, const std::vector<std::size_t>& free,
                                std::size_t lo, std::size_t hi, int blocks, const ResidualFn& residual) {
  const std::size_t frames = hi - lo + 1, rows = 3 * static_cast<std::size_t>(blocks), params = 3 * free.size();
  std::vector<Quat> start(free.size());
  for (std::size_t k = 0; k < free.size(); ++k) start[k] = value_[j][free[k]];
  // Residuals and frame errors of the values as they are now; the worst error.
  Eigen::VectorXd r(frames * rows), rp(frames * rows), err(frames), errp(frames);
  Eigen::MatrixXd jac(frames * rows, params);
  // The frames [a, b] measured again (the others' residuals as `out` and `e` hold them).
  std::vector<Quat> q;
  auto measure = [&](Eigen::VectorXd& out, Eigen::VectorXd& e, std::size_t a, std::size_t b) -> Result<double> {
    if (Status s = rebuild(j, keys, a, b, q); !s) return s.failure();
    for (std::size_t f = a; f <= b; ++f)
      e[static_cast<Eigen::Index>(f - lo)] = residual(f, q[f - a], out.data() + (f - lo) * rows);
    return e.maxCoeff();
  };
  // The frames of [lo, hi] a change of the values at the key frames `changed` moves:
  // within the method's support of each (MethodInfo::support), or all of them.
  const auto s = static_cast<std::size_t>(support(j));
  auto moved = [&](std::initializer_list<std::size_t> changed) {
    std::size_t a = hi, b = lo;
    for (std::size_t k : changed) {
      const auto i = static_cast<std::size_t>(std::lower_bound(keys.begin(), keys.end(), k) - keys.begin());
      a = std::min(a, s > 0 && i >= s ? std::max(lo, keys[i - s]) : lo);
      b = std::max(b, s > 0 && i + s < keys.size() ? std::min(hi, keys[i + s]) : hi);
    }
    return std::pair(a, b);
  };
  const auto [moved_lo, moved_hi] = free.size() == 1 ? moved({free[0]}) : moved({free.front(), free.back()});
  auto first = measure(r, err, lo, hi);
  if (!first) return first.failure();
  double worst = *first;
  constexpr double kStep = 1e-6;  // rad: the forward difference
  for (int iteration = 0; iteration < kRefitIterations; ++iteration) {
    rp = r;
    errp = err;
    for (std::size_t p = 0; p < params; ++p) {
      Quat& v = value_[j][free[p / 3]];
      const Quat keep = v;
      v = apply_moving(keep, RotVec(Vec3::Unit(static_cast<Eigen::Index>(p % 3)) * kStep));
      const auto [a, b] = moved({free[p / 3]});
      if (auto m = measure(rp, errp, a, b); !m) return m.failure();
      v = keep;
      // Rows outside [a, b] are the same residuals: a zero difference, as measuring them gives.
      jac.col(static_cast<Eigen::Index>(p)) = (rp - r) / kStep;
      const auto at = static_cast<Eigen::Index>((a - lo) * rows), count = static_cast<Eigen::Index>((b - a + 1) * rows);
      rp.segment(at, count) = r.segment(at, count);
    }
    Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(params), static_cast<Eigen::Index>(params));
    Eigen::VectorXd g = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(params));
    for (std::size_t f = 0; f < frames; ++f) {
      const double w = std::pow(std::max(err[static_cast<Eigen::Index>(f)] / worst, kRefitWeightFloor), 6);
      const auto rows_f = static_cast<Eigen::Index>(rows), at = static_cast<Eigen::Index>(f * rows);
      normal.noalias() += w * jac.middleRows(at, rows_f).transpose() * jac.middleRows(at, rows_f);
      g.noalias() += w * jac.middleRows(at, rows_f).transpose() * r.segment(at, rows_f);
    }
    normal.diagonal().array() += 1e-9 * normal.diagonal().maxCoeff() + 1e-300;
    const Eigen::VectorXd step = -normal.ldlt().solve(g);
    if (!step.allFinite()) break;
    errp = err;
    // The step, else a half, a quarter, … of it: the first that lowers the worst error.
    std::vector<Quat> before(free.size());
    for (std::size_t k = 0; k < free.size(); ++k) before[k] = value_[j][free[k]];
    bool better = false;
    for (double t = 1.0; t >= 1.0 / 16 && !better; t *= 0.5) {
      for (std::size_t k = 0; k < free.size(); ++k)
        value_[j][free[k]] = apply_moving(before[k], RotVec(t * step.segment<3>(static_cast<Eigen::Index>(3 * k))));
      auto now = measure(rp, errp, moved_lo, moved_hi);
      if (!now) return now.failure();
      if (*now <= 1.0) return true;
      if (*now < worst) better = true, worst = *now;
    }
    if (!better) break;
    r.swap(rp);
    err.swap(errp);
  }
  for (std::size_t k = 0; k < free.size(); ++k) value_[j][free[k]] = start[k];
  return false;
}

}  // namespace rotinterp::detail
