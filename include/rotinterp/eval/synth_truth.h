// Analytic truth for clips written by `rotinterp synth` (eval --truth).
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"
#include "rotinterp/eval/evaluate_clip.h"

#include <string>

namespace rotinterp {

// `rotinterp synth OUT` writes the spec of the motion to OUT.synth. This rebuilds
// that motion (clip/synth_spec.h, read_synth_spec) and returns its exact local
// rotations and translations at any time. Errors (one line, naming the file): no
// spec next to the clip, an unreadable spec, or a motion whose joints (count,
// names, order) differ from the clip's.
Result<TruthFn> synth_truth(const std::string& clip_file, const Clip& clip);

}  // namespace rotinterp
