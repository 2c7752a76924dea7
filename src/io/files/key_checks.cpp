// The keys' validation pass (io/files/key_checks.h).
#include "rotinterp/io/files/key_checks.h"
#include "rotinterp/io/files/file_errors.h"

#include <cmath>
#include <cstdio>

namespace rotinterp {

namespace {

// Below this length a stored quaternion has no reliable direction (float keys of a
// unit quaternion are 1 within 1e-7).
constexpr double kMinQuaternionLength = 1e-6;

std::string key(std::size_t k) { return "key " + std::to_string(k); }

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

}  // namespace

Result<std::vector<std::size_t>> check_keys(const std::vector<double>& times, const std::vector<double>& values,
                                            std::size_t width, const std::string& where) {
  std::vector<std::size_t> repaired;
  for (std::size_t k = 0; k < times.size(); ++k) {
    if (!std::isfinite(times[k])) return make_error(where + ": " + key(k) + ": its time is not finite", file_error::unreadable);
    for (std::size_t i = 0; i < width; ++i)
      if (!std::isfinite(values[k * width + i]))
        return make_error(where + ": " + key(k) + ": a value is not finite", file_error::unreadable);
    if (k == 0) continue;
    if (times[k] < times[k - 1])
      return make_error(where + ": " + key(k) + ": its time " + number(times[k]) + " is before key " +
                            std::to_string(k - 1) + "'s " + number(times[k - 1]) + " (times must increase)",
                        file_error::unreadable);
    if (times[k] == times[k - 1]) {
      for (std::size_t i = 0; i < width; ++i)
        if (values[k * width + i] != values[(k - 1) * width + i])
          return make_error(where + ": " + key(k) + ": its time " + number(times[k]) + " is key " +
                                std::to_string(k - 1) + "'s, with another value (times must increase)",
                            file_error::unreadable);
      repaired.push_back(k);
    }
  }
  return repaired;
}

std::string repaired_keys_warning(const std::string& where, std::size_t repaired) {
  return where + ": " + std::to_string(repaired) + (repaired == 1 ? " key" : " keys") +
         " at a time already keyed with the same values dropped";
}

Status check_quaternion_keys(const std::vector<double>& values, std::size_t first, std::size_t stride,
                             const std::string& where) {
  for (std::size_t at = first, k = 0; at + 4 <= values.size(); at += stride, ++k) {
    const double length = std::sqrt(values[at] * values[at] + values[at + 1] * values[at + 1] +
                                    values[at + 2] * values[at + 2] + values[at + 3] * values[at + 3]);
    if (!(length > kMinQuaternionLength))
      return make_error(where + ": " + key(k) + ": a rotation of length " + number(length) + " (no direction)",
                        file_error::unreadable);
  }
  return Ok{};
}

}  // namespace rotinterp
