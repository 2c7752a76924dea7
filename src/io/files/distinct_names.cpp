// DistinctNames (io/files/distinct_names.h).
#include "rotinterp/io/files/distinct_names.h"

namespace rotinterp {

std::string DistinctNames::take(const std::string& name) {
  if (taken_.insert(name).second) return name;
  std::size_t& k = next_suffix_.try_emplace(name, 1).first->second;
  for (;; ++k) {
    std::string candidate = name + (k == 1 ? "#" : "#" + std::to_string(k));
    if (taken_.insert(candidate).second) {
      ++k;
      return candidate;
    }
  }
}

}  // namespace rotinterp
