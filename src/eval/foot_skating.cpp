// foot_skating: finding foot contacts and measuring how far a contact foot slides.
#include "rotinterp/eval/foot_skating.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace rotinterp {

namespace {

enum class Side { none, left, right };
// 0: not a foot; 1: foot or ankle; 2: toe or ball (preferred).
struct FootName {
  Side side = Side::none;
  int level = 0;
};

// Reads a joint name as a rig would write it: "mixamorig:LeftToeBase", "foot.L",
// "L_Foot", "RightToes", "toe_r".
FootName classify(const std::string& name) {
  std::string n = name.substr(name.rfind(':') == std::string::npos ? 0 : name.rfind(':') + 1);
  std::string lower;
  for (char c : n) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  FootName f;
  // Leaf markers, hands, and the controls and helpers of animation rigs (Maya's
  // LeftFootCtrl, LeftToeRoll, lf_toe_ik, lf_toe_pivot), which do not move as the foot does.
  for (const char* not_a_foot : {"end", "nub", "index", "thumb", "finger", "ctrl", "control", "ik", "pole", "pivot",
                                 "snap", "roll", "target", "helper", "wiggle", "locator"})
    if (lower.find(not_a_foot) != std::string::npos) return f;
  std::string part;
  if (lower.find("toe") != std::string::npos || lower.find("ball") != std::string::npos)
    f.level = 2, part = lower.find("toe") != std::string::npos ? "toe" : "ball";
  else if (lower.find("foot") != std::string::npos || lower.find("ankle") != std::string::npos)
    f.level = 1, part = lower.find("foot") != std::string::npos ? "foot" : "ankle";
  else
    return f;
  if (lower.find("left") != std::string::npos) {
    f.side = Side::left;
  } else if (lower.find("right") != std::string::npos) {
    f.side = Side::right;
  } else {
    // A lone l or r between separators (l_foot, foot.l, L_FootToe, toes_r), or glued
    // to the front of the part (lfoot, rtoe).
    std::string token;
    for (std::size_t i = 0; i <= lower.size() && f.side == Side::none; ++i) {
      if (i < lower.size() && std::isalpha(static_cast<unsigned char>(lower[i]))) {
        token += lower[i];
        continue;
      }
      if (token == "l") f.side = Side::left;
      if (token == "r") f.side = Side::right;
      token.clear();
    }
    if (f.side == Side::none && lower.size() > part.size() && lower.compare(1, part.size(), part) == 0)
      f.side = lower[0] == 'l' ? Side::left : lower[0] == 'r' ? Side::right : Side::none;
  }
  if (f.side == Side::none) f.level = 0;
  return f;
}

}  // namespace

std::vector<std::size_t> find_feet(const Skeleton& skeleton) {
  // Depth in the joint tree: a foot bone ends a leg chain, while IK targets and
  // controls of the same name (a Marine's L_TOE beside its L_FootToe) hang near the root.
  std::vector<int> depth(skeleton.joints.size(), 0);
  for (std::size_t j = 0; j < skeleton.joints.size(); ++j)
    if (skeleton.joints[j].parent >= 0) depth[j] = depth[static_cast<std::size_t>(skeleton.joints[j].parent)] + 1;
  std::vector<std::size_t> feet;
  for (Side side : {Side::left, Side::right}) {
    int best_level = 0, best_depth = -1;
    std::size_t best = 0;
    for (std::size_t j = 0; j < skeleton.joints.size(); ++j) {
      const FootName f = classify(skeleton.joints[j].name);
      if (f.side != side || f.level == 0) continue;
      if (f.level > best_level || (f.level == best_level && depth[j] > best_depth))
        best_level = f.level, best_depth = depth[j], best = j;
    }
    if (best_level > 0) feet.push_back(best);
  }
  return feet;
}

Result<std::vector<std::size_t>> feet_by_name(const Skeleton& skeleton, const std::vector<std::string>& names) {
  std::vector<std::size_t> feet;
  for (const std::string& n : names) {
    const int j = skeleton.find(n);
    if (j < 0) return make_error("no joint named '" + n + "' for --feet");
    if (std::find(feet.begin(), feet.end(), static_cast<std::size_t>(j)) == feet.end())
      feet.push_back(static_cast<std::size_t>(j));
  }
  return feet;
}

FootContact foot_contact(const Vec3* position, const double* times, std::size_t n, double floor,
                         double metres_per_unit, const FootContactOptions& options) {
  FootContact c;
  const double height = options.contact_height_m / metres_per_unit;  // clip units
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const double dt = times[k + 1] - times[k];
    if (!(dt > 0.0)) continue;
    if (!(position[k].y() - floor < height && position[k + 1].y() - floor < height)) continue;
    const double dx = position[k + 1].x() - position[k].x(), dz = position[k + 1].z() - position[k].z();
    const double speed = std::hypot(dx, dz) / dt * metres_per_unit;
    ++c.contact;
    c.speed_sum += speed;
    if (speed > options.contact_speed_mps) ++c.skating;
  }
  return c;
}

}  // namespace rotinterp
