// Exact rates: parsing, recognizing the rate behind a frame time, sample counts and time grids.
#include "rotinterp/clip/sampling.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <numeric>

namespace rotinterp {

namespace {

using i128 = __int128;

constexpr std::int64_t kMaxRateHz = 1000000000;  // 1e9 Hz: anything above is a typo
constexpr int kMaxDecimals = 12;
constexpr std::int64_t kMaxIntegerRate = 100000;  // frame times recognized as 1/n up to this n

std::int64_t pow10(int d) {
  std::int64_t p = 1;
  for (int i = 0; i < d; ++i) p *= 10;
  return p;
}

// A decimal "123", "12.5", ".5", "7." as num/10^decimals. Only digits and one dot.
bool parse_decimal(std::string_view s, std::int64_t& num, std::int64_t& den) {
  std::int64_t n = 0;
  int decimals = 0, significant = 0, digits = 0;
  bool dot = false;
  for (char c : s) {
    if (c == '.') {
      if (dot) return false;
      dot = true;
      continue;
    }
    if (c < '0' || c > '9') return false;
    ++digits;
    if (dot) ++decimals;
    if (n == 0 && c == '0') continue;  // leading zeros are not significant
    if (++significant > 17) return false;
    n = n * 10 + (c - '0');
  }
  if (digits == 0 || decimals > kMaxDecimals) return false;
  num = n;
  den = pow10(decimals);
  return true;
}

bool reduce_fits(i128 num, i128 den, Rate& out) {
  if (num <= 0 || den <= 0) return false;
  i128 a = num, b = den;
  while (b != 0) {
    const i128 r = a % b;
    a = b;
    b = r;
  }
  num /= a;
  den /= a;
  if (num > std::numeric_limits<std::int64_t>::max() || den > std::numeric_limits<std::int64_t>::max()) return false;
  out = Rate{static_cast<std::int64_t>(num), static_cast<std::int64_t>(den)};
  return true;
}

// Best rational approximation of x with denominator ≤ max_den (continued fractions).
Rate approximate(double x, std::int64_t max_den) {
  std::int64_t h0 = 0, h1 = 1, k0 = 1, k1 = 0;
  double f = x;
  for (int i = 0; i < 64; ++i) {
    const double a = std::floor(f);
    if (a > 1e15) break;
    const auto ai = static_cast<std::int64_t>(a);
    const std::int64_t h2 = ai * h1 + h0, k2 = ai * k1 + k0;
    if (k2 > max_den) break;
    h0 = h1; h1 = h2; k0 = k1; k1 = k2;
    const double frac = f - a;
    if (frac < 1e-12) break;
    f = 1.0 / frac;
  }
  Rate r;
  if (!reduce_fits(h1, k1, r)) return Rate{1, 1};
  return r;
}

}  // namespace

double Rate::time_of(std::int64_t k) const {
  const i128 p = static_cast<i128>(k) * den;
  constexpr i128 kExact = static_cast<i128>(1) << 53;
  if (p < kExact && p > -kExact && num < (static_cast<std::int64_t>(1) << 53))
    return static_cast<double>(static_cast<std::int64_t>(p)) / static_cast<double>(num);
  return static_cast<double>(static_cast<long double>(p) / static_cast<long double>(num));
}

std::string Rate::to_string() const {
  if (den == 1) return std::to_string(num);
  // A denominator dividing 10^d prints as a short decimal: 2997/50 → "59.94".
  for (int d = 1; d <= kMaxDecimals; ++d) {
    const std::int64_t p = pow10(d);
    if (p % den != 0) continue;
    const i128 scaled = static_cast<i128>(num) * (p / den);  // den | p; up to 1e9 Hz · 1e12
    std::string frac = std::to_string(static_cast<std::int64_t>(scaled % p));
    frac.insert(0, static_cast<std::size_t>(d) - frac.size(), '0');
    return std::to_string(static_cast<std::int64_t>(scaled / p)) + "." + frac;
  }
  return std::to_string(num) + "/" + std::to_string(den);
}

Result<Rate> make_rate(std::int64_t num, std::int64_t den) {
  Rate r;
  if (num <= 0 || den <= 0 || !reduce_fits(num, den, r))
    return make_error("rate " + std::to_string(num) + "/" + std::to_string(den) + " is not positive");
  return r;
}

Result<Rate> parse_rate(std::string_view text) {
  const std::string quoted = "'" + std::string(text) + "'";
  std::int64_t an = 0, ad = 1, bn = 1, bd = 1;
  const std::size_t slash = text.find('/');
  const bool ok = slash == std::string_view::npos
                      ? parse_decimal(text, an, ad)
                      : parse_decimal(text.substr(0, slash), an, ad) && parse_decimal(text.substr(slash + 1), bn, bd);
  if (!ok) return make_error("frame rate " + quoted + " is not a number (use e.g. 30, 59.94 or 30000/1001)");
  if (an == 0 || bn == 0) return make_error("frame rate " + quoted + " must be greater than 0");
  Rate r;
  // (an/ad) / (bn/bd) = an·bd / (ad·bn)
  if (!reduce_fits(static_cast<i128>(an) * bd, static_cast<i128>(ad) * bn, r) || r.hz() > kMaxRateHz)
    return make_error("frame rate " + quoted + " is out of range (at most 1e9 Hz)");
  return r;
}

std::optional<Rate> recognize_rate(double hz, double relative_tolerance) {
  if (!std::isfinite(hz) || hz <= 0.0) return std::nullopt;
  const double n = std::round(hz);
  if (n >= 1.0 && n <= static_cast<double>(kMaxIntegerRate) && std::abs(hz - n) <= relative_tolerance * hz)
    return Rate{static_cast<std::int64_t>(n), 1};
  const double m = std::round(hz * 1.001);
  if (m >= 1.0 && m <= static_cast<double>(kMaxIntegerRate) && std::abs(hz - m * 1000.0 / 1001.0) <= relative_tolerance * hz) {
    Rate r;
    if (reduce_fits(static_cast<i128>(m) * 1000, 1001, r)) return r;
  }
  return std::nullopt;
}

Result<Rate> rate_from_frame_time(double frame_time) {
  if (!std::isfinite(frame_time) || frame_time <= 0.0)
    return make_error("frame time " + std::to_string(frame_time) + " is not a positive number");
  // Shortest fixed-notation decimal that reads back as frame_time.
  char buf[400];
  const auto res = std::to_chars(buf, buf + sizeof buf, frame_time, std::chars_format::fixed);
  const std::string_view printed(buf, static_cast<std::size_t>(res.ptr - buf));
  const std::size_t dot = printed.find('.');
  const int decimals = dot == std::string_view::npos ? 0 : static_cast<int>(printed.size() - dot - 1);
  // Half a unit in the last printed place, plus round-off of the comparisons.
  const double tol = 0.5 * std::pow(10.0, -decimals) * (1.0 + 1e-9) + 8.0 * std::numeric_limits<double>::epsilon() * frame_time;
  const double hz = 1.0 / frame_time;

  // (1) integer rates: the nearest n and its neighbours.
  {
    const double n0 = std::floor(hz);
    for (double n : {n0, n0 + 1.0, n0 - 1.0})
      if (n >= 1.0 && n <= static_cast<double>(kMaxIntegerRate) && std::abs(1.0 / n - frame_time) <= tol)
        return Rate{static_cast<std::int64_t>(n), 1};
  }
  // (2) NTSC rates n·1000/1001.
  {
    const double n0 = std::floor(hz * 1.001);
    for (double n : {n0, n0 + 1.0, n0 - 1.0})
      if (n >= 1.0 && n <= static_cast<double>(kMaxIntegerRate) && std::abs(1001.0 / (1000.0 * n) - frame_time) <= tol) {
        Rate r;
        if (reduce_fits(static_cast<i128>(n) * 1000, 1001, r)) return r;
      }
  }
  // (3) the printed decimal itself.
  if (decimals <= kMaxDecimals) {
    std::int64_t num = 0, den = 1;
    if (parse_decimal(printed, num, den) && num > 0) {
      Rate r;
      if (reduce_fits(den, num, r)) return r;  // rate = 1/period
    }
  }
  // A computed (not printed) value: a known rate within float precision, else the
  // simplest nearby rational.
  if (const std::optional<Rate> r = recognize_rate(hz, kComputedRateTolerance)) return *r;
  return approximate(hz, 1000000);
}

std::size_t sample_count(double duration, const Rate& rate) {
  if (!std::isfinite(duration) || duration < 0.0) return 0;
  const long double x = static_cast<long double>(duration) * rate.num / rate.den + 1e-9L;
  if (!(x < 1e18L)) return static_cast<std::size_t>(1e18);  // callers refuse such sizes
  return static_cast<std::size_t>(std::floor(x)) + 1;
}

std::size_t sample_count(std::size_t frames, const Rate& source, const Rate& target) {
  if (frames == 0) return 0;
  const i128 n = static_cast<i128>(frames - 1) * target.num * source.den;
  const i128 d = static_cast<i128>(target.den) * source.num;
  return static_cast<std::size_t>(n / d) + 1;
}

double TimeGrid::time(std::size_t k) const {
  const double rel = rate.time_of(static_cast<std::int64_t>(k));
  const double t = offset == 0.0 ? start + rel : start + (offset + rel);
  return std::min(t, end);
}

std::vector<double> TimeGrid::times() const {
  std::vector<double> out(count);
  for (std::size_t k = 0; k < count; ++k) out[k] = time(k);
  return out;
}

}  // namespace rotinterp
