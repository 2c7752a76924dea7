// FBX reading and the writers: helper folding is exact, FBX → clip →
// FBX/glTF/GLB/Collada → clip keeps every orientation, FBX → BVH keeps world
// joint positions.
#include "io_test_util.h"
#include "rotinterp/io/info.h"
#include "rotinterp/io/read.h"
#include "rotinterp/io/write.h"

#include <gtest/gtest.h>

namespace rotinterp {
namespace {

using test::kData;
constexpr double kDeg = kPi / 180.0;

// All key times of a clip's rotation tracks.
std::vector<double> key_times(const Clip& c) {
  std::vector<double> t;
  for (const auto& r : c.rotations) t.insert(t.end(), r.times.begin(), r.times.end());
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end(), [](double a, double b) { return std::abs(a - b) < 1e-9; }), t.end());
  return t;
}

struct Differences {
  double local_angle = 0.0;  // radians, local rotations of same-named joints
  double world_angle = 0.0;  // radians
  double world_position = 0.0;
  std::size_t compared_joints = 0;
};

// The root ancestor of joint j.
int root_of(const Skeleton& s, int j) {
  while (s.joints[static_cast<std::size_t>(j)].parent >= 0) j = s.joints[static_cast<std::size_t>(j)].parent;
  return j;
}

// Compares b against a at a's key times, joints matched by name (only the joints
// under the root named `only_under`, when given).
Differences compare(const Clip& a, const Clip& b, const std::string& only_under = "") {
  Differences d;
  std::vector<int> map(a.skeleton.joints.size(), -1);
  for (std::size_t j = 0; j < a.skeleton.joints.size(); ++j) {
    if (!only_under.empty() && a.skeleton.joints[static_cast<std::size_t>(root_of(a.skeleton, static_cast<int>(j)))].name != only_under)
      continue;
    map[j] = b.skeleton.find(a.skeleton.joints[j].name);
    if (map[j] >= 0) ++d.compared_joints;
  }
  // b's positions in a's units: the same size in metres (a glTF is written in
  // metres, whatever the source's unit).
  const double b_in_a_units = b.unit.metres_per_unit / a.unit.metres_per_unit;
  for (double t : key_times(a)) {
    const WorldPose pa = test::pose_at(a, t), pb = test::pose_at(b, t);
    for (std::size_t j = 0; j < map.size(); ++j) {
      if (map[j] < 0) continue;
      const auto k = static_cast<std::size_t>(map[j]);
      d.local_angle = std::max(d.local_angle, angular_distance(test::sample(a.rotations[j], t), test::sample(b.rotations[k], t)));
      d.world_angle = std::max(d.world_angle, angular_distance(pa.rotation[j], pb.rotation[k]));
      d.world_position = std::max(d.world_position, (pa.position[j] - pb.position[k] * b_in_a_units).norm());
    }
  }
  return d;
}

// Where assimp's own pivot removal (AI_CONFIG_IMPORT_FBX_PRESERVE_PIVOTS off) is
// right — static pre-rotation and translation helpers, no channel orphaned — the
// folded helpers give the same world poses. Only the skeleton under "Root" is
// compared for the DigitalRune marines: their IK locators (L_FOOT, R_FOOT) carry
// FBX geometric translations, which assimp's pivot removal applies to the nodes
// and their children; folding drops them, as FBX defines them for geometry only.
TEST(Fbx, FoldingStaticHelpersGivesTheWorldPosesOfAssimpsPivotRemoval) {
  const struct {
    const char* file;
    const char* root;
    std::size_t joints;
  } cases[] = {{"digitalrune_Marine_Run.fbx", "Root", 26},
               {"digitalrune_PlayerMarine_Idle.fbx", "Root", 26},
               {"digitalrune_Dude.fbx", "", 58}};
  for (const auto& c : cases) {
    Result<ClipFileInfo> folded = inspect_clip(kData / "fbx" / c.file);
    ASSERT_TRUE(folded) << folded.error();
    EXPECT_GT(folded->folded_helpers, 0u) << c.file;
    ReadOptions by_assimp;
    by_assimp.fold_fbx_helpers = false;
    Result<ClipFileInfo> plain = inspect_clip(kData / "fbx" / c.file, by_assimp);
    ASSERT_TRUE(plain) << plain.error();
    EXPECT_EQ(plain->folded_helpers, 0u);
    const Differences d = compare(plain->clip, folded->clip, c.root);
    EXPECT_EQ(d.compared_joints, c.joints) << c.file;
    const double size = test::skeleton_size(plain->clip);
    EXPECT_LE(d.world_angle, 1e-4 * kDeg) << c.file << ": " << d.world_angle / kDeg;
    EXPECT_LE(d.world_position, 1e-6 * size) << c.file << ": " << d.world_position << " of " << size;
    std::printf("[ %s ] %zu helpers folded: world angle %.3g deg, world position %.3g (size %.3g)\n", c.file,
                folded->folded_helpers, d.world_angle / kDeg, d.world_position, size);
  }
}

