// The one validation pass for the keys a reader takes from a file: FBX curves (7.x
// and 6.1), glTF samplers, and through them the default (assimp) path, which reads
// those files only after this pass accepted them. BVH keys are frames at k·Frame Time
// (increasing by construction) whose values its parser checks as it reads them.
// docs/limits.md states the rules for users. Refusals are one line, "WHERE: key K: …".
//
// Rules, over keys k = 0, 1, … with a time and `width` values each:
//  K1. every time is finite;
//  K2. times never go back (a time before the one of the key before is refused);
//  K3. a time equal to the key before's is repaired where the key repeats that key's
//      values exactly (the later one dropped: it changes no curve), refused otherwise
//      (two values at one time: no curve passes through both);
//  K4. every value is finite;
//  K5. (check_quaternion_keys) a rotation key has a length: a zero quaternion has no
//      direction, and normalizing it would make up the identity.
#pragma once

#include "rotinterp/core/result.h"

#include <cstddef>
#include <string>
#include <vector>

namespace rotinterp {

// Checks K1–K4 over `times` (any unit) and `values` (times.size() × width, key by key).
// Returns the keys K3 repairs (to drop), in increasing order.
Result<std::vector<std::size_t>> check_keys(const std::vector<double>& times, const std::vector<double>& values,
                                            std::size_t width, const std::string& where);

// Drops the keys `repaired` names (increasing) from `items`, `per_key` items a key.
template <class T>
void drop_keys(std::vector<T>& items, const std::vector<std::size_t>& repaired, std::size_t per_key) {
  if (repaired.empty()) return;
  std::size_t out = 0, r = 0;
  for (std::size_t k = 0; k * per_key < items.size(); ++k) {
    if (r < repaired.size() && repaired[r] == k) {
      ++r;
      continue;
    }
    for (std::size_t i = 0; i < per_key; ++i) items[out++] = std::move(items[k * per_key + i]);
  }
  items.resize(out);
}

// "WHERE: N keys at a time already keyed with the same values dropped": the warning of
// a K3 repair.
std::string repaired_keys_warning(const std::string& where, std::size_t repaired);

// K5 over `keys` quaternions, stored from `first` with `stride` numbers between keys
// (4 components each, in any order): refused where one has length ≤ 1e-6.
Status check_quaternion_keys(const std::vector<double>& values, std::size_t first, std::size_t stride,
                             const std::string& where);

}  // namespace rotinterp
