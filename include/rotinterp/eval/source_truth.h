// The FBX file's own curves as the truth of eval (eval --truth source).
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"
#include "rotinterp/eval/evaluate_clip.h"

#include <string>

namespace rotinterp {

// Reads `clip_file` again with its curves (io/fbx_source.h; the take named like
// the clip, else the first) and returns, at any time, each joint's local rotation
// from the curves where its node has rotation curves, else the clip's own track
// (sampled as the reference always is); translations are the clip's tracks, or the
// joints' offsets. Errors (one line, naming the file): as read_source_clip and
// fbx_joint_curves, or a second read whose joints differ from the clip's.
Result<TruthFn> source_truth(const std::string& clip_file, const Clip& clip);

}  // namespace rotinterp
