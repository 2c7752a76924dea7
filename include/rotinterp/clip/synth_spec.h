// A synthetic clip's spec: one line of its options that rebuilds its motion exactly
// (clip/synth.h), and the file `rotinterp synth` writes it to next to the clip.
#pragma once

#include "rotinterp/clip/synth.h"
#include "rotinterp/clip/synth_motion.h"
#include "rotinterp/core/result.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace rotinterp {

// One line that reproduces the options: "kind=walk seconds=4 fps=30 seed=1 joints=31".
std::string synth_spec(const SynthOptions& options);
// Parses synth_spec()'s output (keys in any order, missing keys at their defaults).
Result<SynthOptions> parse_synth_spec(std::string_view spec);

// The spec file `rotinterp synth` writes next to a clip: "<clip_file>.synth".
std::filesystem::path synth_spec_path(const std::filesystem::path& clip_file);
// Rebuilds the analytic motion of a clip file from its spec file (for eval --truth):
// an error naming the file when there is none or it does not parse. The motion's
// truth(t, rotation, translation) gives the exact local pose at any t.
Result<SynthMotion> read_synth_spec(const std::filesystem::path& clip_file);

}  // namespace rotinterp
