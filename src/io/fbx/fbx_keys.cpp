// read_fbx_curve_keys: one AnimationCurve's keys from its KeyTime, KeyValueFloat and
// KeyAttr arrays (flags, slopes, weights, velocities, TCB), checked by the shared
// pass (io/files/key_checks.h), and its extrapolation.
#include "fbx_keys.h"

#include "rotinterp/io/files/key_checks.h"

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace rotinterp {

namespace {

// KeyAttrFlags bits (the FBX SDK's FbxAnimCurveDef).
constexpr std::uint32_t kConstant = 0x2, kLinear = 0x4, kCubic = 0x8;
constexpr std::uint32_t kConstantNext = 0x100;  // with kConstant
constexpr std::uint32_t kTangentAuto = 0x100, kTangentTcb = 0x200, kTangentUser = 0x400, kTangentBreak = 0x800;
constexpr std::uint32_t kTangentClamp = 0x1000, kTangentTimeIndependent = 0x2000;
constexpr std::uint32_t kWeightedRight = 0x1000000, kWeightedNextLeft = 0x2000000;
constexpr std::uint32_t kVelocityRight = 0x10000000, kVelocityNextLeft = 0x20000000;
// Packed weights are 16-bit decimal fixed point (0.4 digits); velocities in hundredths.
constexpr double kWeightScale = 10000.0, kVelocityScale = 100.0;


std::uint32_t float_bits(double v) {
  const float f = static_cast<float>(v);
  std::uint32_t u;
  std::memcpy(&u, &f, 4);
  return u;
}
double bits_float(std::int64_t v) {
  const auto u = static_cast<std::uint32_t>(v);
  float f;
  std::memcpy(&f, &u, 4);
  return static_cast<double>(f);
}

// KeyAttrDataFloat as floats and as their bits: binary files store floats, ASCII
// files the floats' bits as integers.
struct AttrData {
  std::vector<double> values;
  std::vector<std::uint32_t> bits;
};
AttrData attr_data(const FbxNode* n) {
  AttrData d;
  if (!n || n->properties.empty()) return d;
  const FbxProperty& p = n->properties[0];
  if (!p.integers.empty()) {
    for (std::int64_t v : p.integers) d.values.push_back(bits_float(v)), d.bits.push_back(static_cast<std::uint32_t>(v));
  } else {
    for (double v : p.numbers) d.values.push_back(v), d.bits.push_back(float_bits(v));
  }
  return d;
}

std::vector<double> array_of(const FbxNode& curve, const char* name) {
  const FbxNode* n = curve.child(name);
  return n && !n->properties.empty() ? n->properties[0].as_doubles() : std::vector<double>{};
}

FbxExtrapolationRule extrapolation(const FbxNode* n) {
  FbxExtrapolationRule r;
  if (!n) return r;
  if (const FbxNode* type = n->child("Type"); type && !type->properties.empty()) {
    const FbxProperty& p = type->properties[0];
    const char c = p.is_string() && !p.text.empty() ? p.text[0] : static_cast<char>(p.integer);
    r.mode = c == 'R' ? FbxExtrapolation::repetition
           : c == 'M' ? FbxExtrapolation::mirror
           : c == 'K' ? FbxExtrapolation::keep_slope
                      : FbxExtrapolation::constant;
  }
  if (const FbxNode* rep = n->child("Repetition"); rep && !rep->properties.empty() && rep->properties[0].is_number())
    r.repetitions = static_cast<int>(std::clamp(rep->properties[0].as_double(), -1.0, 1e9));
  return r;
}

void decode_flags(FbxKey& k, std::uint32_t flags, const double* data, const std::uint32_t* bits) {
  k.flags = flags;
  if (flags & kConstant) k.interpolation = (flags & kConstantNext) ? FbxInterpolation::constant_next : FbxInterpolation::constant_previous;
  else if (flags & kCubic) k.interpolation = FbxInterpolation::cubic;
  else k.interpolation = FbxInterpolation::linear;  // kLinear, or no interpolation bits
  if (k.interpolation == FbxInterpolation::cubic) {
    if (flags & kTangentTcb) k.tangent = FbxTangent::tcb;
    else if (flags & kTangentUser) k.tangent = (flags & kTangentBreak) ? FbxTangent::broken : FbxTangent::user;
    else if (flags & kTangentClamp) k.tangent = FbxTangent::clamped;
    else if (flags & kTangentTimeIndependent) k.tangent = FbxTangent::spline;
    else if (flags & kTangentAuto) k.tangent = FbxTangent::auto_smooth;
  }
  k.right_slope = data[0];
  k.next_left_slope = data[1];
  if (k.tangent == FbxTangent::tcb) k.tension = data[0], k.continuity = data[1], k.bias = data[2];
  k.weighted_right = flags & kWeightedRight;
  k.weighted_next_left = flags & kWeightedNextLeft;
  if (k.weighted_right) k.right_weight = (bits[2] & 0xffff) / kWeightScale;
  if (k.weighted_next_left) k.next_left_weight = (bits[2] >> 16) / kWeightScale;
  k.velocity_right = flags & kVelocityRight;
  k.velocity_next_left = flags & kVelocityNextLeft;
  if (k.velocity_right) k.right_velocity = static_cast<std::int16_t>(bits[3] & 0xffff) / kVelocityScale;
  if (k.velocity_next_left) k.next_left_velocity = static_cast<std::int16_t>(bits[3] >> 16) / kVelocityScale;
}

}  // namespace

Status read_fbx_curve_keys(const FbxNode& node, FbxCurve& c, const std::string& where,
                           std::vector<std::string>& warnings) {
  const std::vector<double> times = array_of(node, "KeyTime"), values = array_of(node, "KeyValueFloat");
  const std::vector<double> flags = array_of(node, "KeyAttrFlags"), refs = array_of(node, "KeyAttrRefCount");
  const AttrData data = attr_data(node.child("KeyAttrDataFloat"));
  if (const FbxNode* d = node.child("Default"); d && !d->properties.empty()) c.default_value = d->properties[0].as_double();
  if (times.size() != values.size())
    return make_error(where + ": " + std::to_string(times.size()) + " key times for " + std::to_string(values.size()) + " values");
  if (flags.size() != refs.size() || data.values.size() != 4 * flags.size())
    return make_error(where + ": key attribute arrays of differing lengths");
  const FbxNode* time_node = node.child("KeyTime");
  static const std::vector<std::int64_t> kNone;
  const std::vector<std::int64_t>& ticks = time_node && !time_node->properties.empty() ? time_node->properties[0].integers : kNone;
  // Times stored as doubles (not the usual int64 ticks) must be whole tick counts in range.
  for (std::size_t i = ticks.size(); i < times.size(); ++i)
    if (!(std::abs(times[i]) < 9.2e18))
      return make_error(where + ": key " + std::to_string(i) + " has a time of " + std::to_string(times[i]) +
                        " ticks, out of range");
  Result<std::vector<std::size_t>> repaired = check_keys(times, values, 1, where);
  if (!repaired) return repaired.failure();
  std::size_t attr = 0, used = 0;
  c.keys.resize(times.size());
  for (std::size_t i = 0; i < times.size(); ++i) {
    FbxKey& k = c.keys[i];
    k.ticks = i < ticks.size() ? ticks[i] : static_cast<std::int64_t>(times[i]);
    k.value = values[i];
    // Ticks past 2^53 compare here as the doubles check_keys saw may not.
    if (i > 0 && k.ticks < c.keys[i - 1].ticks) return make_error(where + ": key times do not increase at key " + std::to_string(i));
    while (attr < refs.size() && static_cast<double>(used) >= refs[attr]) ++attr, used = 0;
    if (attr >= refs.size()) {
      if (!flags.empty()) return make_error(where + ": key attributes cover fewer keys than the curve's " + std::to_string(times.size()));
      continue;  // no attributes at all: linear keys
    }
    ++used;
    double slots[4];
    for (int s = 0; s < 4; ++s) slots[s] = std::isfinite(data.values[4 * attr + s]) ? data.values[4 * attr + s] : 0.0;
    // Flags are 32-bit (stored signed or not); anything else is not a flag word.
    const double f = flags[attr];
    if (!(f >= -2147483648.0 && f <= 4294967295.0)) return make_error(where + ": key flags " + std::to_string(f) + " are not 32-bit");
    decode_flags(k, static_cast<std::uint32_t>(static_cast<std::int64_t>(f)), slots, &data.bits[4 * attr]);
  }
  drop_keys(c.keys, *repaired, 1);
  if (!repaired->empty()) warnings.push_back(repaired_keys_warning(where, repaired->size()));
  c.pre = extrapolation(node.child("Pre-Extrapolation"));
  c.post = extrapolation(node.child("Post-Extrapolation"));
  return Ok{};
}

}  // namespace rotinterp
