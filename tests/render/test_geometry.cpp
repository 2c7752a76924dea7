// What the renderer draws, computed without GL: unit meshes, the instances of a
// pose and of a trail, line lists and the bone radius.
#include "synthetic_clip.h"

#include "rotinterp/render/geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace rotinterp::render {
namespace {

Eigen::Matrix4d model(const Instance& in) {
  return Eigen::Map<const Eigen::Matrix4f>(in.model).cast<double>();
}
Vec3 apply(const Instance& in, const Vec3& p) { return (model(in) * p.homogeneous()).head<3>(); }
// A cylinder instance's two ends: its unit mesh runs from z = 0 to z = 1.
Vec3 start(const Instance& in) { return apply(in, Vec3::Zero()); }
Vec3 end(const Instance& in) { return apply(in, Vec3::UnitZ()); }
// The radius across the cylinder (x of the unit mesh), or a sphere's radius.
double radius(const Instance& in) { return (apply(in, Vec3::UnitX()) - apply(in, Vec3::Zero())).norm(); }

WorldPose first_frame(const Clip& clip) {
  std::vector<Quat> local;
  std::vector<Vec3> translation;
  for (std::size_t j = 0; j < clip.skeleton.joints.size(); ++j) {
    local.push_back(clip.rotations[j].keys[0]);
    translation.push_back(clip.skeleton.joints[j].offset);
  }
  WorldPose pose;
  forward_kinematics(clip.skeleton, local, translation, pose);
  return pose;
}

constexpr Colour kRed = {1.0f, 0.0f, 0.0f};

TEST(Geometry, CylinderMeshIsTheUnitTubeAlongZ) {
  const MeshData m = cylinder_mesh(10);
  ASSERT_EQ(m.vertices.size(), 11u * 2 * 6);
  ASSERT_EQ(m.indices.size(), 10u * 6);
  for (std::size_t v = 0; v < m.vertices.size(); v += 6) {
    const Vec3 p(m.vertices[v], m.vertices[v + 1], m.vertices[v + 2]);
    const Vec3 n(m.vertices[v + 3], m.vertices[v + 4], m.vertices[v + 5]);
    EXPECT_NEAR(std::hypot(p.x(), p.y()), 1.0, 1e-6);
    EXPECT_TRUE(p.z() == 0.0 || p.z() == 1.0);
    EXPECT_NEAR((n - Vec3(p.x(), p.y(), 0)).norm(), 0.0, 1e-6) << "normals point away from the axis";
  }
  for (unsigned i : m.indices) EXPECT_LT(i, m.vertices.size() / 6);
}

TEST(Geometry, SphereMeshIsTheUnitSphereWithOutwardNormals) {
  const MeshData m = sphere_mesh(10, 6);
  ASSERT_EQ(m.vertices.size(), 11u * 7 * 6);
  ASSERT_EQ(m.indices.size(), 10u * 6 * 6);
  for (std::size_t v = 0; v < m.vertices.size(); v += 6) {
    const Vec3 p(m.vertices[v], m.vertices[v + 1], m.vertices[v + 2]);
    const Vec3 n(m.vertices[v + 3], m.vertices[v + 4], m.vertices[v + 5]);
    EXPECT_NEAR(p.norm(), 1.0, 1e-6);
    EXPECT_NEAR((n - p).norm(), 0.0, 1e-7);
  }
  for (unsigned i : m.indices) EXPECT_LT(i, m.vertices.size() / 6);
}

TEST(Geometry, APoseGivesASphereAtEveryJointAndEndSiteAndACylinderPerBone) {
  const Clip clip = test::synthetic_clip();
  const Skeleton& s = clip.skeleton;
  const WorldPose pose = first_frame(clip);
  Batch batch;
  add_pose(s, pose, 0.02, kRed, 0.5f, batch);
  const std::size_t joints = s.joints.size(), end_sites = s.end_sites.size();
  ASSERT_EQ(batch.spheres.size(), joints + end_sites);
  ASSERT_EQ(batch.cylinders.size(), joints - 1 + end_sites);  // one root

  // Bones in the order of the joints, then of the End Sites: parent → child.
  std::vector<std::pair<Vec3, Vec3>> bones;
  for (std::size_t j = 0; j < joints; ++j)
    if (s.joints[j].parent >= 0) bones.emplace_back(pose.position[static_cast<std::size_t>(s.joints[j].parent)], pose.position[j]);
  for (std::size_t e = 0; e < end_sites; ++e)
    bones.emplace_back(pose.position[static_cast<std::size_t>(s.end_sites[e].parent)], pose.end_site_position[e]);
  for (std::size_t i = 0; i < bones.size(); ++i) {
    const Instance& c = batch.cylinders[i];
    EXPECT_LT((start(c) - bones[i].first).norm(), 1e-5) << "bone " << i;
    EXPECT_LT((end(c) - bones[i].second).norm(), 1e-5) << "bone " << i;
    EXPECT_NEAR(radius(c), 0.02, 1e-6);
  }
  for (std::size_t j = 0; j < joints + end_sites; ++j) {
    const Vec3 centre = j < joints ? pose.position[j] : pose.end_site_position[j - joints];
    EXPECT_LT((apply(batch.spheres[j], Vec3::Zero()) - centre).norm(), 1e-5);
    EXPECT_NEAR(radius(batch.spheres[j]), 0.02, 1e-6);
  }
  for (const auto* list : {&batch.cylinders, &batch.spheres})
    for (const Instance& in : *list) {
      EXPECT_EQ(in.colour[0], 1.0f);
      EXPECT_EQ(in.colour[1], 0.0f);
      EXPECT_EQ(in.colour[3], 0.5f);
    }
}

TEST(Geometry, APoseThatDoesNotMatchTheSkeletonDrawsNothingAndZeroLengthBonesAreSkipped) {
  const Clip clip = test::synthetic_clip();
  const WorldPose pose = first_frame(clip);
  Batch batch;
  WorldPose short_pose = pose;
  short_pose.position.pop_back();
  add_pose(clip.skeleton, short_pose, 0.02, kRed, 1.0f, batch);
  EXPECT_TRUE(batch.spheres.empty());
  EXPECT_TRUE(batch.cylinders.empty());

  WorldPose no_end_sites = pose;
  no_end_sites.end_site_position.clear();
  add_pose(clip.skeleton, no_end_sites, 0.02, kRed, 1.0f, batch);
  EXPECT_EQ(batch.spheres.size(), clip.skeleton.joints.size());
  EXPECT_EQ(batch.cylinders.size(), clip.skeleton.joints.size() - 1);

  batch.clear();
  EXPECT_TRUE(batch.spheres.empty() && batch.cylinders.empty());
  WorldPose collapsed = no_end_sites;
  collapsed.position[1] = collapsed.position[0];  // Spine on Hips
  add_pose(clip.skeleton, collapsed, 0.02, kRed, 1.0f, batch);
  EXPECT_EQ(batch.cylinders.size(), clip.skeleton.joints.size() - 2);
}

TEST(Geometry, ACurveIsATubeThroughItsPointsOnTheUnitSphere) {
  std::vector<Vec3> points;
  for (int i = 0; i <= 10; ++i) points.push_back(3.0 * Vec3(std::cos(0.1 * i), std::sin(0.1 * i), 0.5));
  Batch batch;
  add_curve(points, 3, 0.01, kRed, 1.0f, batch);
  // Points 0, 3, 6, 9 and the last, 10.
  const std::vector<std::size_t> used = {0, 3, 6, 9, 10};
  ASSERT_EQ(batch.spheres.size(), used.size());
  ASSERT_EQ(batch.cylinders.size(), used.size() - 1);
  for (std::size_t i = 0; i < used.size(); ++i) {
    const Vec3 on_sphere = points[used[i]].normalized();
    EXPECT_LT((apply(batch.spheres[i], Vec3::Zero()) - on_sphere).norm(), 1e-6) << "point " << used[i];
    if (i > 0) {
      EXPECT_LT((start(batch.cylinders[i - 1]) - points[used[i - 1]].normalized()).norm(), 1e-6);
      EXPECT_LT((end(batch.cylinders[i - 1]) - on_sphere).norm(), 1e-6);
    }
  }
  batch.clear();
  add_curve({}, 1, 0.01, kRed, 1.0f, batch);
  EXPECT_TRUE(batch.spheres.empty());
}

Trail arc(std::size_t n) {
  Trail t;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 0.5 * static_cast<double>(i) / static_cast<double>(n);
    t.reference.push_back(Vec3(std::sin(a), 0.2, std::cos(a)));
    t.method.push_back(Vec3(std::sin(a), 0.25, std::cos(a)));
  }
  return t;
}

