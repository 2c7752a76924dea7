// Our FBX writer: a clip's skeleton, settings and takes as FBX 7.4 objects and connections (takes: fbx_write_takes.cpp).
#include "rotinterp/io/fbx/fbx_write.h"

#include "rotinterp/io/fbx/fbx_bvh_layout.h"
#include "rotinterp/io/files/file_record.h"
#include "rotinterp/io/files/written_names.h"
#include "fbx_write_takes.h"
#include "fbx_rest.h"
#include "rotinterp/clip/frames.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace rotinterp {

namespace {

constexpr int kTimeModeDefault = 0;

// FBX's EFbxRotationOrder names the axes in the order they apply (innermost first):
// eEulerXYZ = 0 is R = Rz·Ry·Rx.
int fbx_rotation_order(const EulerAxes& a) {
  static const char* names[] = {"XYZ", "XZY", "YZX", "YXZ", "ZXY", "ZYX"};
  const std::string name{static_cast<char>('X' + a[2]), static_cast<char>('X' + a[1]), static_cast<char>('X' + a[0])};
  for (int i = 0; i < 6; ++i)
    if (name == names[i]) return i;
  return 0;
}

constexpr double kDegrees = 180.0 / kPi;

}  // namespace

Result<std::string> encode_fbx_curves(const Clip& clip, const std::vector<FbxOutJoint>& curves, FbxEncoding encoding) {
  return encode_fbx_takes(clip, {FbxOutTake{clip.name.empty() ? std::string("clip") : readable_text(clip.name), curves}},
                          clip_rate(clip), encoding);
}

