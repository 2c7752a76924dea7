// A comparison panel's parts from the rebuild: the method's colour and its trail.
#include "panel_parts.h"

#include "rotinterp/palette/method_style.h"

namespace rotinterp::render {

Colour method_colour(const std::string& method) {
  const auto& rgb = method_style(method_slot(method)).rgb;
  return {rgb[0] / 255.0f, rgb[1] / 255.0f, rgb[2] / 255.0f};
}

std::shared_ptr<Trail> make_trail(const RebuiltClip& rebuild, std::size_t m, int joint, std::size_t first,
                                  std::size_t last, std::string label) {
  const auto j = static_cast<std::size_t>(joint);
  const Vec3& axis = rebuild.bone_axis(j);
  auto t = std::make_shared<Trail>();
  t->label = std::move(label);
  for (std::size_t f = first; f <= last; ++f) {
    t->reference.push_back(rebuild.reference_rotation(j, f) * axis);
    t->method.push_back(rebuild.method_rotation(m, j, f) * axis);
  }
  if (rebuild.animated(j))
    for (std::size_t k : rebuild.keys())
      if (k >= first && k <= last) t->keys.push_back(k - first);
  return t;
}

}  // namespace rotinterp::render
