// Fast fixed-point text with 6 decimals for the BVH writer (internal header).
#pragma once

#include <charconv>
#include <cmath>

namespace rotinterp {

// `v` with 6 decimals, exactly as std::to_chars(fixed, 6) prints it (correctly
// rounded), but without its arbitrary-precision path for the common case: for
// |v| < 10⁶ the product v·10⁶ is off the exact one by at most |v·10⁶|·2⁻⁵³ < 1.2·10⁻⁴,
// so when it is more than 10⁻³ away from a tie (k + 0.5) its nearest whole number is
// the correctly rounded value of v in millionths. `end` − `buf` ≥ 320 holds any
// finite double (DBL_MAX has 309 digits before the point).
constexpr int kFixed6MaxChars = 320;

inline char* write_fixed6(char* buf, char* end, double v) {
  const double x = v * 1e6;
  if (std::abs(x) < 1e12) {
    const double r = std::nearbyint(x);
    if (std::abs(std::abs(x - r) - 0.5) > 1e-3 && (r != 0.0 || (v == 0.0 && !std::signbit(v)))) {
      long long m = static_cast<long long>(r);
      char* p = buf;
      if (m < 0) *p++ = '-', m = -m;
      char digits[24];
      int n = 0;
      for (; m > 0 || n < 7; m /= 10) digits[n++] = static_cast<char>('0' + m % 10);
      while (n > 6) *p++ = digits[--n];
      *p++ = '.';
      while (n > 0) *p++ = digits[--n];
      return p;
    }
  }
  return std::to_chars(buf, end, v, std::chars_format::fixed, 6).ptr;
}

}  // namespace rotinterp
