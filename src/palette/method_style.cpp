// The one method palette (colour, marker, dash), keyed by the registry.
#include "rotinterp/palette/method_style.h"

#include "rotinterp/interp/interpolator.h"

namespace rotinterp {

namespace {

// In registry order (slerp, squad, expmap, nlerp, bf, c2, expmap-c2, clamped, gltf-cubic):
// the pairs compared most (slerp, squad, c2) far apart in hue.
constexpr MethodStyle kStyles[kMethodStyles] = {
    {{86, 180, 233}, "●", "○", 1},   {{213, 94, 0}, "■", "□", 2},     {{204, 121, 167}, "▲", "△", 3},
    {{150, 150, 150}, "◆", "◇", 4},  {{0, 114, 178}, "▼", "▽", 5},    {{0, 158, 115}, "★", "☆", 6},
    {{230, 159, 0}, "✚", "✚", 7},    {{153, 153, 51}, "✖", "✖", 8},   {{204, 102, 119}, "◀", "◁", 1}};

}  // namespace

const MethodStyle& method_style(std::size_t slot) { return kStyles[slot % kMethodStyles]; }

std::size_t method_slot(std::string_view name) {
  const MethodInfo* m = find_method(name);
  return m ? static_cast<std::size_t>(m - methods().data()) : methods().size();
}

}  // namespace rotinterp
