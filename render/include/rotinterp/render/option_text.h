// The text of render's options as the command line and the Python keywords give
// it: each parser returns the value or one line naming the option and the problem.
#pragma once

#include "rotinterp/core/result.h"
#include "rotinterp/render/comparison.h"

#include <string_view>
#include <utility>

namespace rotinterp::render {

// "START:END:STEP", "START:END" (step 1) or "START" (one frame); END ≥ START, STEP ≥ 1.
Result<FrameRange> parse_frame_range(std::string_view text);
// "WxH", both positive integers (limits are checked by render()).
Result<std::pair<int, int>> parse_size(std::string_view text);
Result<Colouring> parse_colouring(std::string_view name);  // "error" or "method"
Result<CameraMode> parse_camera(std::string_view name);    // "fixed" or "follow"
Result<View> parse_view(std::string_view name);            // "overlay" or "side"
// Options the overlay cannot honour: a colouring (it colours by method) or a trail
// (one method's curve per panel).
Status check_view_options(View view, bool colour_given, bool trail_given);

}  // namespace rotinterp::render
