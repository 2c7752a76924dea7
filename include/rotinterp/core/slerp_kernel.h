// The polynomial slerp: many samples at once, in structure-of-arrays form, with no
// trigonometric call (Eberly, "A Fast and Accurate Algorithm for Computing SLERP",
// 2011). The slerp method samples a track with it (interp/slerp.h).
//
// slerp(a, b, t) = f(1 − t, x)·a + f(t, x)·b, x = cos θ = a·b (b flipped to a's
// hemisphere, so x ∈ [0, 1] and θ ≤ 90°, half the rotation angle), and
//   f(t, x) = sin(tθ)/sin θ = Σᵢ bᵢ(t)·dⁱ,  d = x − 1,  b₀ = t,  bᵢ = bᵢ₋₁·(uᵢt² − vᵢ),
//   uᵢ = 1/(i(2i+1)), vᵢ = i/(2i+1),
// the series cut after N terms. At d = 0 (θ = 0) it is exactly t: no division, no
// small-angle branch. Its terms shrink by about |d|/2 each, so few terms are exact
// for small steps and many are needed near θ = 90°. Each sample takes the fewest
// terms that suit its step (kSlerpTiers), a block of one tier in one loop:
//   4 terms for rotations ≤ 8.1°, 8 terms ≤ 33.7°: exact to round-off there
//     (truncation < 2e-17 rad);
//   16 terms otherwise, the last scaled by kSlerpTailFactor to stand for the tail
//     (Eberly's correction; his single precision takes 8): still ≤ 1e-16 rad up to
//     83°, then 3e-14 at 100°, 6e-12 at 120°, 2.2e-9 at 150°, 2.3e-8 near 180°.
// A sample's value depends on its own a, b, t alone, bit for bit, whatever its block.
//
// Bound: for unit a, b and t ∈ [−0.1, 1.1], the rotation the result stands for is
// within kSlerpKernelMaxError of the exact slerp's (2.3e-8 rad measured, at rotations
// near 180°; tests/core/test_slerp_kernel.cpp), and the result is unit to a few 1e-15.
#pragma once

#include "rotinterp/core/rotation.h"

#include <cmath>
#include <cstddef>

