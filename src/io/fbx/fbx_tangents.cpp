// fbx_key_tangents: each key's left and right tangent as the DCC evaluates it —
// stored for user keys, solved from the neighbours for auto/spline/clamped keys
// (with the stored auto bias), from tension/continuity/bias for TCB keys.
#include "rotinterp/io/fbx/fbx_curve_eval.h"

#include <algorithm>
#include <cmath>

namespace rotinterp {

namespace {

constexpr double kThird = 1.0 / 3.0;
// Flags that shape an auto tangent (FbxAnimCurveDef): clamp to flat where a
// neighbour has the same value, time-independent (the chord of the neighbours),
// progressive clamp (no overshoot past either neighbour).
constexpr std::uint32_t kClamp = 0x1000, kTimeIndependent = 0x2000, kClampProgressive = 0x4000;
// Auto biases (percent) whose sum is below this count as one shared bias.
constexpr double kSharedBias = 1e-4;
// Past ±500 % an auto bias adds ((|bias| − 500)/100)² · 40 to the slope.
constexpr double kBiasKink = 5.0, kBiasKinkGain = 40.0;

double seconds(const FbxKey& k) { return static_cast<double>(k.ticks) / static_cast<double>(kFbxTicksPerSecond); }

double secant(const FbxKey& a, const FbxKey& b) {
  const double dt = seconds(b) - seconds(a);
  return dt > 0.0 ? (b.value - a.value) / dt : 0.0;
}

double bias_kink(double slope, double bias) {
  const double over = std::abs(bias) / 100.0 - kBiasKink;
  return over > 0.0 ? slope + over * over * (bias > 0.0 ? 1.0 : -1.0) * kBiasKinkGain : slope;
}

// An interior auto key's slope from its neighbours.
double solve_auto(const FbxKey& p, const FbxKey& k, const FbxKey& n, double w_left, double w_right, double bias) {
  const std::uint32_t flags = k.flags;
  if ((flags & kClamp) && std::min(std::abs(p.value - k.value), std::abs(n.value - k.value)) <= 0.0) return 0.0;
  const double tp = seconds(p), t = seconds(k), tn = seconds(n);
  double slope = (n.value - p.value) / (tn - tp);
  if (!(flags & kTimeIndependent)) {
    const double left = (k.value - p.value) / (t - tp), right = (n.value - k.value) / (tn - t);
    const double delta = (t - tp) / (tn - tp);
    slope = 0.5 * slope + 0.5 * (left * (1.0 - delta) + right * delta);
    const double weight = std::abs(bias) / 100.0;
    if (weight > 1e-4) {
      const double target = bias > 0.0 ? right : left;
      const double towards = target - slope;
      slope = slope * (1.0 - weight) + target * weight;
      const double over = weight - kBiasKink;
      if (over > 0.0) {
        const double sign = (std::abs(towards) > 1e-5 ? towards : bias) > 0.0 ? 1.0 : -1.0;
        slope += over * over * sign * kBiasKinkGain;
      }
    }
  }
  if (flags & kClampProgressive) {
    const double sign = slope >= 0.0 ? 1.0 : -1.0;
    double magnitude = sign * slope;
    const double range_left = w_left * (t - tp), range_right = w_right * (tn - t);
    double max_left = range_left > 0.0 ? sign * (k.value - p.value) / range_left : 0.0;
    double max_right = range_right > 0.0 ? sign * (n.value - k.value) / range_right : 0.0;
    if (!(max_left > 0.0)) max_left = 0.0;
    if (!(max_right > 0.0)) max_right = 0.0;
    magnitude = std::min({magnitude, max_left, max_right});
    slope = sign * magnitude;
  }
  return slope;
}

// An end key's auto slope: the chord to its one neighbour.
double solve_auto_end(const FbxKey& a, const FbxKey& b, const FbxKey& k, double bias) {
  if (k.flags & kClampProgressive) return 0.0;
  if ((k.flags & kClamp) && std::abs(b.value - a.value) <= 0.0) return 0.0;
  const double slope = secant(a, b);
  return (k.flags & kTimeIndependent) ? slope : bias_kink(slope, bias);
}

}  // namespace

FbxKeyTangents fbx_key_tangents(const std::vector<FbxKey>& keys, std::size_t i) {
  FbxKeyTangents out;
  if (i >= keys.size()) return out;
  const FbxKey& k = keys[i];
  const bool has_prev = i > 0 && keys[i - 1].ticks < k.ticks;
  const bool has_next = i + 1 < keys.size() && keys[i + 1].ticks > k.ticks;
  // The left tangent as the previous key leaves it.
  if (i > 0) {
    const FbxKey& p = keys[i - 1];
    if (p.interpolation == FbxInterpolation::linear) out.left_slope = secant(p, k);
    else if (p.interpolation == FbxInterpolation::cubic && p.tangent != FbxTangent::tcb) {
      out.left_slope = p.next_left_slope;
      if (p.weighted_next_left) out.left_weight = p.next_left_weight;
    }
  }
  switch (k.interpolation) {
    case FbxInterpolation::constant_previous:
    case FbxInterpolation::constant_next: return out;
    case FbxInterpolation::linear:
      if (has_next) out.right_slope = secant(k, keys[i + 1]);
      return out;
    case FbxInterpolation::cubic: break;
  }
  out.right_slope = k.right_slope;
  if (k.weighted_right) out.right_weight = k.right_weight;
  if (k.tangent == FbxTangent::tcb) {
    const double in = has_prev ? secant(keys[i - 1], k) : 0.0, away = has_next ? secant(k, keys[i + 1]) : 0.0;
    const double f = (has_prev && has_next ? 0.5 : 1.0) * (1.0 - k.tension);
    out.left_slope = f * ((1.0 + k.bias) * (1.0 - k.continuity) * in + (1.0 - k.bias) * (1.0 + k.continuity) * away);
    out.right_slope = f * ((1.0 + k.bias) * (1.0 + k.continuity) * in + (1.0 - k.bias) * (1.0 - k.continuity) * away);
    return out;
  }
  if (k.tangent == FbxTangent::user || k.tangent == FbxTangent::broken) return out;
  // Auto, spline, clamped: the stored values are biases.
  const double bias_left = -out.left_slope, bias_right = k.right_slope;
  if (has_prev && has_next) {
    const FbxKey& p = keys[i - 1];
    const FbxKey& n = keys[i + 1];
    if (std::abs(out.left_slope + k.right_slope) <= kSharedBias) {
      out.left_slope = out.right_slope = solve_auto(p, k, n, out.left_weight, out.right_weight, bias_right);
    } else {
      out.left_slope = solve_auto(p, k, n, out.left_weight, out.right_weight, bias_left);
      out.right_slope = solve_auto(p, k, n, out.left_weight, out.right_weight, bias_right);
    }
  } else if (has_prev) {
    out.left_slope = out.right_slope = solve_auto_end(keys[i - 1], k, k, bias_left);
  } else if (has_next) {
    out.left_slope = out.right_slope = solve_auto_end(k, keys[i + 1], k, bias_right);
  } else {
    out.left_slope = out.right_slope = 0.0;
  }
  return out;
}

}  // namespace rotinterp
