// Units: the unit names, the inference for files that state none, and the parsers of
// physical quantities in options.
#include "rotinterp/clip/units.h"

#include "rotinterp/clip/clip.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

namespace rotinterp {

namespace {

struct NamedUnit {
  const char* name;
  double metres;
};
// The common units, largest first; lengths in options take the same names.
constexpr NamedUnit kUnits[] = {{"ft", 0.3048}, {"m", 1.0}, {"in", 0.0254}, {"cm", 0.01}, {"mm", 0.001}};

// `text` split into a finite number and the rest ("3cm" → 3, "cm"; "0.5 deg" → 0.5,
// "deg"). False when it does not start with a number.
bool split_quantity(std::string_view text, double& value, std::string& suffix) {
  const std::string s(text);
  if (s.empty() || std::isspace(static_cast<unsigned char>(s[0]))) return false;
  errno = 0;
  char* end = nullptr;
  value = std::strtod(s.c_str(), &end);
  if (end == s.c_str() || !std::isfinite(value)) return false;
  std::size_t i = static_cast<std::size_t>(end - s.c_str());
  while (i < s.size() && s[i] == ' ') ++i;
  suffix = s.substr(i);
  return true;
}

std::string quoted(std::string_view text) { return "'" + std::string(text) + "'"; }

std::string short_number(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

}  // namespace

const char* unit_origin_name(UnitOrigin origin) {
  switch (origin) {
    case UnitOrigin::declared: return "declared";
    case UnitOrigin::given: return "given";
    case UnitOrigin::inferred: return "inferred";
    case UnitOrigin::assumed: break;
  }
  return "assumed";
}

std::string unit_name(double metres_per_unit) {
  for (const NamedUnit& u : kUnits)
    if (std::abs(metres_per_unit - u.metres) <= 1e-12 * u.metres) return u.name;
  return short_number(metres_per_unit) + " m";
}

std::string describe_unit(const ClipUnit& unit) {
  return unit_name(unit.metres_per_unit) + " (" + unit.reason + ")";
}

Result<double> parse_unit(std::string_view text) {
  for (const NamedUnit& u : kUnits)
    if (text == u.name) return u.metres;
  double v = 0.0;
  std::string rest;
  if (!split_quantity(text, v, rest) || !rest.empty() || !(v > 0.0))
    return make_error("unit " + quoted(text) + " is not m, cm, mm, in, ft or a positive number of metres per unit");
  return v;
}

namespace {

// The largest side of the box around the skeleton posed with rotations r and local
// translations t, End Sites included where `end_sites` says. Roots are left out where the skeleton has more:
// a root can be a ground marker far from the body (Bandai's, whose pelvis carries the
// world position); a root that is the hips lies inside the body's box anyway.
double posed_size(const Clip& clip, const std::vector<Quat>& r, const std::vector<Vec3>& t, bool end_sites) {
  WorldPose pose;
  forward_kinematics(clip.skeleton, r, t, pose);
  if (!end_sites) pose.end_site_position.clear();
  if (pose.position.size() > 1) {
    std::vector<Vec3> body;
    for (std::size_t j = 0; j < pose.position.size(); ++j)
      if (clip.skeleton.joints[j].parent >= 0) body.push_back(pose.position[j]);
    if (!body.empty()) pose.position = std::move(body);
  }
  return skeleton_height(pose);
}

bool usable_size(double size) { return size > 0.0 && std::isfinite(size); }

}  // namespace

double first_pose_size(const Clip& clip) {
  const std::size_t n = clip.skeleton.joints.size();
  std::vector<Quat> r(n);
  std::vector<Vec3> t(n);
  for (std::size_t j = 0; j < n; ++j) {
    r[j] = j < clip.rotations.size() && !clip.rotations[j].keys.empty() ? clip.rotations[j].keys.front()
                                                                         : clip.skeleton.joints[j].rest_rotation;
    const bool moves = j < clip.translations.size() && clip.translations[j] && !clip.translations[j]->keys.empty();
    t[j] = moves ? clip.translations[j]->keys.front() : clip.skeleton.joints[j].offset;
  }
  return posed_size(clip, r, t, true);
}

double rest_pose_size(const Clip& clip) {
  std::vector<Quat> r;
  std::vector<Vec3> t;
  for (const Joint& j : clip.skeleton.joints) {
    r.push_back(j.rest_rotation);
    t.push_back(j.offset);
  }
  return posed_size(clip, r, t, false);
}

ClipUnit infer_unit(const Clip& clip) {
  double size = rest_pose_size(clip);
  // Where the size came from, and what it is: "its offsets" + "a skeleton 184 units tall at rest".
  std::string from = "its offsets", figure = "a skeleton " + short_number(size) + " units tall at rest";
  if (!usable_size(size)) {  // every offset zero: the motion alone places the joints
    size = first_pose_size(clip);
    from = "its first pose";
    figure = "a figure " + short_number(size) + " units tall";
  }
  ClipUnit out;
  if (!usable_size(size)) {
    out.reason = "assumed: neither its offsets nor its first pose have a size; --unit to set";
    return out;
  }
  for (const NamedUnit& u : kUnits) {
    const double metres = size * u.metres;
    if (metres >= kInferMinFigureMetres && metres <= kInferMaxFigureMetres) {
      out.metres_per_unit = u.metres;
      out.origin = UnitOrigin::inferred;
      out.reason = "inferred from " + from + ", " + figure + "; --unit to set";
      return out;
    }
  }
  out.metres_per_unit = kAssumedFigureMetres / size;
  out.reason = "assumed: measured on " + from + ", " + figure + " is 1-2.5 m in no common unit, so it is scaled to " +
               short_number(kAssumedFigureMetres) + " m; --unit to set";
  return out;
}

void convert_unit(Clip& clip, double metres_per_unit, const std::string& reason) {
  const double k = clip.unit.metres_per_unit / metres_per_unit;
  for (Joint& j : clip.skeleton.joints) j.offset *= k;
  for (EndSite& e : clip.skeleton.end_sites) e.offset *= k;
  for (std::optional<TranslationTrack>& t : clip.translations)
    if (t)
      for (Vec3& v : t->keys) v *= k;
  clip.unit = {metres_per_unit, UnitOrigin::given, "given: " + reason};
}

// ---- quantities ----------------------------------------------------------------------

Result<double> parse_length(std::string_view text, bool allow_zero) {
  auto v = parse_signed_length(text);
  if (!v) return v;
  if (*v < 0.0 || (*v == 0.0 && !allow_zero))
    return make_error("length " + quoted(text) + (allow_zero ? " must not be negative" : " must be greater than 0"));
  return v;
}

Result<double> parse_signed_length(std::string_view text) {
  double v = 0.0;
  std::string suffix;
  if (split_quantity(text, v, suffix)) {
    if (suffix.empty()) return v;
    for (const NamedUnit& u : kUnits)
      if (suffix == u.name) return v * u.metres;
  }
  return make_error("length " + quoted(text) + " is not a number with m, cm, mm, in or ft (a bare number is metres)");
}

Result<double> parse_angle_deg(std::string_view text) {
  double v = 0.0;
  std::string suffix;
  if (!split_quantity(text, v, suffix) || !(suffix.empty() || suffix == "deg" || suffix == "rad"))
    return make_error("angle " + quoted(text) + " is not a number with deg or rad (a bare number is degrees)");
  if (suffix == "rad") v *= 180.0 / M_PI;
  if (!(v > 0.0)) return make_error("angle " + quoted(text) + " must be greater than 0");
  return v;
}

Result<double> parse_speed(std::string_view text) {
  double v = 0.0;
  std::string suffix;
  if (split_quantity(text, v, suffix)) {
    double scale = 0.0;
    if (suffix.empty() || suffix == "m/s") scale = 1.0;
    if (suffix == "cm/s") scale = 0.01;
    if (suffix == "mm/s") scale = 0.001;
    if (scale > 0.0) {
      if (!(v > 0.0)) return make_error("speed " + quoted(text) + " must be greater than 0");
      return v * scale;
    }
  }
  return make_error("speed " + quoted(text) + " is not a number with m/s, cm/s or mm/s (a bare number is m/s)");
}

}  // namespace rotinterp
