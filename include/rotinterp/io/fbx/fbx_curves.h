// FBX animation as the file stores it (FBX 7.x AnimationStack/Layer/CurveNode/
// Curve objects, or FBX 6.1 Takes): per node property and channel, every key with its interpolation,
// tangent mode, slopes, weights, velocities and TCB parameters, the curve's pre-
// and post-extrapolation, every take and layer, and the node properties that shape
// a transform. Read from an FbxDocument (io/fbx_nodes.h); evaluated by
// io/fbx_curve_eval.h.
//
// Units: key times in FBX ticks (kFbxTicksPerSecond); values as stored (degrees
// for Lcl Rotation, file units for Lcl Translation); slopes in value per second.
#pragma once

#include "rotinterp/core/result.h"
#include "rotinterp/io/fbx/fbx_nodes.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp {

inline constexpr std::int64_t kFbxTicksPerSecond = 46186158000;

using FbxVec3 = std::array<double, 3>;

// Of the segment that starts at a key.
enum class FbxInterpolation { constant_previous, constant_next, linear, cubic };
// How the DCC made the key's tangents (the stored slopes are what it evaluates).
enum class FbxTangent { none, auto_smooth, spline, clamped, user, broken, tcb };
enum class FbxExtrapolation { constant, repetition, mirror, keep_slope };

const char* fbx_interpolation_name(FbxInterpolation i);  // "constant-previous", …
const char* fbx_tangent_name(FbxTangent t);             // "auto", "spline", …
const char* fbx_extrapolation_name(FbxExtrapolation e);  // "constant", "repetition", …

struct FbxKey {
  std::int64_t ticks = 0;
  double value = 0.0;
  FbxInterpolation interpolation = FbxInterpolation::linear;
  FbxTangent tangent = FbxTangent::none;
  std::uint32_t flags = 0;  // KeyAttrFlags as stored
  // KeyAttrDataFloat's first two values as stored: user and broken keys' right
  // slope and the next key's left slope (value per second); for auto keys the
  // auto biases (RightAuto, NextLeftAuto), the slopes being solved from the keys
  // (fbx_curve_eval.h fbx_key_tangents).
  double right_slope = 0.0, next_left_slope = 0.0;
  // Tangent lengths as fractions of the segment; 1/3 unless weighted.
  bool weighted_right = false, weighted_next_left = false;
  double right_weight = 1.0 / 3.0, next_left_weight = 1.0 / 3.0;
  bool velocity_right = false, velocity_next_left = false;
  double right_velocity = 0.0, next_left_velocity = 0.0;
  // TCB keys: tension, continuity, bias (the first three data values).
  double tension = 0.0, continuity = 0.0, bias = 0.0;
};

struct FbxExtrapolationRule {
  FbxExtrapolation mode = FbxExtrapolation::constant;
  int repetitions = -1;  // -1: without end
};

struct FbxCurve {
  std::string node;      // the model's name
  std::string property;  // "Lcl Rotation", "Lcl Translation", "Lcl Scaling"
  char channel = 'X';    // 'X', 'Y', 'Z'
  std::size_t layer = 0;  // index in the take's layers
  double default_value = 0.0;
  std::vector<FbxKey> keys;  // times strictly increasing
  FbxExtrapolationRule pre, post;
};

enum class FbxBlendMode { additive, override, override_passthrough };
const char* fbx_blend_mode_name(FbxBlendMode b);

struct FbxLayer {
  std::string name;
  double weight = 100.0;  // percent
  // An animated Weight (Maya keys a layer's weight; the static value is the one at
  // the scene's current time): percent at each time. Node: the layer's name,
  // property "Weight", channel ' '.
  std::optional<FbxCurve> weight_curve;
  FbxBlendMode blend = FbxBlendMode::additive;
  bool mute = false, solo = false;
  // 0 by layer: the layer's rotation composes with the result as a rotation
  // (io/fbx_transform.h); 1 by channel: Euler angles add (blend) one by one.
  int rotation_accumulation = 0;
  int scale_accumulation = 0;  // 0 multiply (blend as powers), 1 additive
};

// One animated node property in one layer (an AnimationCurveNode, or a 6.1 take's
// T/R/S channel group): the values its channels take where they have no curve.
struct FbxAnimatedProperty {
  std::string node;
  std::string property;  // "Lcl Translation", "Lcl Rotation", "Lcl Scaling"
  std::size_t layer = 0;
  FbxVec3 defaults{0, 0, 0};
};

// A model's transform properties (Properties70 over its template's defaults; 6.1: Properties60).
struct FbxModel {
  std::string name;
  std::string type;         // "Mesh", "LimbNode", "Null", … (the object's subclass)
  std::int64_t id = 0;
  std::int64_t parent = 0;  // the parent model's id, 0 for the scene root (6.1: ids are 1, 2, … in file order)
  int rotation_order = 0;   // 0 XYZ, 1 XZY, 2 YZX, 3 YXZ, 4 ZXY, 5 ZYX
  int inherit_type = 0;     // 0 RrSs, 1 RSrs, 2 Rrs
  bool rotation_active = false;
  FbxVec3 translation{0, 0, 0}, rotation{0, 0, 0}, scaling{1, 1, 1};
  FbxVec3 pre_rotation{0, 0, 0}, post_rotation{0, 0, 0};
  FbxVec3 rotation_offset{0, 0, 0}, rotation_pivot{0, 0, 0};
  FbxVec3 scaling_offset{0, 0, 0}, scaling_pivot{0, 0, 0};
};

struct FbxTake {
  std::string name;
  std::int64_t start = 0, stop = 0;  // ticks (LocalStart, LocalStop; 6.1: LocalTime)
  std::vector<FbxLayer> layers;      // 6.1: one, "BaseLayer"
  std::vector<FbxCurve> curves;
  std::vector<FbxAnimatedProperty> properties;  // every animated property, curves or not
};

// A take's span in ticks, the one clock every reader places frames on: the stack's
// LocalStart..LocalStop (6.1: LocalTime) where it declares a non-empty one, else its
// keys' first..last (assimp re-bases a take's keys to the same start). Keys outside
// it only shape the curves inside it.
struct FbxTickSpan {
  std::int64_t start = 0, stop = 0;
};
FbxTickSpan fbx_take_span(const FbxTake& take);

struct FbxAnimation {
  std::uint32_t version = 0;  // the file's FBX version (6100, 7500, …)
  std::vector<FbxTake> takes;
  std::vector<FbxModel> models;
  // One warning per curve whose keys the reader repaired (io/files/key_checks.h K3),
  // for the read to pass on. Not part of the curves.
  std::vector<std::string> repairs;
};

// The animation of a parsed FBX file: 7.x objects, or 6.1 Objects/Model
// (Properties60) and Takes, whose keys are a flat list per channel (time, value,
// interpolation letter, then the tangent mode's slopes and weights). Malformed
// animation (key arrays of differing lengths, keys that break the rules of
// io/files/key_checks.h, attribute counts that do not cover the keys, 6.1 key lists
// shorter or longer than their KeyCount) is refused with one line naming the file and
// the curve's node path.
Result<FbxAnimation> read_fbx_animation(const FbxDocument& doc, const std::string& label);

// The file at `path` read whole and through parse_fbx_nodes and read_fbx_animation;
// `label` names it in errors (file_error::unreadable, or cannot_open).
Result<FbxAnimation> read_fbx_curves_file(const std::string& path, const std::string& label);

}  // namespace rotinterp
