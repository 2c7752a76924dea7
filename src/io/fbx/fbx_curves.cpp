// read_fbx_animation: FBX 7.x takes (AnimationStack), their layers, and each
// layer's curves on Lcl Translation/Rotation/Scaling with every key attribute
// (FBX 6.1 takes: fbx_takes.cpp).
#include "rotinterp/io/fbx/fbx_curves.h"

#include "fbx_keys.h"
#include "fbx_objects.h"
#include "rotinterp/io/files/file_errors.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iterator>
#include <optional>
#include <tuple>

namespace rotinterp {

namespace {

using fbx::Connection;
using fbx::Objects;

const char* const kProperties[] = {"Lcl Translation", "Lcl Rotation", "Lcl Scaling"};


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
                         FbxTake& take, std::vector<std::string>& repairs, const std::string& label) {
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
        if (Status st = read_fbx_curve_keys(*curve, c, where, repairs); !st) return make_error(st.error(), file_error::unreadable);
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
        if (Status st = read_fbx_curve_keys(*curve->second, c, where, repairs); !st) return make_error(st.error(), file_error::unreadable);
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
      if (Status st = read_layer_curves(objects, *layers[l], l, anim.models, take, anim.repairs, label); !st) return st.failure();
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
  Result<FbxDocument> doc = read_fbx_file(path, label);
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
