// A comparison panel's parts from the rebuild: the method's colour, its trail and its error strip.
#include "panel_parts.h"

#include "views.h"

#include "rotinterp/palette/method_style.h"
#include "rotinterp/render/colour_map.h"

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

std::vector<std::shared_ptr<ErrorStrip>> error_strips(const RebuiltClip& rebuild, std::size_t methods,
                                                      std::size_t first, std::size_t last) {
  std::vector<std::shared_ptr<ErrorStrip>> strips(methods);
  std::vector<std::size_t> strip_keys;
  for (std::size_t k : rebuild.keys())
    if (k >= first && k <= last) strip_keys.push_back(k - first);
  std::vector<Quat> local;
  std::vector<double> maxima;
  for (std::size_t m = 0; m < methods; ++m) {
    auto strip = std::make_shared<ErrorStrip>();
    for (std::size_t f = first; f <= last; ++f) {
      const FrameError e = rebuild.method_rotations(m, f, local);
      strip->max_deg.push_back(static_cast<float>(e.max));
      strip->mean_deg.push_back(static_cast<float>(e.mean));
      maxima.push_back(e.max);
    }
    strip->keys = strip_keys;
    strips[m] = std::move(strip);
  }
  for (auto& strip : strips) strip->scale_deg = error_scale(quantile(maxima, kRobustFraction));
  return strips;
}

}  // namespace rotinterp::render
