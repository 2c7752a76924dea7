// The layout of the BVH file a clip was read from: each joint's CHANNELS and the
// Frame Time as written. A Clip carries it (Clip::bvh_layout) without looking
// inside, so that the BVH writer gives the same channel order and Frame Time text
// back, and the FBX writer each joint's rotation order. The BVH reader (io/bvh.h)
// fills it; synthetic clips (clip/synth.h) get a random one.
#pragma once

#include "rotinterp/clip/clip.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
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

struct BvhLayout {
  // One entry per joint of the clip (same order): its CHANNELS, in file order;
  // empty for a joint without any.
  std::vector<std::vector<Channel>> channels;
  // The Frame Time exactly as written (e.g. ".0083333"). The BVH writer reuses this
  // text while it still parses to Clip::frame_time; empty if none.
  std::string frame_time_text;
};

// Joint `joint`'s channels in the clip's layout; empty when it has none (a clip
// that is not from BVH, or a joint without CHANNELS).
inline const std::vector<Channel>& bvh_channels(const Clip& clip, std::size_t joint) {
  static const std::vector<Channel> none;
  const BvhLayout* layout = clip.bvh_layout.get();
  return layout && joint < layout->channels.size() ? layout->channels[joint] : none;
}

// The clip's Frame Time as written in its BVH file; empty when there is none.
inline const std::string& frame_time_text(const Clip& clip) {
  static const std::string none;
  return clip.bvh_layout ? clip.bvh_layout->frame_time_text : none;
}

// `layout` without its Frame Time text, for a clip whose frame time changed; null
// stays null.
inline std::shared_ptr<const BvhLayout> without_frame_time_text(const std::shared_ptr<const BvhLayout>& layout) {
  if (!layout || layout->frame_time_text.empty()) return layout;
  auto out = std::make_shared<BvhLayout>(*layout);
  out->frame_time_text.clear();
  return out;
}

}  // namespace rotinterp
