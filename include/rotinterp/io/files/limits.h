// What every reader accepts, in one place (docs/limits.md gives the user's view).
// The rule: a size a file declares (an array's count, a chunk's length, a frame
// count) is checked against the bytes that can hold it before anything is
// allocated for it, and what a compressed array may inflate to is bounded by the
// file's own size, so a few KB of input never ask for gigabytes. Each limit is far
// past real files; past it a file is refused with one line naming it and the field.
#pragma once

#include "rotinterp/core/result.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace rotinterp {

// Joints nested in one chain (ROOT or the scene root is level 1): mocap skeletons nest
// fewer than 50; a deeper chain is a hostile file, and callers walk the tree.
inline constexpr std::size_t kMaxJointDepth = 1000;
// Bytes of one joint name (assimp's own limit too): real names are a few dozen.
inline constexpr std::size_t kMaxNameBytes = 1024;
// FBX node records nested in each other: real files nest fewer than 10; the readers
// recurse, so the depth bounds their stack.
inline constexpr std::size_t kFbxMaxDepth = 64;
// Elements of one FBX array: 2 GiB as doubles, a hundred times a long take's keys.
inline constexpr std::size_t kFbxMaxArrayElements = std::size_t{1} << 28;

// What the compressed arrays of one file may inflate to, all together: this much…
inline constexpr std::uint64_t kInflationFloorBytes = std::uint64_t{64} << 20;
// … plus this many times the file's size. FBX key and mesh arrays deflate 2 to 10
// times; zlib's own ceiling is 1032, which a bomb uses to ask for gigabytes.
inline constexpr std::uint64_t kInflationPerFileByte = 32;

// BVH: the head of a file read first, to check its HIERARCHY before the whole file
// is read (a 3 GB file with garbage on line 2 is refused after 1 MiB).
inline constexpr std::size_t kBvhHeadBytes = std::size_t{1} << 20;

// `count` elements of `element_bytes` each (≥ 1) declared where `bytes_left` bytes
// remain to hold them. Refused ("WHERE: COUNT elements of B bytes cannot fit in the
// L bytes left") when they cannot, or when count passes `max_count`.
Status check_declared_count(std::uint64_t count, std::uint64_t element_bytes, std::uint64_t bytes_left,
                            std::uint64_t max_count, const std::string& where);

// The bytes the compressed arrays of one file may inflate to (see above), taken array
// by array before each is inflated.
class InflationBudget {
 public:
  explicit InflationBudget(std::uint64_t file_bytes);
  // Takes `bytes` from the budget; refused ("WHERE: …") once the file's arrays would
  // pass it together.
  Status take(std::uint64_t bytes, const std::string& where);

 private:
  std::uint64_t left_;
  std::uint64_t limit_;
};

}  // namespace rotinterp
