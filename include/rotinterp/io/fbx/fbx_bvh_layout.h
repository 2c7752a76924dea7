// A BVH channel layout kept through FBX: each joint's CHANNELS line as a user property
// of its Model ("rotinterp_bvh_channels", a KString such as "Xposition Yposition
// Zposition Zrotation Xrotation Yrotation"). FBX has no channels, only curves; with
// it, BVH → FBX → BVH writes the source's channels again (assimp hands the property
// on as node metadata; Blender 3.4 imports the file alike and skips it).
#pragma once

#include "rotinterp/io/files/bvh_layout.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rotinterp {

inline constexpr const char* kBvhChannelsProperty = "rotinterp_bvh_channels";

// "Xposition Yposition …": the CHANNELS line's names.
inline std::string bvh_channels_text(const std::vector<Channel>& channels) {
  std::string out;
  for (Channel c : channels) out += (out.empty() ? "" : " ") + std::string(channel_name(c));
  return out;
}

// The channels of bvh_channels_text's text; nullopt for any other word (a property of
// that name written by someone else is ignored, not trusted).
inline std::optional<std::vector<Channel>> parse_bvh_channels_text(std::string_view text) {
  std::vector<Channel> out;
  while (!text.empty()) {
    const std::size_t space = text.find(' ');
    const std::optional<Channel> c = channel_from_name(text.substr(0, space));
    if (!c || out.size() == 6) return std::nullopt;
    out.push_back(*c);
    text = space == std::string_view::npos ? std::string_view() : text.substr(space + 1);
  }
  return out;
}

}  // namespace rotinterp