// An animated joint under a PreRotation helper and no pivots: FBX's local rotation is
// PreRotation · Lcl Rotation, once. assimp 5.2.5 multiplies the PreRotation into the
// joint's keys and, keeping pivots, also leaves it in a helper node above the joint;
// its pivot removal gets it right (the channel replaces the node's transform).
// Folding used to compose both, 90° off at every key (Blender's import, and the
// file's own curves, say 90° + curve once: FbxSource.*).
TEST(Fbx, FoldingCountsThePreRotationOfAnAnimatedJointOnce) {
  const auto path = kData / "fbx" / "ufbx_maya_game_sausage_7500_binary_wiggle.fbx";
  Result<Clip> folded = read_clip(path);
  ASSERT_TRUE(folded) << folded.error();
  ReadOptions by_assimp;
  by_assimp.fold_fbx_helpers = false;
  Result<Clip> plain = read_clip(path, by_assimp);
  ASSERT_TRUE(plain) << plain.error();
  const int j = folded->skeleton.find("joint1");
  ASSERT_GE(j, 0);
  const auto& fk = folded->rotations[static_cast<std::size_t>(j)];
  const auto& pk = plain->rotations[static_cast<std::size_t>(plain->skeleton.find("joint1"))];
  ASSERT_EQ(fk.keys.size(), 20u);
  ASSERT_EQ(pk.keys.size(), fk.keys.size());
  for (std::size_t k = 0; k < fk.keys.size(); ++k)
    EXPECT_LE(angular_distance(fk.keys[k], pk.keys[k]), 1e-5 * kDeg) << "key " << k;
  // The second key: the Z curve reads −43.639° there, so 46.361° about Z in all.
  const Quat expected(Eigen::AngleAxisd((90.0 - 43.639) * kDeg, Vec3::UnitZ()));
  EXPECT_LE(angular_distance(fk.keys[1], expected), 1e-3 * kDeg);
}

// On Xbox Jump assimp's pivot removal orphans 62 channels (their motion is lost);
// folding keeps it: the two readings differ, and the folded one moves those joints.
TEST(Fbx, FoldingKeepsMotionAssimpsPivotRemovalLoses) {
  const auto path = kData / "fbx" / "digitalrune_XboxAvatars_Jump.fbx";
  Result<ClipFileInfo> folded = inspect_clip(path);
  ASSERT_TRUE(folded) << folded.error();
  EXPECT_GT(folded->folded_helpers, 0u);
  const int base = folded->clip.skeleton.find("Base_Control");
  ASSERT_GE(base, 0);
  EXPECT_GT(folded->clip.rotations[static_cast<std::size_t>(base)].keys.size(), 1u);  // animated through its helpers
  ReadOptions by_assimp;
  by_assimp.fold_fbx_helpers = false;
  Result<Clip> plain = read_clip(path, by_assimp);
  ASSERT_TRUE(plain) << plain.error();
  const int base_plain = plain->skeleton.find("Base_Control");
  if (base_plain >= 0) {
    EXPECT_EQ(plain->rotations[static_cast<std::size_t>(base_plain)].keys.size(), 1u);
  }
}

// Every writable format's round trip: tests/io/test_format_contract.cpp.

// FBX → BVH (rest rotations baked into the BVH rotations): world joint positions
// unchanged within 1e-3 of the skeleton's size, for every order of --bvh-order.
TEST(Fbx, ToBvhKeepsWorldJointPositions) {
  const struct {
    const char* file;
    double frame_time;  // the source's, or 1/30 s where its keys have no uniform grid
  } cases[] = {{"digitalrune_Marine_Run.fbx", 0}, {"digitalrune_Dude.fbx", 1.0 / 30}, {"assimp_huesitos.fbx", 0},
               {"ufbx_maya_kenney_character_7700_binary.fbx", 0}};
  for (const auto& c : cases) {
    Result<Clip> a = read_clip(kData / "fbx" / c.file);
    ASSERT_TRUE(a) << a.error();
    const Clip uniform = test::resample_uniform(*a, c.frame_time > 0 ? c.frame_time : a->frame_time);
    const double size = test::skeleton_size(uniform);
    ASSERT_GT(size, 0.0);
    test::TempDir dir;
    for (const char* order : {"ZXY", "XYZ", "YZX"}) {
      WriteOptions w;
      w.bvh_order = order;
      const Status s = write_clip(uniform, dir / "out.bvh", w);
      ASSERT_TRUE(s) << s.error();
      Result<Clip> b = read_clip(dir / "out.bvh");
      ASSERT_TRUE(b) << b.error();
      // Several roots get one synthetic root above them (see below).
      const std::size_t shift = b->skeleton.joints.size() - uniform.skeleton.joints.size();
      ASSERT_LE(shift, 1u);
      double worst = 0.0;
      for (std::size_t f = 0; f < uniform.frame_count(); ++f) {
        const double t = uniform.start_time() + static_cast<double>(f) * uniform.frame_time;
        const WorldPose pa = test::pose_at(uniform, t), pb = test::pose_at(*b, t - uniform.start_time());
        for (std::size_t j = 0; j < pa.position.size(); ++j)
          worst = std::max(worst, (pa.position[j] - pb.position[j + shift]).norm());
      }
      EXPECT_LE(worst, 1e-3 * size) << c.file << " " << order << ": " << worst << " of " << size;
      std::printf("[ %s -> bvh %s ] worst joint position %.3g (skeleton size %.3g)\n", c.file, order, worst, size);
    }
  }
}