Result<std::string> encode_fbx_takes(const Clip& clip, const std::vector<FbxOutTake>& takes,
                                     const std::optional<Rate>& rate, FbxEncoding encoding) {
  if (Status s = clip.validate(); !s) return s.failure("cannot write an invalid clip: ");
  const Skeleton& sk = clip.skeleton;
  const std::size_t n = sk.joints.size();
  if (takes.empty()) return make_error("FBX: no takes to write");
  // The models' rotation orders and rest values are the first take's.
  const std::vector<FbxOutJoint>& curves = takes.front().curves;
  for (const FbxOutTake& take : takes) {
    const std::string where = takes.size() > 1 ? "take '" + take.name + "': " : "";
    if (take.curves.size() != n)
      return make_error(where + "FBX curves for " + std::to_string(take.curves.size()) + " joints, the clip has " + std::to_string(n));
    for (std::size_t j = 0; j < n; ++j) {
      const FbxOutJoint& c = take.curves[j];
      if (std::all_of(c.rotation.begin(), c.rotation.end(), [](const FbxOutCurve& k) { return k.empty(); }))
        return make_error(where + "FBX curves: joint " + sk.joints[j].name + " has no rotation keys");
      if (c.axes != curves[j].axes)
        return make_error(where + "FBX curves: joint " + sk.joints[j].name + " has another rotation order than in the first take");
    }
  }
  std::vector<FbxTickSpan> spans;
  for (const FbxOutTake& take : takes) spans.push_back(fbx_curves_span(take.curves));
  FbxTickSpan whole = spans.front();
  for (const FbxTickSpan& s : spans) whole = {std::min(whole.start, s.start), std::max(whole.stop, s.stop)};

  std::vector<Vec3> rest_euler(n);
  for (std::size_t j = 0; j < n; ++j) {
    const EulerAxes& axes = curves[j].axes;
    // Angle i of a sequence turns about axis axes[i]; FBX stores them by axis (X, Y, Z).
    const Vec3 rest = euler_nearest(sk.joints[j].rest_rotation, axes, Vec3::Zero()) * kDegrees;
    for (int i = 0; i < 3; ++i) rest_euler[j][axes[static_cast<std::size_t>(i)]] = rest[i];
  }

  const std::vector<Vec3> rest_translation = fbx_rest_translations(clip);  // Blender-safe (fbx_rest.h)

  FbxWriteDocument doc(encoding);
  FbxEncoder& e = doc.enc();
  const std::string creator = std::string("rotinterp ") + ROTINTERP_VERSION;

  e.begin("FBXHeaderExtension");
  doc.leaf_i32("FBXHeaderVersion", 1003);
  doc.leaf_i32("FBXVersion", static_cast<std::int32_t>(FbxEncoder::kVersion));
  e.begin("CreationTimeStamp");
  doc.leaf_i32("Version", 1000);
  for (auto [field, v] : {std::pair<const char*, int>{"Year", 1970}, {"Month", 1}, {"Day", 1}, {"Hour", 10},
                          {"Minute", 0}, {"Second", 0}, {"Millisecond", 0}})
    doc.leaf_i32(field, v);
  e.end();
  doc.leaf_str("Creator", creator);
  e.end();
  if (encoding == FbxEncoding::binary) {
    doc.file_id();
    doc.leaf_str("Creator", creator);
  }

  // Global settings: axes as BVH (Y up, Z front, X right), units, the clip's rate.
  e.begin("GlobalSettings");
  doc.leaf_i32("Version", 1000);
  e.begin("Properties70");
  for (auto [name, v] : {std::pair<const char*, int>{"UpAxis", 1}, {"UpAxisSign", 1}, {"FrontAxis", 2},
                         {"FrontAxisSign", 1}, {"CoordAxis", 0}, {"CoordAxisSign", 1}, {"OriginalUpAxis", 1},
                         {"OriginalUpAxisSign", 1}})
    doc.p_int(name, "int", "Integer", v);
  doc.p_double("UnitScaleFactor", 100.0 * clip.unit.metres_per_unit);
  doc.p_double("OriginalUnitScaleFactor", 100.0 * clip.unit.metres_per_unit);
  doc.p("TimeMode", "enum", "", "").i32(rate ? fbx_time_mode(rate->num, rate->den) : kTimeModeDefault);
  e.end();
  doc.p_time("TimeSpanStart", whole.start);
  doc.p_time("TimeSpanStop", whole.stop);
  doc.p_double("CustomFrameRate", rate ? rate->hz() : -1.0);
  e.end();
  e.end();

  // Object ids: node attributes, models, then each take's stack, layer, curve nodes, curves.
  std::int64_t next_id = 1000000;
  auto new_id = [&next_id] { return next_id++; };
  const std::int64_t document_id = new_id();
  std::vector<std::int64_t> attr_id(n), model_id(n);
  for (std::size_t j = 0; j < n; ++j) attr_id[j] = new_id(), model_id[j] = new_id();
  std::vector<FbxTakeIds> take_ids;
  std::size_t curve_nodes = 0, curve_count = 0;
  for (const FbxOutTake& take : takes) {
    take_ids.push_back(new_take_ids(take.curves, new_id));
    curve_nodes += take_ids.back().curve_nodes;
    curve_count += take_ids.back().curves;
  }

  e.begin("Documents");
  doc.leaf_i32("Count", 1);
  e.begin("Document");
  e.i64(document_id).str("Scene").str("Scene");
  e.begin("Properties70");
  doc.p("SourceObject", "object", "", "");
  e.end();
  doc.p("ActiveAnimStackName", "KString", "", "").str(takes.front().name);
  e.end();
  e.end();
  e.begin("RootNode");
  e.i64(0);
  e.end();
  e.end();
  e.end();
  e.begin("References");
  e.end();

  e.begin("Definitions");
  doc.leaf_i32("Version", 100);
  const std::pair<const char*, std::size_t> types[] = {{"GlobalSettings", 1}, {"NodeAttribute", n}, {"Model", n},
                                                       {"AnimationStack", takes.size()}, {"AnimationLayer", takes.size()},
                                                       {"AnimationCurveNode", curve_nodes},
                                                       {"AnimationCurve", curve_count}};
  std::size_t total = 0;
  for (const auto& t : types) total += t.second;
  doc.leaf_i32("Count", static_cast<std::int32_t>(total));
  for (const auto& [type, count] : types) {
    e.begin("ObjectType");
    e.str(type);
    doc.leaf_i32("Count", static_cast<std::int32_t>(count));
    e.end();
  }
  e.end();

  e.begin("Objects");
  const std::vector<std::string> names = written_joint_names(sk, NameForm::text);
  for (std::size_t j = 0; j < n; ++j) {
    e.begin("NodeAttribute");
    e.i64(attr_id[j]).str(e.object_name(names[j], "NodeAttribute")).str("LimbNode");
    e.begin("Properties70");
    doc.p_double("Size", 1.0);
    e.end();
    doc.leaf_str("TypeFlags", "Skeleton");
    e.end();
  }
  for (std::size_t j = 0; j < n; ++j) {
    e.begin("Model");
    e.i64(model_id[j]).str(e.object_name(names[j], "Model")).str("LimbNode");
    doc.leaf_i32("Version", 232);
    e.begin("Properties70");
    doc.p("RotationOrder", "enum", "", "").i32(fbx_rotation_order(curves[j].axes));
    e.end();
    if (const std::vector<Channel>& channels = bvh_channels(clip, j); !channels.empty()) {
      doc.p(kBvhChannelsProperty, "KString", "", "U").str(bvh_channels_text(channels));
      e.end();
    }
    doc.p_int("RotationActive", "bool", "", 1);
    doc.p_int("InheritType", "enum", "", 1);
    doc.p_int("DefaultAttributeIndex", "int", "Integer", 0);
    if (const auto& node = curves[j].node) {
      doc.p_vec("PreRotation", node->pre_rotation);
      doc.p_vec("PostRotation", node->post_rotation);
    }
    doc.p_vec("Lcl Translation", curves[j].node ? curves[j].node->lcl_translation : rest_translation[j]);
    doc.p_vec("Lcl Rotation", curves[j].node ? curves[j].node->lcl_rotation : rest_euler[j]);
    doc.p_vec("Lcl Scaling", Vec3::Ones());
    e.end();
    doc.leaf_str("Culling", "CullingOff");
    e.end();
  }
  for (std::size_t t = 0; t < takes.size(); ++t) write_take_objects(doc, takes[t], take_ids[t], spans[t]);
  e.end();

  e.begin("Connections");
  for (std::size_t j = 0; j < n; ++j) {
    const int parent = sk.joints[j].parent;
    doc.connect(model_id[j], parent >= 0 ? model_id[static_cast<std::size_t>(parent)] : 0);
    doc.connect(attr_id[j], model_id[j]);
  }
  for (std::size_t t = 0; t < takes.size(); ++t) write_take_connections(doc, takes[t], take_ids[t], model_id);
  e.end();

  e.begin("Takes");
  doc.leaf_str("Current", takes.front().name);
  for (std::size_t t = 0; t < takes.size(); ++t) write_take_entry(doc, takes[t].name, spans[t]);
  e.end();
  return e.finish();
}

}  // namespace rotinterp
