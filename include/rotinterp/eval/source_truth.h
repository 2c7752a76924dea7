// The file's own motion as the truth of eval (eval --truth source): FBX curves, glTF
// animation samplers, BVH frames (io/source_motion.h).
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"
#include "rotinterp/eval/evaluate_clip.h"

#include <string>

namespace rotinterp {

// Reads `clip_file` again with its own motion (read_file_source; the animation named
// like the clip, else the first) and returns, at any time, each joint's local rotation
// from that motion where the file has it, else the clip's own track (sampled as the
// reference always is); translations are the clip's tracks, or the joints' offsets.
// Errors (one line, naming the file): as read_file_source, or a second read whose
// joints differ from the clip's. `allow_external_files` as ReadOptions'.
Result<TruthFn> source_truth(const std::string& clip_file, const Clip& clip, bool allow_external_files = false);

}  // namespace rotinterp
