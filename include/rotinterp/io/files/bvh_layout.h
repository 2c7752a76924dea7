// The layout of the BVH file a clip was read from: each joint's CHANNELS, the Frame
// Time as written and the rotation channels' own numbers. A clip carries it in its
// file record (io/files/file_record.h), so that the BVH writer gives the same
// channel order, Frame Time text and Euler angles back, and the FBX writer each
// joint's rotation order. The BVH reader (io/bvh/bvh.h) fills it; `rotinterp synth`
// gives its clips their motion's random rotation orders (clip/synth.h).
#pragma once

#include <cctype>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rotinterp {

// BVH channel kinds, as in a CHANNELS line.
enum class Channel : std::uint8_t { Xposition, Yposition, Zposition, Xrotation, Yrotation, Zrotation };

// "Xposition", …
inline const char* channel_name(Channel c) {
  switch (c) {
    case Channel::Xposition: return "Xposition";
    case Channel::Yposition: return "Yposition";
    case Channel::Zposition: return "Zposition";
    case Channel::Xrotation: return "Xrotation";
    case Channel::Yrotation: return "Yrotation";
    case Channel::Zrotation: return "Zrotation";
  }
  return "?";
}

// The numbers a BVH file wrote in its rotation channels (degrees), per joint: frame
// after frame, that joint's rotation channels in file order; frame f was at
// f·frame_time seconds. The same rotation has many Euler triples (θ and θ + 360°,
// the two gimbal branches): the writer gives these back where it writes the file's
// own rotation at one of its frame times, so a round trip keeps its numbers.
// The channel a CHANNELS word names, in any case ("Xrotation", "XROTATION"), as BVH
// readers take it; nullopt for another word.
inline std::optional<Channel> channel_from_name(std::string_view word) {
  for (int i = 0; i < 6; ++i) {
    const auto c = static_cast<Channel>(i);
    const std::string_view name = channel_name(c);
    bool same = word.size() == name.size();
    for (std::size_t k = 0; k < word.size() && same; ++k)
      same = std::tolower(static_cast<unsigned char>(word[k])) == std::tolower(static_cast<unsigned char>(name[k]));
    if (same) return c;
  }
  return std::nullopt;
}

// Rotation or position, and the axis (0 X, 1 Y, 2 Z) of a channel.
inline bool is_rotation(Channel c) { return c == Channel::Xrotation || c == Channel::Yrotation || c == Channel::Zrotation; }
inline int axis_of(Channel c) { return static_cast<int>(c) % 3; }

struct BvhSourceAngles {
  double frame_time = 0.0;
  std::size_t frames = 0;
  std::vector<std::vector<double>> degrees;  // [joint][frame · rotation channels + channel]
};

struct BvhLayout {
  // One entry per joint of the clip (same order): its CHANNELS, in file order;
  // empty for a joint without any.
  std::vector<std::vector<Channel>> channels;
  // The Frame Time exactly as written (e.g. ".0083333"). The BVH writer reuses this
  // text while it still parses to Clip::frame_time; empty if none.
  std::string frame_time_text;
  // The file's own rotation numbers; null for a clip not read from BVH. Shared: the
  // layouts of a clip's resampled copies point to the one table.
  std::shared_ptr<const BvhSourceAngles> source_angles;
  // The source frame that is the clip's frame 0: a cut of frames 100-300 starts at
  // the clip's start, its frame 0 the source's frame 100.
  std::size_t source_first_frame = 0;
};

}  // namespace rotinterp
