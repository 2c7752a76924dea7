// The name of the file's own motion and its form, as every command and the renderer
// see it (io/source_motion.h reads it from a file). Below the formats, so that the
// renderer, which only draws a SourceMotion, links no reader.
#pragma once

#include "rotinterp/core/rotation.h"

#include <cstddef>
#include <functional>
#include <string>

namespace rotinterp {

// What --method takes for it; not a method of the registry (interp/interpolator.h):
// it needs the file, not a joint's keys.
inline constexpr const char* kSourceMethodName = "source";
// Whether `name` is kSourceMethodName, ignoring ASCII case.
bool is_source_method(const std::string& name);

// Joint j's local rotation at clip time t (seconds); j indexes the clip's joints.
using SourceMotion = std::function<Quat(std::size_t joint, double t)>;

}  // namespace rotinterp
