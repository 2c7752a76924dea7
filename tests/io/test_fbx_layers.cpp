// Layer blending and the full node transform (io/fbx/fbx_transform.h) against Maya:
// ../shared/data/curves/ufbx_maya_anim_layers_over_acc_orders_18.obj is Maya's
// world-space mesh at frame 18 of fbx/ufbx_maya_anim_layers_over_acc_orders_7500_ascii.fbx
// (six cubes, one per rotation order, each animated in an additive layer that
// accumulates rotation by channel and an override-passthrough layer at 99.39 %).
// Each cube's local vertices (its Geometry node), taken through our evaluated node
// transform at frame 18, land on Maya's within 1e-3 cm.
#include "io_test_util.h"
#include "rotinterp/core/rotation.h"
#include "rotinterp/io/fbx/fbx_curve_eval.h"
#include "rotinterp/io/fbx/fbx_curves.h"
#include "rotinterp/io/fbx/fbx_nodes.h"
#include "rotinterp/io/fbx/fbx_transform.h"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>

namespace rotinterp {
namespace {

const char* const kFbx = "fbx/ufbx_maya_anim_layers_over_acc_orders_7500_ascii.fbx";
const char* const kObj = "curves/ufbx_maya_anim_layers_over_acc_orders_18.obj";
constexpr double kFrame = 18.0, kRate = 24.0;

// Each group's vertices of an OBJ written by Maya: the `v` lines before `g NAME`.
std::map<std::string, std::vector<Vec3>> obj_groups(const std::string& path) {
  std::map<std::string, std::vector<Vec3>> out;
  std::vector<Vec3> pending;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    std::istringstream ss(line);
    std::string tag;
    ss >> tag;
    if (tag == "v") {
      Vec3 v;
      ss >> v.x() >> v.y() >> v.z();
      pending.push_back(v);
    } else if (tag == "g") {
      std::string name;
      ss >> name;
      if (name != "default" && !pending.empty()) out[name] = std::move(pending), pending.clear();
    }
  }
  return out;
}

// Each Model's mesh vertices (its connected Geometry node's Vertices), by model name.
std::map<std::string, std::vector<Vec3>> fbx_mesh_vertices(const FbxDocument& doc, const FbxAnimation& anim) {
  std::map<std::int64_t, const FbxNode*> geometry;
  for (const FbxNode& o : doc.node("Objects")->children)
    if (o.name == "Geometry" && !o.properties.empty()) geometry[o.properties[0].integer] = &o;
  std::map<std::string, std::vector<Vec3>> out;
  for (const FbxNode& c : doc.node("Connections")->children) {
    if (c.properties.size() < 3) continue;
    const auto g = geometry.find(c.properties[1].integer);
    const auto m = std::find_if(anim.models.begin(), anim.models.end(),
                                [&](const FbxModel& x) { return x.id == c.properties[2].integer; });
    if (g == geometry.end() || m == anim.models.end()) continue;
    const std::vector<double> xyz = g->second->child("Vertices")->properties.at(0).as_doubles();
    for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) out[m->name].push_back(Vec3(xyz[i], xyz[i + 1], xyz[i + 2]));
  }
  return out;
}

// The largest distance of a cube's vertices through our transform at frame 18
// from Maya's, over the six cubes.
double worst_vertex_error(const FbxTake& take, const FbxAnimation& anim, const FbxDocument& doc) {
  const auto maya = obj_groups((test::kData / kObj).string());
  const auto local = fbx_mesh_vertices(doc, anim);
  const auto layers = fbx_node_layers(take);
  const double ticks = kFrame / kRate * static_cast<double>(kFbxTicksPerSecond);
  double worst = 0.0;
  std::size_t cubes = 0;
  for (const FbxModel& model : anim.models) {
    EXPECT_EQ(model.parent, 0) << model.name;  // world space = the node's local space
    const auto node = layers.find(model.name);
    const Eigen::Matrix4d m =
        fbx_node_matrix(model, fbx_lcl_values(take, model, node == layers.end() ? nullptr : &node->second, ticks));
    const std::vector<Vec3>& ours = local.at(model.name);
    const std::vector<Vec3>& theirs = maya.at(model.name);
    EXPECT_EQ(ours.size(), theirs.size()) << model.name;
    for (std::size_t v = 0; v < ours.size() && v < theirs.size(); ++v)
      worst = std::max(worst, ((m * ours[v].homogeneous()).head<3>() - theirs[v]).norm());
    ++cubes;
  }
  EXPECT_EQ(cubes, 6u);
  return worst;
}

struct LayeredFile {
  FbxDocument doc;
  FbxAnimation anim;
};
LayeredFile read_layered_file() {
  const std::string path = (test::kData / kFbx).string();
  auto doc = parse_fbx_nodes(test::read_text(path), path);
  EXPECT_TRUE(doc.ok()) << doc.error();
  auto anim = read_fbx_animation(*doc, path);
  EXPECT_TRUE(anim.ok()) << anim.error();
  return {doc.ok() ? *doc : FbxDocument{}, anim.ok() ? *anim : FbxAnimation{}};
}

TEST(FbxLayers, EveryCubeVertexAtFrame18LandsOnMayasWithin1e3Cm) {
  const LayeredFile file = read_layered_file();
  ASSERT_EQ(file.anim.takes.size(), 1u);
  ASSERT_EQ(file.anim.takes[0].layers.size(), 3u);
  const double worst = worst_vertex_error(file.anim.takes[0], file.anim, file.doc);
  std::printf("frame 18: worst vertex %.3g cm from Maya's mesh\n", worst);
  EXPECT_LT(worst, 1e-3);
}

