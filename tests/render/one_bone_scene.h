// The renderer tests' smallest scene: one bone, seen from the front.
#pragma once

#include "rotinterp/render/renderer.h"

namespace rotinterp::test {

// A two-joint skeleton: one bone from (0,0,0) to (1,0,0), seen from the front.
inline render::Scene one_bone_scene() {
  render::Scene scene;
  Joint root;
  root.name = "Root";
  Joint tip;
  tip.name = "Tip";
  tip.parent = 0;
  tip.offset = Vec3(1, 0, 0);
  scene.skeleton.joints = {root, tip};
  scene.bounds.extend(Vec3(-0.1, -0.3, -0.1));
  scene.bounds.extend(Vec3(1.1, 0.3, 0.1));
  scene.bone_radius = 0.08;
  scene.view.azimuth_deg = 0.0;
  scene.view.elevation_deg = 0.0;
  return scene;
}

}  // namespace rotinterp::test