namespace rotinterp {

// The promised bound on the rotation angle between kernel and exact slerp (rad).
inline constexpr double kSlerpKernelMaxError = 1e-7;
// The most terms, and the scale of the last one in that tier: chosen by scanning for
// the smallest largest error over θ ∈ [0°, 90°], t ∈ [−0.1, 1.1] (the tail of a
// series whose ratio nears ½ is about as large again as its last term).
inline constexpr int kSlerpTerms = 16;
inline constexpr double kSlerpTailFactor = 1.92;

// A tier: n terms serve every d = a·b − 1 ≥ min_d (measured; 2e-17 rad truncation).
struct SlerpTier {
  int terms;
  double min_d;
};
inline constexpr SlerpTier kSlerpTiers[] = {{4, -2.5e-3}, {8, -4.3e-2}, {kSlerpTerms, -1.0}};

namespace slerp_kernel_detail {

// uᵢ and vᵢ for i = 1 … kSlerpTerms, computed at compile time.
struct Coefficients {
  double u[kSlerpTerms + 1] = {}, v[kSlerpTerms + 1] = {};
};
constexpr Coefficients make_coefficients() {
  Coefficients c;
  for (int i = 1; i <= kSlerpTerms; ++i) {
    c.u[i] = 1.0 / (i * (2.0 * i + 1.0));
    c.v[i] = i / (2.0 * i + 1.0);
  }
  return c;
}
inline constexpr Coefficients kCoefficients = make_coefficients();

// out[j] for n ≤ kBlock samples whose dots are known, with N terms.
template <int N>
void slerp_block(const double* aw, const double* ax, const double* ay, const double* az, const double* bw,
                 const double* bx, const double* by, const double* bz, const double* dot, const double* t,
                 std::size_t n, double* ow, double* ox, double* oy, double* oz);

}  // namespace slerp_kernel_detail

// f(t, x) = sin(tθ)/sin θ for d = x − 1 ∈ [−1, 0] with N terms, by Horner's rule on
// the nested form t·(1 + d·c₁·(1 + d·c₂·(…))), cᵢ = uᵢt² − vᵢ.
template <int N>
inline double slerp_weight(double t, double d) {
  static_assert(N >= 1 && N <= kSlerpTerms, "the coefficients stop at kSlerpTerms");
  const auto& k = slerp_kernel_detail::kCoefficients;
  const double t2 = t * t;
  double acc = 1.0;
  // Unrolled, so that the loop calling this has no inner loop and vectorizes.
#if defined(__clang__)
#pragma unroll
#elif defined(__GNUC__)
#pragma GCC unroll 16
#endif
  for (int i = N; i >= 1; --i) {
    const double c = i == kSlerpTerms ? kSlerpTailFactor * (k.u[i] * t2 - k.v[i]) : k.u[i] * t2 - k.v[i];
    acc = 1.0 + d * c * acc;
  }
  return t * acc;
}

// n quaternions as four arrays of components.
struct QuatArrays {
  const double *w, *x, *y, *z;
};
struct QuatArraysOut {
  double *w, *x, *y, *z;
};

// out[j] = slerp(a[j], b[j], t[j]) on the shortest arc, for unit a, b and finite t;
// out overlaps no input. At a·b = ±0 (a half turn) b is taken as stored for +0 and
// flipped for −0: the slerp method's keys are aligned (align_pair) before they reach it.
inline void slerp_arrays(QuatArrays a, QuatArrays b, const double* t, std::size_t n, QuatArraysOut out) {
  constexpr std::size_t kBlock = 64;
  constexpr int kTiers = 3;
  double dot[kBlock], r[4][kBlock];
  int tier[kBlock];
  for (std::size_t j0 = 0; j0 < n; j0 += kBlock) {
    const std::size_t m = n - j0 < kBlock ? n - j0 : kBlock;
    const double *aw = a.w + j0, *ax = a.x + j0, *ay = a.y + j0, *az = a.z + j0;
    const double *bw = b.w + j0, *bx = b.x + j0, *by = b.y + j0, *bz = b.z + j0;
    for (std::size_t j = 0; j < m; ++j) dot[j] = aw[j] * bw[j] + ax[j] * bx[j] + ay[j] * by[j] + az[j] * bz[j];
    bool used[kTiers] = {};
    for (std::size_t j = 0; j < m; ++j) {
      const double d = std::abs(dot[j]) - 1.0;  // NaN takes the last tier
      tier[j] = d >= kSlerpTiers[0].min_d ? 0 : d >= kSlerpTiers[1].min_d ? 1 : 2;
      used[tier[j]] = true;
    }
    const bool mixed = int(used[0]) + int(used[1]) + int(used[2]) > 1;
    const double* tj = t + j0;
    double *ow = out.w + j0, *ox = out.x + j0, *oy = out.y + j0, *oz = out.z + j0;
    for (int k = 0; k < kTiers; ++k) {
      if (!used[k]) continue;
      // One tier: straight into out. Several (a rare block): each tier over the whole
      // block, its own samples kept, so that a sample's value depends on its own step
      // alone, bit for bit, whatever block it is in.
      double *rw = mixed ? r[0] : ow, *rx = mixed ? r[1] : ox, *ry = mixed ? r[2] : oy, *rz = mixed ? r[3] : oz;
      using namespace slerp_kernel_detail;
      if (k == 0) slerp_block<kSlerpTiers[0].terms>(aw, ax, ay, az, bw, bx, by, bz, dot, tj, m, rw, rx, ry, rz);
      if (k == 1) slerp_block<kSlerpTiers[1].terms>(aw, ax, ay, az, bw, bx, by, bz, dot, tj, m, rw, rx, ry, rz);
      if (k == 2) slerp_block<kSlerpTiers[2].terms>(aw, ax, ay, az, bw, bx, by, bz, dot, tj, m, rw, rx, ry, rz);
      if (!mixed) continue;
      for (std::size_t j = 0; j < m; ++j)
        if (tier[j] == k) ow[j] = rw[j], ox[j] = rx[j], oy[j] = ry[j], oz[j] = rz[j];
    }
  }
}

template <int N>
inline void slerp_kernel_detail::slerp_block(const double* aw, const double* ax, const double* ay,
                                             const double* az, const double* bw, const double* bx,
                                             const double* by, const double* bz, const double* dot,
                                             const double* t, std::size_t n, double* ow, double* ox,
                                             double* oy, double* oz) {
  // No element is read after another's result is written (out overlaps no input).
  // Said to the compiler, which otherwise gives up on checking fourteen arrays for
  // overlap at run time.
#if defined(__clang__)
#pragma clang loop vectorize(assume_safety)
#elif defined(__GNUC__)
#pragma GCC ivdep
#endif
  for (std::size_t j = 0; j < n; ++j) {
    // The shortest arc. copysign and fabs rather than comparisons, which GCC does
    // not vectorize as selects without -ffast-math (nor fmin, a call).
    const double sign = std::copysign(1.0, dot[j]);
    // d is a few ulps above 0 where rounding puts |a·b| above 1: f stays ≈ t there.
    const double d = std::fabs(dot[j]) - 1.0;
    const double c0 = slerp_weight<N>(1.0 - t[j], d);
    const double c1 = sign * slerp_weight<N>(t[j], d);
    const double rw = c0 * aw[j] + c1 * bw[j], rx = c0 * ax[j] + c1 * bx[j];
    const double ry = c0 * ay[j] + c1 * by[j], rz = c0 * az[j] + c1 * bz[j];
    // ‖r‖² = 1 + e, |e| < 1e-7: one Newton step, 1/‖r‖ ≈ (3 − ‖r‖²)/2, leaves 3e²/8.
    const double s = 0.5 * (3.0 - (rw * rw + rx * rx + ry * ry + rz * rz));
    ow[j] = s * rw;
    ox[j] = s * rx;
    oy[j] = s * ry;
    oz[j] = s * rz;
  }
}

// One sample, the same arithmetic as one lane of slerp_arrays (so a track's single
// and batch evaluations agree).
inline Quat slerp_poly(const Quat& a, const Quat& b, double t) {
  Quat r;
  slerp_arrays({&a.w(), &a.x(), &a.y(), &a.z()}, {&b.w(), &b.x(), &b.y(), &b.z()}, &t, 1,
               {&r.w(), &r.x(), &r.y(), &r.z()});
  return r;
}

}  // namespace rotinterp
