// What a read gives back: the file's takes, the selected clip, warnings, and (FBX) its
// curves as stored; and the outcome the importer process sends back whole. Plain
// data shared by the readers, the importer and info (io/info.h).
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"
#include "rotinterp/io/fbx/fbx_curves.h"
#include "rotinterp/io/record/character_body.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp {

struct AnimationSummary {
  std::string name;
  double duration = 0.0;          // seconds (assimp's mDuration / ticks per second)
  double ticks_per_second = 0.0;  // as used (kDefaultTicksPerSecond where the file gives 0)
  bool default_rate = false;      // the file gave 0 ticks per second
  std::size_t channels = 0;       // animated nodes
  // The take as read (one clock for every reader): its span starts at `start` in file
  // time (seconds; FBX: LocalStart where declared, else its first key; NaN where the
  // reader cannot see the file's time) and lasts `duration`; `keys` distinct key times
  // lie in it; frames are placed at `frame_rate_hz` (0: none), stated by the file
  // (FBX TimeMode, BVH Frame Time) or inferred from its key times.
  double start = 0.0;
  std::size_t keys = 0;
  double frame_rate_hz = 0.0;
  bool rate_stated = false;
};

// The take's frames: duration × rate + 1 at its rate, else its key count.
std::size_t take_frames(const AnimationSummary& take);
// "stated by the file" or "inferred from its key times" (info's words for rate_stated).
const char* rate_origin_text(bool stated);

struct ClipFileInfo {
  std::string format;  // lower-case extension: "bvh", "fbx", "glb", …
  std::vector<AnimationSummary> animations;
  std::size_t selected = 0;           // index of the animation read into `clip`
  Clip clip;
  std::vector<std::string> warnings;  // as also passed to ReadOptions::on_warning
  std::size_t folded_helpers = 0;     // `$AssimpFbx$` helper nodes folded into bones
  // FBX with ReadOptions::read_curves: the curves as the file stores them, read by
  // our own FBX reader (io/fbx/fbx_curves.h); empty otherwise.
  std::optional<FbxAnimation> curves;
  // With ReadOptions::read_body, from a file assimp reads: the character's body
  // (character_body.h); empty otherwise.
  std::optional<CharacterBody> body;
  // A file without animation, which a read refuses (file_error::no_animation): what it
  // holds ("1 mesh, 2 nodes: RootNode, Cube"), for info; empty otherwise.
  std::string holds;
};

// A whole reading, or the reason there is none (`error`, of `kind`) with what the
// reading found before it: its warnings, and what a file without animation holds
// (info.holds). What the importer sends back (io/process clip_wire.h) and what
// info reads (io/info.h).
struct ReadOutcome {
  ClipFileInfo info;
  std::optional<std::string> error;
  ErrorKind kind = ErrorKind::other;  // of `error`
};

// The outcome's reading, or its error (message and kind).
Result<ClipFileInfo> reading_or_failure(ReadOutcome outcome);

}  // namespace rotinterp