TEST(Geometry, ATrailMarksKeysAndTheCurrentSampleAndScalesWithTheZoom) {
  Trail t = arc(20);
  t.keys = {0, 5, 10, 99};  // 99 is past the end: not marked
  t.current = 7;
  Batch solid, translucent;
  trail_figure(t, kRed, 0.5, solid, translucent);
  // The method: 20 tube spheres, 3 keys, the current sample.
  ASSERT_EQ(solid.spheres.size(), 20u + 3 + 1);
  ASSERT_EQ(solid.cylinders.size(), 19u);
  EXPECT_NEAR(radius(solid.cylinders[0]), 0.5 * kTrailMethodRadius, 1e-7);
  EXPECT_NEAR(radius(solid.spheres[20]), 0.5 * kTrailKeyRadius, 1e-7);
  const Instance& current = solid.spheres.back();
  EXPECT_NEAR(radius(current), 0.5 * kTrailCurrentRadius, 1e-7);
  EXPECT_LT((apply(current, Vec3::Zero()) - t.method[7].normalized()).norm(), 1e-6);
  // The reference: translucent, its tube and a larger current marker.
  ASSERT_EQ(translucent.spheres.size(), 20u + 1);
  EXPECT_NEAR(radius(translucent.cylinders[0]), 0.5 * kTrailReferenceRadius, 1e-7);
  EXPECT_GT(radius(translucent.spheres.back()), radius(current));
  EXPECT_LT((apply(translucent.spheres.back(), Vec3::Zero()) - t.reference[7].normalized()).norm(), 1e-6);
  for (const Instance& in : translucent.spheres) EXPECT_LT(in.colour[3], 1.0f);

  t.keys.assign(kMaxKeyMarkers + 1, 3);  // too many keys: none marked
  trail_figure(t, kRed, 0.5, solid, translucent);
  EXPECT_EQ(solid.spheres.size(), 20u + 1);
}

