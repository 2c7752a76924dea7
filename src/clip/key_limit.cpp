// The keys-per-call limit and its message.
#include "rotinterp/clip/key_limit.h"

#include <cmath>
#include <cstdio>

namespace rotinterp {

bool too_many_keys(double frames, std::size_t joints) {
  return !(frames * static_cast<double>(joints) <= static_cast<double>(kMaxKeys));  // NaN counts as too many
}

std::string too_many_keys_text(double frames, std::size_t joints) {
  char count[64];
  std::snprintf(count, sizeof count, "%.0f", std::floor(frames));
  return std::string(count) + " frames × " + std::to_string(joints) + (joints == 1 ? " joint" : " joints") +
         ", more than " + std::to_string(kMaxKeys) + " keys";
}

}  // namespace rotinterp
