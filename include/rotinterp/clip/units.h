// Units: how many metres one clip unit is, where that figure came from, and the
// physical quantities options are given in. The one place that knows units: the
// reader settles a clip's unit once (io/read.h), and every writer, metric, option
// and report converts through Clip::unit.metres_per_unit.
//
// Where the figure comes from (UnitOrigin):
//  * declared: the file states it (FBX GlobalSettings UnitScaleFactor, centimetres
//    per unit; glTF is metres by its spec; Collada's <unit>, which assimp applies);
//  * given: the user said it (--unit, read_clip(..., unit=));
//  * inferred: a file that states none (BVH and a few others) whose figure size
//    matches a common unit (infer_unit below);
//  * assumed: no rule applied; the reason says what was assumed.
#pragma once

#include "rotinterp/core/result.h"

#include <string>
#include <string_view>

namespace rotinterp {

struct Clip;

enum class UnitOrigin { declared, given, inferred, assumed };

struct ClipUnit {
  double metres_per_unit = 1.0;  // > 0 and finite
  UnitOrigin origin = UnitOrigin::assumed;
  std::string reason;            // one phrase: "FBX UnitScaleFactor 1", "--unit cm", …
};

// "declared", "given", "inferred" or "assumed".
const char* unit_origin_name(UnitOrigin origin);

// A unit's short name where it is a common one ("m", "cm", "mm", "in", "ft"), else
// the figure in metres ("0.0652 m").
std::string unit_name(double metres_per_unit);
// "cm (inferred from its offsets, a skeleton 184 units tall at rest; --unit to set)".
std::string describe_unit(const ClipUnit& unit);

// A unit as the user writes it (--unit): m, cm, mm, in, ft, or a positive number of
// metres per unit. Returns metres per unit.
Result<double> parse_unit(std::string_view text);

// ---- inference (files that declare no unit) ------------------------------------------

// The figure sizes, in metres, a clip of people is taken to have: the largest side of
// the bounding box of its skeleton at rest (height, or arm span in a T-pose) lies in
// this range in at most one of the common units m, cm, mm, in and ft (each two are
// more than 2.5× apart, so the ranges do not overlap and the choice is never
// ambiguous). The rest pose — offsets and rest rotations — is what a cut of the clip
// keeps, so a clip and any range of its frames get the same unit (CMU 01_01 and its
// frames 100-300 alike); the first pose, which moves with the cut, is used only where
// every offset is zero.
constexpr double kInferMinFigureMetres = 1.0;
constexpr double kInferMaxFigureMetres = 2.5;
// Where no common unit gives such a figure (CMU's BVH, in units of 1/0.45 inch), the
// figure is scaled to this size, and the unit says it was assumed.
constexpr double kAssumedFigureMetres = 1.7;

// The size of the skeleton posed at its first key of every track (first_pose_size,
// End Sites included) or at rest (rest_pose_size, joints only: FBX and glTF keep no
// End Sites, so a BVH and its trip through them measure alike), in clip units: the
// largest side of its bounding box; 0 for a point. Root joints are left out of the
// box when there are other joints (a root can be a ground marker far from the body,
// as Bandai's is).
double first_pose_size(const Clip& clip);
double rest_pose_size(const Clip& clip);
// The unit of a clip whose file states none, from rest_pose_size() (first_pose_size()
// where that is zero); its reason names which and the size.
ClipUnit infer_unit(const Clip& clip);

// The same motion in another unit: every length (joint and End Site offsets,
// translation keys) scaled by old ÷ new metres per unit; the clip's unit becomes
// `metres_per_unit`, given by `reason` (resample --out-unit).
void convert_unit(Clip& clip, double metres_per_unit, const std::string& reason);

// ---- physical quantities in options ----------------------------------------------------

// A length: a number with a unit suffix (m, cm, mm, in, ft), or a bare number in
// metres. Returns metres; refuses negative, zero (unless allow_zero) and non-finite.
Result<double> parse_length(std::string_view text, bool allow_zero = false);
// A signed length (a floor height): as parse_length, any finite value.
Result<double> parse_signed_length(std::string_view text);
// An angle: a number with deg or rad, or a bare number in degrees. Returns degrees; > 0.
Result<double> parse_angle_deg(std::string_view text);
// A speed: m/s, cm/s, mm/s, or a bare number in m/s. Returns m/s; > 0.
Result<double> parse_speed(std::string_view text);

}  // namespace rotinterp
