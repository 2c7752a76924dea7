// Our FBX writer: a clip's skeleton and given curves as FBX 7.4 objects, properties, curves and connections.
#include "fbx_write.h"

#include "fbx_bvh_layout.h"
#include "fbx_encode.h"
#include "fbx_rest.h"
#include "rotinterp/clip/frames.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <optional>

namespace rotinterp {

namespace {

constexpr int kTimeModeDefault = 0;
// FbxAnimCurve key layout version and per-key attributes (io/fbx_curves.cpp reads
// them): linear interpolation (0x4) with the SDK's default tangent bits; cubic (0x8)
// with user tangents (0x400), broken (0x800) where the left and right slopes differ.
// The tangent weights are the default 1/3, packed as two 16-bit 3333s into one
// float's bits.
constexpr std::int32_t kKeyVersion = 4008;
constexpr std::int32_t kKeyLinearFlags = 0x4 | 0x100 | 0x2000 | 0x4000;
constexpr std::int32_t kKeyCubicUserFlags = 0x8 | 0x400, kKeyBrokenFlag = 0x800;
constexpr std::uint32_t kDefaultTangentWeights = 0x0D050D05;
// A fixed creation time (and the FileId the format notes give for it), so that the
// same command writes the same bytes.
constexpr const char* kCreationTime = "1970-01-01 10:00:00:000";
constexpr unsigned char kFileId[16] = {0x28, 0xb3, 0x2a, 0xeb, 0xb6, 0x24, 0xcc, 0xc2,
                                       0xbf, 0xc8, 0xb0, 0x2a, 0xa9, 0x2b, 0xfc, 0xf1};

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

class Document {
 public:
  explicit Document(FbxEncoding e)
      : enc_(e == FbxEncoding::binary ? FbxEncoder::Format::binary : FbxEncoder::Format::ascii) {}
  FbxEncoder& enc() { return enc_; }

  // A Properties70 entry: P: name, type, label, flags, values… (values follow; then end()).
  FbxEncoder& p(std::string_view name, std::string_view type, std::string_view label, std::string_view flags) {
    enc_.begin("P");
    return enc_.str(name).str(type).str(label).str(flags);
  }
  void p_int(std::string_view name, std::string_view type, std::string_view label, std::int32_t v) {
    p(name, type, label, "").i32(v);
    enc_.end();
  }
  void p_double(std::string_view name, double v) {
    p(name, "double", "Number", "").f64(v);
    enc_.end();
  }
  void p_time(std::string_view name, std::int64_t ticks) {
    p(name, "KTime", "Time", "").i64(ticks);
    enc_.end();
  }
  void p_vec(std::string_view name, const Vec3& v) {
    p(name, name, "", "A").f64(v.x()).f64(v.y()).f64(v.z());
    enc_.end();
  }
  void leaf_i32(std::string_view name, std::int32_t v) {
    enc_.begin(name);
    enc_.i32(v);
    enc_.end();
  }
  void leaf_str(std::string_view name, std::string_view v) {
    enc_.begin(name);
    enc_.str(v);
    enc_.end();
  }
  void connect(std::int64_t child, std::int64_t parent, std::string_view property = {}) {
    enc_.begin("C");
    enc_.str(property.empty() ? "OO" : "OP").i64(child).i64(parent);
    if (!property.empty()) enc_.str(property);
    enc_.end();
  }

