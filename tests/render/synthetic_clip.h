// A small synthetic clip for the renderer tests: a 13-joint stick figure (Y up,
// facing +Z) whose arms swing and whose left elbow bends with known sinusoids;
// with `speed` (units/s) its root travels along +X.
#pragma once

#include "rotinterp/clip/clip.h"

#include <cmath>
#include <string>

namespace rotinterp::test {

inline Clip synthetic_clip(int frames = 61, double rate = 30.0, double speed = 0.0) {
  Clip clip;
  clip.name = "synthetic";
  clip.frame_time = 1.0 / rate;
  clip.source_format = "test";
  auto add = [&](const std::string& name, int parent, Vec3 offset) {
    Joint j;
    j.name = name;
    j.parent = parent;
    j.offset = offset;
    clip.skeleton.joints.push_back(j);
    return static_cast<int>(clip.skeleton.joints.size()) - 1;
  };
  const int hips = add("Hips", -1, Vec3(0, 0.95, 0));
  const int spine = add("Spine", hips, Vec3(0, 0.25, 0));
  const int chest = add("Chest", spine, Vec3(0, 0.25, 0));
  add("Head", chest, Vec3(0, 0.25, 0));
  const int lsh = add("LeftShoulder", chest, Vec3(0.18, 0.15, 0));
  const int lel = add("LeftElbow", lsh, Vec3(0.28, 0, 0));
  add("LeftHand", lel, Vec3(0.25, 0, 0));
  const int rsh = add("RightShoulder", chest, Vec3(-0.18, 0.15, 0));
  const int rel = add("RightElbow", rsh, Vec3(-0.28, 0, 0));
  add("RightHand", rel, Vec3(-0.25, 0, 0));
  const int lhip = add("LeftHip", hips, Vec3(0.1, -0.05, 0));
  add("LeftKnee", lhip, Vec3(0, -0.45, 0));
  const int rhip = add("RightHip", hips, Vec3(-0.1, -0.05, 0));
  add("RightKnee", rhip, Vec3(0, -0.45, 0));
  EndSite head_top{3, Vec3(0, 0.15, 0), "EndSite_Head"};
  EndSite lfoot{11, Vec3(0, -0.45, 0.05), "EndSite_LeftKnee"};
  EndSite rfoot{13, Vec3(0, -0.45, 0.05), "EndSite_RightKnee"};
  clip.skeleton.end_sites = {head_top, lfoot, rfoot};

  const std::size_t n = clip.skeleton.joints.size();
  clip.rotations.resize(n);
  clip.translations.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    RotationTrack& track = clip.rotations[j];
    for (int f = 0; f < frames; ++f) {
      const double t = f * clip.frame_time;
      const double phase = kTwoPi * t / ((frames - 1) * clip.frame_time);  // one cycle over the clip
      Quat q = Quat::Identity();
      const std::string& name = clip.skeleton.joints[j].name;
      if (name == "LeftShoulder") q = exp(RotVec(0, 0.3 * std::sin(phase), 1.1 * std::sin(phase) - 0.4));
      if (name == "RightShoulder") q = exp(RotVec(0.6 * std::sin(2 * phase), 0, 0.5 + 0.5 * std::cos(phase)));
      if (name == "LeftElbow") q = exp(RotVec(0, 1.2 * (1 - std::cos(3 * phase)), 0));
      if (name == "Spine") q = exp(RotVec(0, 0.35 * std::sin(phase), 0));
      if (name == "LeftHip") q = exp(RotVec(0.5 * std::sin(phase), 0, 0));
      if (name == "RightHip") q = exp(RotVec(-0.5 * std::sin(phase), 0, 0));
      track.times.push_back(t);
      track.keys.push_back(q);
    }
    track.make_sign_continuous();
  }
  if (speed != 0.0) {
    TranslationTrack root;
    for (int f = 0; f < frames; ++f) {
      root.times.push_back(f * clip.frame_time);
      root.keys.push_back(clip.skeleton.joints[0].offset + Vec3(speed * f * clip.frame_time, 0, 0));
    }
    clip.translations[0] = root;
  }
  return clip;
}

}  // namespace rotinterp::test
