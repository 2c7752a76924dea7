// Joint names as every writer writes them (issue 47, class 4). A clip's names are
// unique and non-empty but may hold any bytes; what is written must read back with
// our own readers, so each writer takes its names from here, never from the clip:
//   1. valid UTF-8: a byte that starts no well-formed sequence becomes U+FFFD (�);
//   2. no control characters: C0 (NUL, \t, \n, \r, \f, \v, …), DEL and C1 become '_';
//   3. NameForm::bvh_token also has no space, '{' or '}' ('_' each): the BVH
//      hierarchy is split on whitespace and braces;
//   4. at most kMaxNameBytes − kNameSuffixRoom bytes (1000), cut at a character
//      boundary, so that with rule 5's suffix it stays within every reader's limit;
//   5. unique: a name already written becomes name#, name#2, … (DistinctNames, linear).
// A name that needs none of this is written as it is.
#pragma once

#include "rotinterp/clip/clip.h"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace rotinterp {

enum class NameForm {
  text,       // FBX, glTF, Collada, JSON: the format quotes its strings
  bvh_token,  // BVH: one whitespace-free token
};

// Bytes kept free below kMaxNameBytes for rule 5's "#" and its digits.
inline constexpr std::size_t kNameSuffixRoom = 24;

// Rules 1 and 2 on any text a writer prints (a take's name, a file's name in JSON).
std::string readable_text(std::string_view text);

// The skeleton's joint names under rules 1–5, in joint order.
std::vector<std::string> written_joint_names(const Skeleton& skeleton, NameForm form);

}  // namespace rotinterp
