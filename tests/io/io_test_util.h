// Helpers shared by the io tests: temp dirs, clip comparison, sampling, FK.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/io/fbx/fbx_curves.h"

#include <filesystem>
#include <string>
#include <vector>

namespace rotinterp::test {

inline const std::filesystem::path kData = ROTINTERP_SHARED_DATA;

// A fresh empty directory under the system temp dir, removed by the destructor.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  // Names of the files in the directory.
  std::vector<std::string> files() const;

 private:
  std::filesystem::path path_;
};

void write_text(const std::filesystem::path& path, const std::string& text);
std::string read_text(const std::filesystem::path& path);

// The animation curves of the FBX file at `path`, read with our node reader; a failure
// is a test failure and gives an empty animation.
FbxAnimation read_fbx_curves(const std::string& path);

// Slerp/lerp of a track at time t (clamped), for tests only.
Quat sample(const RotationTrack& track, double t);
Vec3 sample(const std::optional<TranslationTrack>& track, const Vec3& offset, double t);

// World pose of `clip` at time t.
WorldPose pose_at(const Clip& clip, double t);

// The clip resampled on the grid start + k·frame_time (test-side resampler).
Clip resample_uniform(const Clip& clip, double frame_time);

// Take `name`: the shared clip `relative` (under kData) cut to [start, end] s and
// resampled at `fps` (a rate text: "30", "30000/1001").
Clip cut_take(const std::string& relative, const std::string& fps, double start, double end, const std::string& name);

// The angle between two orientations, degrees.
double angle_degrees(const Quat& a, const Quat& b);

// Largest distance between joint origins over all pairs in the clip's rest pose
// (a skeleton size for relative tolerances).
double skeleton_size(const Clip& clip);

// A DirectX .x scene: a child frame 2 units up (its x axis scaled by `child_x_scale`),
// turned 0°, 90°, 180° about X at ticks 0, 10, 20, with AnimTicksPerSecond 0.
inline std::string zero_rate_x_scene(const std::string& child_x_scale = "1.0") {
  return R"(xof 0302txt 0032
Frame Root {
  FrameTransformMatrix { 1.0,0.0,0.0,0.0, 0.0,1.0,0.0,0.0, 0.0,0.0,1.0,0.0, 0.0,0.0,0.0,1.0;; }
  Frame Child {
    FrameTransformMatrix { )" +
         child_x_scale + R"(,0.0,0.0,0.0, 0.0,1.0,0.0,0.0, 0.0,0.0,1.0,0.0, 0.0,2.0,0.0,1.0;; }
  }
}
AnimTicksPerSecond { 0; }
AnimationSet Wave {
  Animation {
    { Child }
    AnimationKey {
      0;
      3;
      0;4;1.0,0.0,0.0,0.0;;,
      10;4;0.7071068,0.7071068,0.0,0.0;;,
      20;4;0.0,1.0,0.0,0.0;;;
    }
  }
}
)";
}

}  // namespace rotinterp::test
