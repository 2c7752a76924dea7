// Our FBX writer's takes: per take an AnimationStack, its layer, curve nodes and curves, and their connections.
#include "fbx_write_takes.h"

#include <algorithm>
#include <cstring>

namespace rotinterp {

namespace {

// FbxAnimCurve key layout version and per-key attributes (io/fbx/fbx_curves.cpp reads
// them): linear interpolation (0x4) with the SDK's default tangent bits; cubic (0x8)
// with user tangents (0x400), broken (0x800) where the left and right slopes differ.
// The tangent weights are the default 1/3, packed as two 16-bit 3333s into one
// float's bits.
constexpr std::int32_t kKeyVersion = 4008;
constexpr std::int32_t kKeyLinearFlags = 0x4 | 0x100 | 0x2000 | 0x4000;
constexpr std::int32_t kKeyCubicUserFlags = 0x8 | 0x400, kKeyBrokenFlag = 0x800;
constexpr std::uint32_t kDefaultTangentWeights = 0x0D050D05;

// An AnimationCurve: its keys, and their attributes as runs of keys that share
// flags and data (KeyAttrRefCount: the length of each run).
void write_curve(FbxWriteDocument& doc, std::int64_t id, const FbxOutCurve& keys) {
  FbxEncoder& e = doc.enc();
  std::vector<std::int64_t> ticks;
  std::vector<float> values, data;
  std::vector<std::int32_t> flags, runs;
  float weights;
  std::memcpy(&weights, &kDefaultTangentWeights, 4);
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const FbxOutKey& k = keys[i];
    ticks.push_back(k.ticks);
    values.push_back(k.value);
    std::int32_t f = kKeyLinearFlags;
    std::array<float, 4> slots{0.0f, 0.0f, weights, 0.0f};
    if (k.stored_flags) {
      f = static_cast<std::int32_t>(k.stored_flags);
      slots = k.stored_data;
    } else if (k.cubic) {
      f = kKeyCubicUserFlags;
      slots[0] = k.right_slope, slots[1] = k.next_left_slope;
      if (i > 0 && keys[i - 1].cubic && keys[i - 1].next_left_slope != k.right_slope) f |= kKeyBrokenFlag;
    }
    // Compared by bits: stored data may hold packed integers.
    if (!flags.empty() && flags.back() == f && std::memcmp(&data[data.size() - 4], slots.data(), 16) == 0) {
      ++runs.back();
      continue;
    }
    flags.push_back(f);
    runs.push_back(1);
    data.insert(data.end(), slots.begin(), slots.end());
  }
  e.begin("AnimationCurve");
  e.i64(id).str(e.object_name("", "AnimCurve")).str("");
  e.begin("Default");
  e.f64(values.front());
  e.end();
  doc.leaf_i32("KeyVer", kKeyVersion);
  e.begin("KeyTime");
  e.i64_array(ticks);
  e.end();
  e.begin("KeyValueFloat");
  e.f32_array(values);
  e.end();
  e.begin("KeyAttrFlags");
  e.i32_array(flags);
  e.end();
  e.begin("KeyAttrDataFloat");
  e.f32_array(data);
  e.end();
  e.begin("KeyAttrRefCount");
  e.i32_array(runs);
  e.end();
  e.end();
}

void write_curve_node(FbxWriteDocument& doc, std::int64_t id, const char* name, const std::array<FbxOutCurve, 3>& c,
                      const Vec3& defaults) {
  FbxEncoder& e = doc.enc();
  e.begin("AnimationCurveNode");
  e.i64(id).str(e.object_name(name, "AnimCurveNode")).str("");
  e.begin("Properties70");
  for (std::size_t a = 0; a < 3; ++a) {
    const double value = c[a].empty() ? defaults[static_cast<Eigen::Index>(a)] : c[a].front().value;
    doc.p(std::string("d|") + static_cast<char>('X' + a), "Number", "", "A").f64(value);
    e.end();
  }
  e.end();
  e.end();
}

}  // namespace

FbxTakeIds new_take_ids(const std::vector<FbxOutJoint>& curves, const std::function<std::int64_t()>& new_id) {
  const std::size_t n = curves.size();
  FbxTakeIds ids;
  ids.stack = new_id();
  ids.layer = new_id();
  ids.rotation_node.assign(n, 0);
  ids.translation_node.assign(n, 0);
  ids.rotation_curve.assign(n, {});
  ids.translation_curve.assign(n, {});
  ids.scaling_node.assign(n, 0);
  ids.scaling_curve.assign(n, {});
  for (std::size_t j = 0; j < n; ++j) {
    if (curves[j].has_rotation) {
      ids.rotation_node[j] = new_id();
      for (std::size_t a = 0; a < 3; ++a) ids.rotation_curve[j][a] = curves[j].rotation[a].empty() ? 0 : new_id();
      ++ids.curve_nodes;
    }
    if (curves[j].has_translation) {
      ids.translation_node[j] = new_id();
      for (std::size_t a = 0; a < 3; ++a) ids.translation_curve[j][a] = curves[j].translation[a].empty() ? 0 : new_id();
      ++ids.curve_nodes;
    }
    if (curves[j].has_scaling) {
      ids.scaling_node[j] = new_id();
      for (std::size_t a = 0; a < 3; ++a) ids.scaling_curve[j][a] = curves[j].scaling[a].empty() ? 0 : new_id();
      ++ids.curve_nodes;
    }
    for (std::size_t a = 0; a < 3; ++a)
      ids.curves += (ids.rotation_curve[j][a] != 0) + (ids.translation_curve[j][a] != 0) + (ids.scaling_curve[j][a] != 0);
  }
  return ids;
}