TEST(Geometry, LongTrailsAreDrawnWithAStride) {
  const Trail t = arc(3 * kMaxTrailSegments);
  Batch solid, translucent;
  trail_figure(t, kRed, 1.0, solid, translucent);
  EXPECT_LE(translucent.cylinders.size(), kMaxTrailSegments);
  EXPECT_LE(solid.cylinders.size(), kMaxTrailSegments);
  EXPECT_GE(solid.cylinders.size(), kMaxTrailSegments - 1);
}

TEST(Geometry, GridLinesLieOnTheFloorAtTheGridSteps) {
  Bounds b;
  b.extend(Vec3(-0.3, 0.02, -1.7));
  b.extend(Vec3(0.4, 1.8, 2.9));
  const GroundGrid g = ground_grid(b);
  const LineList lines = grid_lines(b);
  const auto along_x = static_cast<std::size_t>(std::lround((g.x1 - g.x0) / g.step)) + 1;
  const auto along_z = static_cast<std::size_t>(std::lround((g.z1 - g.z0) / g.step)) + 1;
  ASSERT_EQ(lines.size(), (along_x + along_z) * 2 * 7);
  for (std::size_t v = 0; v < lines.size(); v += 7) {
    EXPECT_FLOAT_EQ(lines[v + 1], static_cast<float>(g.y));
    EXPECT_GE(lines[v], g.x0 - 1e-6);
    EXPECT_LE(lines[v], g.x1 + 1e-6);
    EXPECT_GE(lines[v + 2], g.z0 - 1e-6);
    EXPECT_LE(lines[v + 2], g.z1 + 1e-6);
    EXPECT_EQ(lines[v + 6], 1.0f);
  }
}

TEST(Geometry, SphereWireframeIsOnTheUnitSphere) {
  const LineList lines = sphere_wireframe();
  ASSERT_EQ(lines.size(), (5u + 6u) * 48 * 2 * 7);  // 5 parallels, 6 meridians
  for (std::size_t v = 0; v < lines.size(); v += 7)
    EXPECT_NEAR(Vec3(lines[v], lines[v + 1], lines[v + 2]).norm(), 1.0, 1e-6);
}

TEST(Geometry, BoneRadiusIsATenthOfTheMedianBoneWithinTheDiagonalsBounds) {
  const Clip clip = test::synthetic_clip();
  Bounds b;
  b.extend(Vec3(-1, 0, -1));
  b.extend(Vec3(1, 2, 1));  // diagonal √12 ≈ 3.46: clamp to [0.0139, 0.0693]
  // Bone lengths: 0.112 ×2, 0.15, 0.234 ×2, 0.25 ×5, 0.28 ×2, 0.45 ×2, 0.453 ×2; median 0.25.
  EXPECT_NEAR(scene_bone_radius(clip.skeleton, b), 0.025, 1e-12);
  Bounds huge;
  huge.extend(Vec3(-100, 0, -100));
  huge.extend(Vec3(100, 200, 100));
  EXPECT_NEAR(scene_bone_radius(clip.skeleton, huge), 0.004 * huge.size().norm(), 1e-12);
  EXPECT_NEAR(scene_bone_radius(Skeleton{}, b), 0.01 * b.size().norm(), 1e-12);
}

}  // namespace
}  // namespace rotinterp::render