// A clip that is not on a uniform grid is refused by the BVH writer, nothing written.
TEST(Fbx, ToBvhWithoutResamplingIsRefusedAndWritesNothing) {
  Result<Clip> a = read_clip(kData / "fbx" / "digitalrune_Marine_Run.fbx");
  ASSERT_TRUE(a) << a.error();
  test::TempDir dir;
  const Status s = write_clip(*a, dir / "out.bvh");
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().find("resample first"), std::string::npos) << s.error();
  EXPECT_TRUE(dir.files().empty());
}

// Unit scale and tick rates as the files say.
TEST(Fbx, ReportsUnitScaleAndFrameRate) {
  Result<Clip> cm = read_clip(kData / "fbx" / "assimp_huesitos.fbx");
  ASSERT_TRUE(cm) << cm.error();
  EXPECT_DOUBLE_EQ(cm->unit.metres_per_unit, 0.01);
  EXPECT_EQ(cm->unit.origin, UnitOrigin::declared);
  EXPECT_DOUBLE_EQ(cm->frame_time, 1.0 / 25.0);
  Result<Clip> inch = read_clip(kData / "fbx" / "digitalrune_XboxAvatars_Jump.fbx");
  ASSERT_TRUE(inch) << inch.error();
  EXPECT_NEAR(inch->unit.metres_per_unit, 0.0254, 1e-7);
  // Its take spans LocalStart..LocalStop: the key 1 tick before LocalStart shapes the
  // curves but is no frame (it was one, at t = −1 tick).
  EXPECT_EQ(inch->start_time(), 0.0);
}

}  // namespace
}  // namespace rotinterp

namespace rotinterp {
namespace {

// Marine_Run has three roots (Root, L_FOOT, R_FOOT): the BVH has one ROOT, a
// synthetic joint at the origin above them, and every joint keeps its world pose.
TEST(Fbx, SeveralRootsAreWrittenAsBvhUnderOneSyntheticRoot) {
  Result<Clip> a = read_clip(test::kData / "fbx" / "digitalrune_Marine_Run.fbx");
  ASSERT_TRUE(a) << a.error();
  const Clip uniform = test::resample_uniform(*a, a->frame_time);
  test::TempDir dir;
  ASSERT_TRUE(write_clip(uniform, dir / "out.bvh"));
  const std::string text = test::read_text(dir / "out.bvh");
  EXPECT_EQ(text.find("ROOT "), text.rfind("ROOT "));
  EXPECT_EQ(text.find("ROOT rotinterp_root\n{\n\tOFFSET 0 0 0\n"), 10u);  // right after "HIERARCHY\n"
  Result<Clip> b = read_clip(dir / "out.bvh");
  ASSERT_TRUE(b) << b.error();
  ASSERT_EQ(b->skeleton.joints.size(), uniform.skeleton.joints.size() + 1);
  EXPECT_EQ(b->skeleton.joints[0].name, "rotinterp_root");
  double worst = 0.0;
  for (std::size_t f = 0; f < uniform.frame_count(); ++f) {
    const double t = uniform.start_time() + static_cast<double>(f) * uniform.frame_time;
    const WorldPose pa = test::pose_at(uniform, t), pb = test::pose_at(*b, t - uniform.start_time());
    for (std::size_t j = 0; j < pa.position.size(); ++j) {
      const int k = b->skeleton.find(uniform.skeleton.joints[j].name);
      ASSERT_GE(k, 1);
      worst = std::max(worst, (pa.position[j] - pb.position[static_cast<std::size_t>(k)]).norm());
    }
  }
  EXPECT_LE(worst, 1e-5 * test::skeleton_size(uniform));
}

}  // namespace
}  // namespace rotinterp
