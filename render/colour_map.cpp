// colour_map: viridis and the error scale of error-coloured poses.
#include "rotinterp/render/colour_map.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace rotinterp::render {

namespace {

// viridis (Stéfan van der Walt and Nathaniel Smith, 2015; matplotlib's
// _cm_listed.py, _viridis_data, CC0): entries round(k·255/32), k = 0…32, of its
// 256, sRGB. Entry k sits at t = index/255.
struct ControlPoint {
  int index;
  Colour rgb;
};
constexpr ControlPoint kViridis[] = {
    {0, {0.267004f, 0.004874f, 0.329415f}},
    {8, {0.277018f, 0.050344f, 0.375715f}},
    {16, {0.282327f, 0.094955f, 0.417331f}},
    {24, {0.282884f, 0.135920f, 0.453427f}},
    {32, {0.278826f, 0.175490f, 0.483397f}},
    {40, {0.270595f, 0.214069f, 0.507052f}},
    {48, {0.258965f, 0.251537f, 0.524736f}},
    {56, {0.244972f, 0.287675f, 0.537260f}},
    {64, {0.229739f, 0.322361f, 0.545706f}},
    {72, {0.214298f, 0.355619f, 0.551184f}},
    {80, {0.199430f, 0.387607f, 0.554642f}},
    {88, {0.185556f, 0.418570f, 0.556753f}},
    {96, {0.172719f, 0.448791f, 0.557885f}},
    {104, {0.160665f, 0.478540f, 0.558115f}},
    {112, {0.149039f, 0.508051f, 0.557250f}},
    {120, {0.137770f, 0.537492f, 0.554906f}},
    {128, {0.127568f, 0.566949f, 0.550556f}},
    {135, {0.121148f, 0.592739f, 0.544641f}},
    {143, {0.120081f, 0.622161f, 0.534946f}},
    {151, {0.130067f, 0.651384f, 0.521608f}},
    {159, {0.153894f, 0.680203f, 0.504172f}},
    {167, {0.191090f, 0.708366f, 0.482284f}},
    {175, {0.239374f, 0.735588f, 0.455688f}},
    {183, {0.296479f, 0.761561f, 0.424223f}},
    {191, {0.360741f, 0.785964f, 0.387814f}},
    {199, {0.430983f, 0.808473f, 0.346476f}},
    {207, {0.506271f, 0.828786f, 0.300362f}},
    {215, {0.585678f, 0.846661f, 0.249897f}},
    {223, {0.668054f, 0.861999f, 0.196293f}},
    {231, {0.751884f, 0.874951f, 0.143228f}},
    {239, {0.835270f, 0.886029f, 0.102646f}},
    {247, {0.916242f, 0.896091f, 0.100717f}},
    {255, {0.993248f, 0.906157f, 0.143936f}},
};

}  // namespace

Colour viridis(double t) {
  if (!(t > 0.0)) return kViridis[0].rgb;
  if (t >= 1.0) return std::prev(std::end(kViridis))->rgb;
  const double x = t * 255.0;
  std::size_t k = 1;
  while (kViridis[k].index < x) ++k;
  const ControlPoint& a = kViridis[k - 1];
  const ControlPoint& b = kViridis[k];
  const double w = (x - a.index) / (b.index - a.index);
  Colour c;
  for (std::size_t i = 0; i < 3; ++i) c[i] = static_cast<float>(a.rgb[i] + w * (b.rgb[i] - a.rgb[i]));
  return c;
}

double error_scale(double max_error_deg) {
  if (!std::isfinite(max_error_deg) || max_error_deg <= 1.0) return 1.0;
  const double decade = std::pow(10.0, std::floor(std::log10(max_error_deg)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * decade >= max_error_deg * (1.0 - 1e-12)) return std::min(m * decade, 180.0);
  return 180.0;
}

Colour error_colour(double error_deg, double scale_deg) {
  return viridis(scale_deg > 0.0 ? error_deg / scale_deg : 0.0);
}

}  // namespace rotinterp::render