FbxTickSpan fbx_curves_span(const std::vector<FbxOutJoint>& curves) {
  FbxTickSpan span;
  bool any = false;
  for (const FbxOutJoint& c : curves)
    for (const auto* set : {&c.rotation, &c.translation, &c.scaling})
      for (const FbxOutCurve& curve : *set) {
        if (curve.empty()) continue;
        span.start = any ? std::min(span.start, curve.front().ticks) : curve.front().ticks;
        span.stop = any ? std::max(span.stop, curve.back().ticks) : curve.back().ticks;
        any = true;
      }
  return span;
}

void write_take_objects(FbxWriteDocument& doc, const FbxOutTake& take, const FbxTakeIds& ids, FbxTickSpan span) {
  FbxEncoder& e = doc.enc();
  e.begin("AnimationStack");
  e.i64(ids.stack).str(e.object_name(take.name, "AnimStack")).str("");
  e.begin("Properties70");
  doc.p_time("LocalStart", span.start);
  doc.p_time("LocalStop", span.stop);
  doc.p_time("ReferenceStart", span.start);
  doc.p_time("ReferenceStop", span.stop);
  e.end();
  e.end();
  e.begin("AnimationLayer");
  e.i64(ids.layer).str(e.object_name(take.layer, "AnimLayer")).str("");
  e.end();
  const std::vector<FbxOutJoint>& curves = take.curves;
  for (std::size_t j = 0; j < curves.size(); ++j) {
    if (ids.rotation_node[j]) write_curve_node(doc, ids.rotation_node[j], "R", curves[j].rotation, curves[j].rotation_default);
    if (ids.translation_node[j])
      write_curve_node(doc, ids.translation_node[j], "T", curves[j].translation, curves[j].translation_default);
    if (ids.scaling_node[j]) write_curve_node(doc, ids.scaling_node[j], "S", curves[j].scaling, Vec3::Ones());
  }
  for (std::size_t j = 0; j < curves.size(); ++j) {
    for (std::size_t a = 0; a < 3; ++a)
      if (ids.rotation_curve[j][a]) write_curve(doc, ids.rotation_curve[j][a], curves[j].rotation[a]);
    for (std::size_t a = 0; a < 3; ++a)
      if (ids.translation_curve[j][a]) write_curve(doc, ids.translation_curve[j][a], curves[j].translation[a]);
    for (std::size_t a = 0; a < 3; ++a)
      if (ids.scaling_curve[j][a]) write_curve(doc, ids.scaling_curve[j][a], curves[j].scaling[a]);
  }
}

void write_take_connections(FbxWriteDocument& doc, const FbxOutTake& take, const FbxTakeIds& ids,
                            const std::vector<std::int64_t>& model_id) {
  static const char* axis_names[] = {"d|X", "d|Y", "d|Z"};
  doc.connect(ids.layer, ids.stack);
  for (std::size_t j = 0; j < take.curves.size(); ++j) {
    const std::pair<std::int64_t, const std::array<std::int64_t, 3>*> nodes[] = {
        {ids.rotation_node[j], &ids.rotation_curve[j]},
        {ids.translation_node[j], &ids.translation_curve[j]},
        {ids.scaling_node[j], &ids.scaling_curve[j]}};
    const char* properties[] = {"Lcl Rotation", "Lcl Translation", "Lcl Scaling"};
    for (std::size_t p = 0; p < 3; ++p) {
      const auto [node, curves] = nodes[p];
      if (!node) continue;
      doc.connect(node, ids.layer);
      doc.connect(node, model_id[j], properties[p]);
      for (std::size_t a = 0; a < 3; ++a)
        if ((*curves)[a]) doc.connect((*curves)[a], node, axis_names[a]);
    }
  }
}

void write_take_entry(FbxWriteDocument& doc, const std::string& name, FbxTickSpan span) {
  FbxEncoder& e = doc.enc();
  e.begin("Take");
  e.str(name);
  doc.leaf_str("FileName", name + ".tak");
  e.begin("LocalTime");
  e.i64(span.start).i64(span.stop);
  e.end();
  e.begin("ReferenceTime");
  e.i64(span.start).i64(span.stop);
  e.end();
  e.end();
}

}  // namespace rotinterp
