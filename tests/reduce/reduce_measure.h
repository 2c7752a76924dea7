// Measuring a reduced clip in the reduce tests: every source frame at its exact
// time, and the largest local angle and shell error per joint of a rebuilt motion
// against it, with the eval metrics (clip/metrics.h), not the selection's own code.
#pragma once

#include "rotinterp/clip/frames.h"
#include "rotinterp/clip/metrics.h"

#include <algorithm>
#include <vector>

namespace rotinterp::test {

// Local rotations and translations per joint and frame, [joint][frame].
struct Motion {
  std::vector<std::vector<Quat>> rotation;
  std::vector<std::vector<Vec3>> translation;
};

// The largest local angle and shell error of `test` against the source at every frame,
// measured with the eval metrics: rotation_error and forward kinematics + accumulate_pose_error.
struct Measured {
  std::vector<double> angle;  // per joint, rad
  std::vector<double> shell;  // per joint, clip units
};
inline Measured measure(const Clip& source, const DenseClip& ref, const Motion& test, double shell_distance) {
  const std::size_t n = source.skeleton.joints.size(), frames = ref.grid.size();
  Measured m;
  std::vector<double> scratch;
  const std::vector<Vec3> axes = bone_axes(source.skeleton);
  for (std::size_t j = 0; j < n; ++j)
    m.angle.push_back(rotation_error(ref.rotation[j].data(), test.rotation[j].data(), frames, axes[j], scratch).angle.max);
  PoseError acc = make_pose_error(source.skeleton);
  std::vector<Quat> qr(n), qt(n);
  std::vector<Vec3> tr(n), tt(n);
  WorldPose wr, wt;
  for (std::size_t f = 0; f < frames; ++f) {
    for (std::size_t j = 0; j < n; ++j) {
      qr[j] = ref.rotation[j][f];
      tr[j] = ref.translation[j][f];
      qt[j] = test.rotation[j][f];
      tt[j] = test.translation[j][f];
    }
    forward_kinematics(source.skeleton, qr, tr, wr);
    forward_kinematics(source.skeleton, qt, tt, wt);
    accumulate_pose_error(wr, wt, shell_distance, acc);
  }
  for (const RunningError& e : acc.joint_shell) m.shell.push_back(e.max);
  return m;
}

inline double max_of(const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); }

}  // namespace rotinterp::test
