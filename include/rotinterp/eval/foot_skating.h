// Foot skating: feet sliding while they touch the floor, the artefact motion-synthesis
// papers judge resampled and generated motion by. Time-aware and in real units.
//
// A foot (a joint; the ball or toe where the rig has one, else the ankle) is in
// contact over the frame interval [t_k, t_{k+1}] when its height above the floor is
// below `contact_height_m` at both ends; it skates over that interval when, in
// contact, its horizontal speed |Δ(x, z)| / (t_{k+1} − t_k) is above
// `contact_speed_mps`. Y is up (BVH, and assimp's scenes). The floor is the lowest
// height any foot reaches in the reference over the clip, or `floor_m`. Both
// thresholds are metres and are converted with the clip's metres per unit
// (Clip::unit, clip/units.h). The defaults are those of the widely copied evaluation
// scripts (5 cm, 0.5 m/s), which apply them per frame at a fixed 20 fps; here the
// speed is measured over the clip's own frame times.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp {

// Foot height below which a foot may be in contact, metres.
constexpr double kDefaultContactHeightMetres = 0.05;
// Horizontal foot speed above which a foot in contact skates, metres per second.
constexpr double kDefaultContactSpeedMps = 0.5;

struct FootContactOptions {
  std::vector<std::string> feet;        // joint names; empty: found by name (find_feet)
  double contact_height_m = kDefaultContactHeightMetres;
  double contact_speed_mps = kDefaultContactSpeedMps;
  std::optional<double> floor_m;        // floor height (Y), metres; unset: the lowest foot height
};

// The foot joints of `skeleton`, found by the names of common rigs: CMU (LeftToeBase,
// LeftFoot), Mixamo (mixamorig:LeftToeBase), Bandai Namco (LeftToes, LeftFoot),
// Blender (toe.L, foot.L), and L/R, Left/Right, l_/_l variants. Per side the toe-level
// joint (ToeBase, Toe, Toes, Ball) when there is one, else the foot/ankle, the
// deepest in the joint tree where several match (a bone, not an IK target); never a
// rig's control or helper (…Ctrl, …IK, …Roll, …Pivot, …_end). Empty when no side is
// found (no feet: a box chain, an arm, a rig of controls only).
std::vector<std::size_t> find_feet(const Skeleton& skeleton);

// The joints named in `names`; an error names one that is not in the skeleton.
Result<std::vector<std::size_t>> feet_by_name(const Skeleton& skeleton, const std::vector<std::string>& names);

// One foot over a clip.
struct FootContact {
  std::size_t contact = 0;  // frame intervals in contact
  std::size_t skating = 0;  // of them, sliding faster than the threshold
  double speed_sum = 0.0;   // horizontal speed summed over the contact intervals, m/s
  double mean_speed() const { return contact ? speed_sum / static_cast<double>(contact) : 0.0; }
};

// Contacts of one foot whose world positions (clip units) at times[0..n) are
// `position`; `floor` in clip units. Intervals of zero or negative length are skipped.
FootContact foot_contact(const Vec3* position, const double* times, std::size_t n, double floor,
                         double metres_per_unit, const FootContactOptions& options);

}  // namespace rotinterp