 private:
  FbxEncoder enc_;
};

// An AnimationCurve: its keys, and their attributes as runs of keys that share
// flags and data (KeyAttrRefCount: the length of each run).
void write_curve(Document& doc, std::int64_t id, const FbxOutCurve& keys) {
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

}  // namespace

Result<std::string> encode_fbx_curves(const Clip& clip, const std::vector<FbxOutJoint>& curves, FbxEncoding encoding) {
  if (Status s = clip.validate(); !s) return s.failure("cannot write an invalid clip: ");
  const Skeleton& sk = clip.skeleton;
  const std::size_t n = sk.joints.size();
  if (curves.size() != n) return make_error("FBX curves for " + std::to_string(curves.size()) + " joints, the clip has " + std::to_string(n));
  const std::optional<Rate> rate = clip_rate(clip);
  std::int64_t first = 0, last = 0;
  bool any = false;
  for (const FbxOutJoint& c : curves)
    for (const auto* set : {&c.rotation, &c.translation})
      for (const FbxOutCurve& curve : *set) {
        if (curve.empty()) continue;
        first = any ? std::min(first, curve.front().ticks) : curve.front().ticks;
        last = any ? std::max(last, curve.back().ticks) : curve.back().ticks;
        any = true;
      }
  for (std::size_t j = 0; j < n; ++j)
    if (std::all_of(curves[j].rotation.begin(), curves[j].rotation.end(), [](const FbxOutCurve& c) { return c.empty(); }))
      return make_error("FBX curves: joint " + sk.joints[j].name + " has no rotation keys");
  const std::string take = clip.name.empty() ? std::string("clip") : clip.name;

  std::vector<Vec3> rest_euler(n);
  for (std::size_t j = 0; j < n; ++j) {
    const EulerAxes& axes = curves[j].axes;
    // Angle i of a sequence turns about axis axes[i]; FBX stores them by axis (X, Y, Z).
    const Vec3 rest = euler_nearest(sk.joints[j].rest_rotation, axes, Vec3::Zero()) * kDegrees;
    for (int i = 0; i < 3; ++i) rest_euler[j][axes[static_cast<std::size_t>(i)]] = rest[i];
  }

  const std::vector<Vec3> rest_translation = fbx_rest_translations(clip);  // Blender-safe (fbx_rest.h)

  Document doc(encoding);
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
    e.begin("FileId");
    e.raw(std::string_view(reinterpret_cast<const char*>(kFileId), sizeof kFileId));
    e.end();
    doc.leaf_str("CreationTime", kCreationTime);
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
  doc.p_time("TimeSpanStart", first);
  doc.p_time("TimeSpanStop", last);
  doc.p_double("CustomFrameRate", rate ? rate->hz() : -1.0);
  e.end();
  e.end();

  // Object ids: node attributes, models, stack, layer, curve nodes, curves.
  std::int64_t next_id = 1000000;
  auto new_id = [&next_id] { return next_id++; };
  const std::int64_t document_id = new_id();
  std::vector<std::int64_t> attr_id(n), model_id(n), rot_node(n), pos_node(n, 0);
  std::vector<std::array<std::int64_t, 3>> rot_curve(n), pos_curve(n);
  for (std::size_t j = 0; j < n; ++j) attr_id[j] = new_id(), model_id[j] = new_id();
  const std::int64_t stack_id = new_id(), layer_id = new_id();
  std::size_t curve_nodes = 0;
  for (std::size_t j = 0; j < n; ++j) {
    rot_node[j] = new_id();
    for (std::size_t a = 0; a < 3; ++a) rot_curve[j][a] = curves[j].rotation[a].empty() ? 0 : new_id();
    ++curve_nodes;
    if (curves[j].has_translation) {
      pos_node[j] = new_id();
      for (std::size_t a = 0; a < 3; ++a) pos_curve[j][a] = curves[j].translation[a].empty() ? 0 : new_id();
      ++curve_nodes;
    }
  }

  e.begin("Documents");
  doc.leaf_i32("Count", 1);
  e.begin("Document");
  e.i64(document_id).str("Scene").str("Scene");
  e.begin("Properties70");
  doc.p("SourceObject", "object", "", "");
  e.end();
  doc.p("ActiveAnimStackName", "KString", "", "").str(take);
  e.end();
  e.end();
  e.begin("RootNode");
  e.i64(0);
  e.end();
  e.end();
  e.end();
  e.begin("References");
  e.end();

  std::size_t curve_count = 0;
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t a = 0; a < 3; ++a) curve_count += (rot_curve[j][a] != 0) + (pos_curve[j][a] != 0);
  e.begin("Definitions");
  doc.leaf_i32("Version", 100);
  const std::pair<const char*, std::size_t> types[] = {{"GlobalSettings", 1}, {"NodeAttribute", n}, {"Model", n},
                                                       {"AnimationStack", 1}, {"AnimationLayer", 1},
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
  for (std::size_t j = 0; j < n; ++j) {
    e.begin("NodeAttribute");
    e.i64(attr_id[j]).str(e.object_name(sk.joints[j].name, "NodeAttribute")).str("LimbNode");
    e.begin("Properties70");
    doc.p_double("Size", 1.0);
    e.end();
    doc.leaf_str("TypeFlags", "Skeleton");
    e.end();
  }
  for (std::size_t j = 0; j < n; ++j) {
    const Joint& joint = sk.joints[j];
    e.begin("Model");
    e.i64(model_id[j]).str(e.object_name(joint.name, "Model")).str("LimbNode");
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
  e.begin("AnimationStack");
  e.i64(stack_id).str(e.object_name(take, "AnimStack")).str("");
  e.begin("Properties70");
  doc.p_time("LocalStart", first);
  doc.p_time("LocalStop", last);
  doc.p_time("ReferenceStart", first);
  doc.p_time("ReferenceStop", last);
  e.end();
  e.end();
  e.begin("AnimationLayer");
  e.i64(layer_id).str(e.object_name("BaseLayer", "AnimLayer")).str("");
  e.end();
  auto curve_node = [&](std::int64_t id, const char* name, const std::array<FbxOutCurve, 3>& c, const Vec3& defaults) {
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
  };
  for (std::size_t j = 0; j < n; ++j) {
    curve_node(rot_node[j], "R", curves[j].rotation, curves[j].rotation_default);
    if (pos_node[j]) curve_node(pos_node[j], "T", curves[j].translation, curves[j].translation_default);
  }
  for (std::size_t j = 0; j < n; ++j) {
    for (std::size_t a = 0; a < 3; ++a)
      if (rot_curve[j][a]) write_curve(doc, rot_curve[j][a], curves[j].rotation[a]);
    for (std::size_t a = 0; a < 3; ++a)
      if (pos_curve[j][a]) write_curve(doc, pos_curve[j][a], curves[j].translation[a]);
  }
  e.end();

  e.begin("Connections");
  for (std::size_t j = 0; j < n; ++j) {
    const int parent = sk.joints[j].parent;
    doc.connect(model_id[j], parent >= 0 ? model_id[static_cast<std::size_t>(parent)] : 0);
    doc.connect(attr_id[j], model_id[j]);
  }
  doc.connect(layer_id, stack_id);
  static const char* axis_names[] = {"d|X", "d|Y", "d|Z"};
  for (std::size_t j = 0; j < n; ++j) {
    doc.connect(rot_node[j], layer_id);
    doc.connect(rot_node[j], model_id[j], "Lcl Rotation");
    for (std::size_t a = 0; a < 3; ++a)
      if (rot_curve[j][a]) doc.connect(rot_curve[j][a], rot_node[j], axis_names[a]);
    if (!pos_node[j]) continue;
    doc.connect(pos_node[j], layer_id);
    doc.connect(pos_node[j], model_id[j], "Lcl Translation");
    for (std::size_t a = 0; a < 3; ++a)
      if (pos_curve[j][a]) doc.connect(pos_curve[j][a], pos_node[j], axis_names[a]);
  }
  e.end();

  e.begin("Takes");
  doc.leaf_str("Current", take);
  e.begin("Take");
  e.str(take);
  doc.leaf_str("FileName", take + ".tak");
  e.begin("LocalTime");
  e.i64(first).i64(last);
  e.end();
  e.begin("ReferenceTime");
  e.i64(first).i64(last);
  e.end();
  e.end();
  e.end();
  return e.finish();
}

}  // namespace rotinterp
