// The parts of a comparison panel taken from the rebuild: the method's colour, the
// bone-direction trail (private to render/).
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

}  // namespace rotinterp::render
