// readable_text and written_joint_names (io/files/written_names.h).
#include "rotinterp/io/files/written_names.h"

#include "rotinterp/io/files/distinct_names.h"
#include "rotinterp/io/files/limits.h"

#include <cstdint>

namespace rotinterp {

namespace {

constexpr std::string_view kReplacement = "\xEF\xBF\xBD";  // U+FFFD

// The length of the well-formed UTF-8 sequence at text[i] (RFC 3629: no overlong
// forms, no surrogates, nothing past U+10FFFF), or 0 when there is none.
std::size_t sequence_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<std::uint8_t>(text[k]); };
  const std::uint8_t b0 = byte(i);
  if (b0 < 0x80) return 1;
  std::size_t n = 0;
  std::uint8_t low = 0x80, high = 0xBF;  // the range of the second byte
  if (b0 >= 0xC2 && b0 <= 0xDF) n = 2;
  else if (b0 >= 0xE0 && b0 <= 0xEF) {
    n = 3;
    if (b0 == 0xE0) low = 0xA0;
    if (b0 == 0xED) high = 0x9F;
  } else if (b0 >= 0xF0 && b0 <= 0xF4) {
    n = 4;
    if (b0 == 0xF0) low = 0x90;
    if (b0 == 0xF4) high = 0x8F;
  } else {
    return 0;
  }
  if (i + n > text.size() || byte(i + 1) < low || byte(i + 1) > high) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  return n;
}

bool is_control(std::string_view character) {
  const auto b0 = static_cast<std::uint8_t>(character[0]);
  if (character.size() == 1) return b0 < 0x20 || b0 == 0x7F;
  return character.size() == 2 && b0 == 0xC2 && static_cast<std::uint8_t>(character[1]) < 0xA0;  // C1
}

bool splits_bvh_token(std::string_view character) {
  return character == " " || character == "{" || character == "}";
}

// Rules 1–3; with `max_bytes`, rule 4's cut at a character boundary.
std::string clean(std::string_view text, NameForm form, std::size_t max_bytes) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = sequence_length(text, i);
    std::string_view character = n == 0 ? kReplacement : text.substr(i, n);
    if (n != 0 && (is_control(character) || (form == NameForm::bvh_token && splits_bvh_token(character))))
      character = "_";
    if (out.size() + character.size() > max_bytes) break;
    out += character;
    i += n == 0 ? 1 : n;
  }
  return out;
}

}  // namespace

std::string readable_text(std::string_view text) { return clean(text, NameForm::text, std::string::npos); }

std::vector<std::string> written_joint_names(const Skeleton& skeleton, NameForm form) {
  std::vector<std::string> names;
  names.reserve(skeleton.joints.size());
  DistinctNames taken;
  for (const Joint& joint : skeleton.joints) {
    std::string name = clean(joint.name, form, kMaxNameBytes - kNameSuffixRoom);
    if (name.empty()) name = "_";  // an empty name would read as a missing one
    names.push_back(taken.take(name));
  }
  return names;
}

}  // namespace rotinterp
