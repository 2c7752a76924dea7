// The parts of a comparison panel taken from the rebuild: the method's colour, the
// bone-direction trail and the error strip (private to render/).
#pragma once

#include "rotinterp/clip/rebuild.h"
#include "rotinterp/render/renderer.h"

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace rotinterp::render {

// A method's colour: its registry slot's (palette/method_style.h), as in eval's plots.
Colour method_colour(const std::string& method);

// Method m's trail of `joint`'s bone direction over frames first…last.
std::shared_ptr<Trail> make_trail(const RebuiltClip& rebuild, std::size_t m, int joint, std::size_t first,
                                  std::size_t last, std::string label);

// Each of the first `methods` methods' error at every frame of first…last, with the
// keys among them, on one scale for all: the error that kRobustFraction of the
// frames stay below (spikes above it are clipped at the strip's top).
std::vector<std::shared_ptr<ErrorStrip>> error_strips(const RebuiltClip& rebuild, std::size_t methods,
                                                      std::size_t first, std::size_t last);

}  // namespace rotinterp::render