// The check above has teeth: the base layer alone (layers X and Y muted), or
// layer Y applied at full weight, misses Maya's mesh by far more.
TEST(FbxLayers, WithoutTheLayersOrTheirWeightsTheCubesMissMayasMesh) {
  const LayeredFile file = read_layered_file();
  ASSERT_EQ(file.anim.takes.size(), 1u);
  FbxTake base_only = file.anim.takes[0];
  for (std::size_t l = 1; l < base_only.layers.size(); ++l) base_only.layers[l].mute = true;
  EXPECT_GT(worst_vertex_error(base_only, file.anim, file.doc), 1.0);
  FbxTake full_weight = file.anim.takes[0];
  full_weight.layers.at(2).weight = 100.0;
  full_weight.layers.at(2).weight_curve.reset();
  EXPECT_GT(worst_vertex_error(full_weight, file.anim, file.doc), 1e-2);
  FbxTake euler_add = file.anim.takes[0];
  euler_add.layers.at(2).rotation_accumulation = 1;  // blend Euler angles instead of slerping
  EXPECT_GT(worst_vertex_error(euler_add, file.anim, file.doc), 1e-2);
}

// Layer Y's weight is keyed, 0 % at frame 1 to 100 % at frame 20 (a weighted
// Bezier): the file's static 99.39 % is its value at frame 18, where Maya wrote the
// mesh. Elsewhere the keyed weight, not the static one, blends the layer.
TEST(FbxLayers, AKeyedLayerWeightBlendsByItsValueAtEachTime) {
  const LayeredFile file = read_layered_file();
  ASSERT_EQ(file.anim.takes.size(), 1u);
  const FbxTake& take = file.anim.takes[0];
  ASSERT_EQ(take.layers.size(), 3u);
  ASSERT_TRUE(take.layers[2].weight_curve.has_value());
  EXPECT_FALSE(take.layers[1].weight_curve.has_value());
  const FbxCurve& weight = *take.layers[2].weight_curve;
  ASSERT_EQ(weight.keys.size(), 2u);
  const double tick_per_frame = static_cast<double>(kFbxTicksPerSecond) / kRate;
  EXPECT_NEAR(evaluate_fbx_curve(weight, kFrame * tick_per_frame), take.layers[2].weight, 1e-2);  // 1e-4 of its range
  EXPECT_EQ(evaluate_fbx_curve(weight, 1.0 * tick_per_frame), 0.0);

  // Frame 1: the layer at 0 % is the layer muted; frame 10: neither muted nor static.
  FbxTake muted = take, static_weight = take;
  muted.layers[2].mute = true;
  static_weight.layers[2].weight_curve.reset();
  const auto keyed_layers = fbx_node_layers(take), muted_layers = fbx_node_layers(muted),
             static_layers = fbx_node_layers(static_weight);
  std::size_t layered = 0;
  for (const FbxModel& model : file.anim.models) {
    const auto k = keyed_layers.find(model.name);
    if (k == keyed_layers.end()) continue;
    ++layered;
    auto rotation = [&](const FbxTake& t, const FbxNodeLayers& l, double frame) {
      return fbx_node_rotation(model, fbx_lcl_values(t, model, &l, frame * tick_per_frame).rotation);
    };
    const FbxNodeLayers& m = muted_layers.at(model.name);
    const FbxNodeLayers& st = static_layers.at(model.name);
    EXPECT_LT(angular_distance(rotation(take, k->second, 1.0), rotation(muted, m, 1.0)), 1e-12) << model.name;
    EXPECT_GT(angular_distance(rotation(take, k->second, 10.0), rotation(muted, m, 10.0)), 1e-3) << model.name;
    EXPECT_GT(angular_distance(rotation(take, k->second, 10.0), rotation(static_weight, st, 10.0)), 1e-3) << model.name;
  }
  EXPECT_EQ(layered, 6u);
}

// Found by fuzz_read_fbx: key times stored as doubles beyond the range of int64 ticks
// were converted regardless (undefined behaviour); now one line naming the curve.
TEST(FbxLayers, AKeyTimeBeyondTheTickRangeIsOneLineNamingTheCurve) {
  const std::string path = (test::kData / kFbx).string();
  std::string text = test::read_text(path);
  const std::string first_times = "a: 1924423250,38488465000";
  const std::size_t at = text.find(first_times);
  ASSERT_NE(at, std::string::npos);
  for (const char* time : {"5.5e33", "-9.3e18", "nan"}) {
    std::string hostile = text;
    hostile.replace(at, first_times.size(), std::string("a: ") + time + ",38488465000");
    auto doc = parse_fbx_nodes(hostile, "hostile.fbx");
    ASSERT_TRUE(doc.ok()) << doc.error();
    auto anim = read_fbx_animation(*doc, "hostile.fbx");
    ASSERT_FALSE(anim.ok()) << time;
    EXPECT_EQ(anim.error().rfind("hostile.fbx", 0), 0u) << anim.error();
    EXPECT_NE(anim.error().find("key 0 has a time of"), std::string::npos) << anim.error();
    EXPECT_NE(anim.error().find("out of range"), std::string::npos) << anim.error();
    EXPECT_EQ(anim.error().find('\n'), std::string::npos);
  }
}

}  // namespace
}  // namespace rotinterp
