// read_fbx_animation: FBX 7.x takes (AnimationStack), their layers, and each
// layer's curves on Lcl Translation/Rotation/Scaling with every key attribute
// (FBX 6.1 takes: fbx_takes.cpp).
#include "fbx_objects.h"
#include "rotinterp/io/fbx/fbx_curves.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <iterator>
#include <optional>
#include <tuple>

namespace rotinterp {

namespace {

using fbx::Connection;
using fbx::Objects;

// KeyAttrFlags bits (the FBX SDK's FbxAnimCurveDef).
constexpr std::uint32_t kConstant = 0x2, kLinear = 0x4, kCubic = 0x8;
constexpr std::uint32_t kConstantNext = 0x100;  // with kConstant
constexpr std::uint32_t kTangentAuto = 0x100, kTangentTcb = 0x200, kTangentUser = 0x400, kTangentBreak = 0x800;
constexpr std::uint32_t kTangentClamp = 0x1000, kTangentTimeIndependent = 0x2000;
constexpr std::uint32_t kWeightedRight = 0x1000000, kWeightedNextLeft = 0x2000000;
constexpr std::uint32_t kVelocityRight = 0x10000000, kVelocityNextLeft = 0x20000000;
// Packed weights are 16-bit decimal fixed point (0.4 digits); velocities in hundredths.
constexpr double kWeightScale = 10000.0, kVelocityScale = 100.0;

const char* const kProperties[] = {"Lcl Translation", "Lcl Rotation", "Lcl Scaling"};

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

Status read_keys(const FbxNode& node, FbxCurve& c, const std::string& where) {
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
  std::size_t attr = 0, used = 0;
  c.keys.resize(times.size());
  for (std::size_t i = 0; i < times.size(); ++i) {
    FbxKey& k = c.keys[i];
    // Times stored as doubles (not the usual int64 ticks) must be whole tick counts in range.
    if (i >= ticks.size() && !(std::abs(times[i]) < 9.2e18))
      return make_error(where + ": key " + std::to_string(i) + " has a time of " + std::to_string(times[i]) +
                        " ticks, out of range");
    k.ticks = i < ticks.size() ? ticks[i] : static_cast<std::int64_t>(times[i]);
    k.value = values[i];
    if (!std::isfinite(k.value)) return make_error(where + ": key " + std::to_string(i) + " has a non-finite value");
    if (i > 0 && k.ticks <= c.keys[i - 1].ticks) return make_error(where + ": key times do not increase at key " + std::to_string(i));
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
  c.pre = extrapolation(node.child("Pre-Extrapolation"));
  c.post = extrapolation(node.child("Post-Extrapolation"));
  return Ok{};
}

FbxLayer read_layer(const FbxNode& node) {
  FbxLayer l;
  l.name = fbx::object_name(node);
  l.weight = fbx::property_number(fbx::find_property(node, "Weight"), 0, 100.0);
  const int blend = static_cast<int>(fbx::property_number(fbx::find_property(node, "BlendMode"), 0, 0));
  l.blend = blend == 1 ? FbxBlendMode::override : blend == 2 ? FbxBlendMode::override_passthrough : FbxBlendMode::additive;
  l.mute = fbx::property_number(fbx::find_property(node, "Mute"), 0, 0) != 0.0;
  l.solo = fbx::property_number(fbx::find_property(node, "Solo"), 0, 0) != 0.0;
  l.rotation_accumulation = static_cast<int>(fbx::property_number(fbx::find_property(node, "RotationAccumulationMode"), 0, 0));
  l.scale_accumulation = static_cast<int>(fbx::property_number(fbx::find_property(node, "ScaleAccumulationMode"), 0, 0));
  return l;
}

// The objects of class `cls` connected to `parent` as its children, in file order.
std::vector<const FbxNode*> children_of(const Objects& o, std::int64_t parent, std::string_view cls) {
  std::vector<std::size_t> idx;
  for (auto [it, end] = o.by_parent.equal_range(parent); it != end; ++it) idx.push_back(it->second);
  std::sort(idx.begin(), idx.end());
  std::vector<const FbxNode*> out;
  for (std::size_t i : idx)
    if (auto obj = o.by_id.find(o.connections[i].child); obj != o.by_id.end() && obj->second->name == cls)
      out.push_back(obj->second);
  return out;
}

// The curve of `curve_node` connected as `property` ("d|X", "d|Weight"), or nullptr.
const FbxNode* curve_of(const Objects& o, std::int64_t curve_node, std::string_view property) {
  for (auto [ci, cend] = o.by_parent.equal_range(curve_node); ci != cend; ++ci) {
    const Connection& link = o.connections[ci->second];
    const auto curve = o.by_id.find(link.child);
    if (curve != o.by_id.end() && curve->second->name == "AnimationCurve" && link.property == property)
      return curve->second;
  }
  return nullptr;
}

Status read_layer_curves(const Objects& o, const FbxNode& layer, std::size_t index, const std::vector<FbxModel>& models,
                         FbxTake& take, const std::string& label) {
  const std::int64_t layer_id = fbx::object_id(layer);
  for (const FbxNode* cn : children_of(o, layer_id, "AnimationCurveNode")) {
    const std::int64_t cn_id = fbx::object_id(*cn);
    for (auto [it, end] = o.by_child.equal_range(cn_id); it != end; ++it) {
      const Connection& target = o.connections[it->second];
      if (target.parent == layer_id && target.property == "Weight") {  // the layer's own weight, keyed
        const FbxNode* curve = curve_of(o, cn_id, "d|Weight");
        if (!curve) continue;
        FbxCurve c;
        c.node = take.layers[index].name;
        c.property = "Weight";
        c.channel = ' ';
        c.layer = index;
        c.default_value = fbx::property_number(fbx::find_property(*cn, "d|Weight"), 0, take.layers[index].weight);
        const std::string where = label + ": FBX layer " + fbx_printable(c.node) + "/Weight";
        if (Status st = read_keys(*curve, c, where); !st) return make_error(st.error(), ErrorKind::unreadable);
        take.layers[index].weight_curve = std::move(c);
        continue;
      }
      if (std::find(std::begin(kProperties), std::end(kProperties), target.property) == std::end(kProperties)) continue;
      const auto model = std::find_if(models.begin(), models.end(), [&](const FbxModel& m) { return m.id == target.parent; });
      if (model == models.end()) continue;
      FbxAnimatedProperty animated{model->name, target.property, index, {}};
      for (std::size_t c = 0; c < 3; ++c)
        animated.defaults[c] = fbx::property_number(fbx::find_property(*cn, std::string("d|") + "XYZ"[c]), 0, 0.0);
      take.properties.push_back(std::move(animated));
      for (auto [ci, cend] = o.by_parent.equal_range(cn_id); ci != cend; ++ci) {
        const Connection& link = o.connections[ci->second];
        const auto curve = o.by_id.find(link.child);
        if (curve == o.by_id.end() || curve->second->name != "AnimationCurve") continue;
        if (link.property.size() != 3 || link.property.substr(0, 2) != "d|") continue;
        const char ch = link.property[2];
        if (ch != 'X' && ch != 'Y' && ch != 'Z') continue;
        FbxCurve c;
        c.node = model->name;
        c.property = target.property;
        c.channel = ch;
        c.layer = index;
        c.default_value = fbx::property_number(fbx::find_property(*cn, link.property), 0, 0.0);
        const std::string where = label + ": FBX curve " + fbx_printable(c.node) + "/" + c.property + "/" + ch;
        if (Status st = read_keys(*curve->second, c, where); !st) return make_error(st.error(), ErrorKind::unreadable);
        take.curves.push_back(std::move(c));
      }
    }
  }
  return Ok{};
}

}  // namespace

FbxTickSpan fbx_take_span(const FbxTake& take) {
  if (take.stop > take.start) return {take.start, take.stop};
  std::optional<FbxTickSpan> keys;
  for (const FbxCurve& c : take.curves)
    if (!c.keys.empty())
      keys = FbxTickSpan{std::min(keys ? keys->start : c.keys.front().ticks, c.keys.front().ticks),
                         std::max(keys ? keys->stop : c.keys.back().ticks, c.keys.back().ticks)};
  return keys.value_or(FbxTickSpan{take.start, take.start});
}

Result<FbxAnimation> read_fbx_animation(const FbxDocument& doc, const std::string& label) {
  if (doc.version > 0 && doc.version < 7000) return fbx::read_fbx_takes(doc, label);
  const Objects objects = fbx::index_objects(doc);
  FbxAnimation anim;
  anim.version = doc.version;
  anim.models = fbx::read_models(doc, objects);
  std::vector<std::string> order;
  for (const FbxModel& m : anim.models) order.push_back(m.name);
  for (const FbxNode* stack : objects.in_order) {
    if (stack->name != "AnimationStack") continue;
    FbxTake take;
    take.name = fbx::object_name(*stack);
    take.start = static_cast<std::int64_t>(fbx::property_number(fbx::find_property(*stack, "LocalStart"), 0, 0));
    take.stop = static_cast<std::int64_t>(fbx::property_number(fbx::find_property(*stack, "LocalStop"), 0, 0));
    const std::vector<const FbxNode*> layers = children_of(objects, fbx::object_id(*stack), "AnimationLayer");
    for (std::size_t l = 0; l < layers.size(); ++l) {
      take.layers.push_back(read_layer(*layers[l]));
      if (Status st = read_layer_curves(objects, *layers[l], l, anim.models, take, label); !st) return st.failure();
    }
    auto rank = [&](const FbxCurve& c) {
      const auto at = std::find(order.begin(), order.end(), c.node) - order.begin();
      const auto prop = std::find(std::begin(kProperties), std::end(kProperties), c.property) - std::begin(kProperties);
      return std::make_tuple(at, prop, c.channel, c.layer);
    };
    std::stable_sort(take.curves.begin(), take.curves.end(), [&](const FbxCurve& a, const FbxCurve& b) { return rank(a) < rank(b); });
    anim.takes.push_back(std::move(take));
  }
  return anim;
}

Result<FbxAnimation> read_fbx_curves_file(const std::string& path, const std::string& label) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  if (!in || !(bytes << in.rdbuf())) return make_error(label + ": cannot read the file", ErrorKind::cannot_open);
  const std::string text = bytes.str();
  Result<FbxDocument> doc = parse_fbx_nodes(text, label);
  if (!doc) return doc.failure();
  return read_fbx_animation(*doc, label);
}

const char* fbx_interpolation_name(FbxInterpolation i) {
  switch (i) {
    case FbxInterpolation::constant_previous: return "constant-previous";
    case FbxInterpolation::constant_next: return "constant-next";
    case FbxInterpolation::linear: return "linear";
    case FbxInterpolation::cubic: return "cubic";
  }
  return "linear";
}

const char* fbx_tangent_name(FbxTangent t) {
  switch (t) {
    case FbxTangent::none: return "none";
    case FbxTangent::auto_smooth: return "auto";
    case FbxTangent::spline: return "spline";
    case FbxTangent::clamped: return "clamped";
    case FbxTangent::user: return "user";
    case FbxTangent::broken: return "break";
    case FbxTangent::tcb: return "tcb";
  }
  return "none";
}

const char* fbx_extrapolation_name(FbxExtrapolation e) {
  switch (e) {
    case FbxExtrapolation::constant: return "constant";
    case FbxExtrapolation::repetition: return "repetition";
    case FbxExtrapolation::mirror: return "mirror";
    case FbxExtrapolation::keep_slope: return "keep-slope";
  }
  return "constant";
}

const char* fbx_blend_mode_name(FbxBlendMode b) {
  switch (b) {
    case FbxBlendMode::additive: return "additive";
    case FbxBlendMode::override: return "override";
    case FbxBlendMode::override_passthrough: return "override-passthrough";
  }
  return "additive";
}

}  // namespace rotinterp
