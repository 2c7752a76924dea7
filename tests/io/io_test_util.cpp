#include "io_test_util.h"

#include "rotinterp/io/files/file_record.h"
#include "rotinterp/clip/resample.h"
#include "rotinterp/clip/sampling.h"
#include "rotinterp/core/rotation.h"
#include "rotinterp/io/fbx/fbx_nodes.h"
#include "rotinterp/io/read.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>

namespace rotinterp::test {

namespace fs = std::filesystem;

TempDir::TempDir() {
  std::random_device rd;
  path_ = fs::temp_directory_path() / ("rotinterp_io_test_" + std::to_string(::getpid()) + "_" + std::to_string(rd()));
  fs::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ec;
  fs::remove_all(path_, ec);
}

std::vector<std::string> TempDir::files() const {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(path_)) out.push_back(e.path().filename().string());
  return out;
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary);
  f << text;
}

std::string read_text(const fs::path& path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

FbxAnimation read_fbx_curves(const std::string& path) {
  auto doc = parse_fbx_nodes(read_text(path), path);
  EXPECT_TRUE(doc.ok()) << doc.error();
  if (!doc.ok()) return {};
  auto anim = read_fbx_animation(*doc, path);
  EXPECT_TRUE(anim.ok()) << anim.error();
  return anim.ok() ? *anim : FbxAnimation{};
}

Quat sample(const RotationTrack& track, double t) {
  const auto& ts = track.times;
  if (t <= ts.front()) return track.keys.front();
  if (t >= ts.back()) return track.keys.back();
  const std::size_t hi = static_cast<std::size_t>(std::upper_bound(ts.begin(), ts.end(), t) - ts.begin());
  const double u = (t - ts[hi - 1]) / (ts[hi] - ts[hi - 1]);
  return track.keys[hi - 1].slerp(u, track.keys[hi]).normalized();
}

Vec3 sample(const std::optional<TranslationTrack>& track, const Vec3& offset, double t) {
  if (!track) return offset;
  const auto& ts = track->times;
  if (t <= ts.front()) return track->keys.front();
  if (t >= ts.back()) return track->keys.back();
  const std::size_t hi = static_cast<std::size_t>(std::upper_bound(ts.begin(), ts.end(), t) - ts.begin());
  const double u = (t - ts[hi - 1]) / (ts[hi] - ts[hi - 1]);
  return (1 - u) * track->keys[hi - 1] + u * track->keys[hi];
}

WorldPose pose_at(const Clip& clip, double t) {
  const std::size_t n = clip.skeleton.joints.size();
  std::vector<Quat> r(n);
  std::vector<Vec3> p(n);
  for (std::size_t j = 0; j < n; ++j) {
    r[j] = sample(clip.rotations[j], t);
    p[j] = sample(clip.translations[j], clip.skeleton.joints[j].offset, t);
  }
  WorldPose w;
  forward_kinematics(clip.skeleton, r, p, w);
  return w;
}

Clip cut_take(const std::string& relative, const std::string& fps, double start, double end, const std::string& name) {
  Result<Clip> a = read_clip(kData / relative);
  EXPECT_TRUE(a) << a.error();
  ResampleOptions o;
  o.fps = *parse_rate(fps);
  o.range = TimeRange{start, end};
  Result<Clip> b = resample_clip(*a, o);
  EXPECT_TRUE(b) << b.error();
  b->name = name;
  return *b;
}

double angle_degrees(const Quat& a, const Quat& b) { return angular_distance(a, b) * 180.0 / kPi; }

Clip resample_uniform(const Clip& clip, double frame_time) {
  Clip out = clip;
  out.frame_time = frame_time;
  out.source_record = retimed(clip.source_record);
  const double start = clip.start_time();
  const std::size_t frames = static_cast<std::size_t>(std::floor((clip.end_time() - start) / frame_time + 1e-9)) + 1;
  for (std::size_t j = 0; j < clip.skeleton.joints.size(); ++j) {
    RotationTrack r;
    for (std::size_t k = 0; k < frames; ++k) {
      const double t = start + static_cast<double>(k) * frame_time;
      r.times.push_back(t);
      r.keys.push_back(sample(clip.rotations[j], t));
    }
    r.make_sign_continuous();
    out.rotations[j] = r;
    if (clip.translations[j]) {
      TranslationTrack tt;
      tt.times = r.times;
      for (double t : r.times) tt.keys.push_back(sample(clip.translations[j], Vec3::Zero(), t));
      out.translations[j] = tt;
    }
  }
  return out;
}

double skeleton_size(const Clip& clip) {
  const std::size_t n = clip.skeleton.joints.size();
  std::vector<Quat> r(n);
  std::vector<Vec3> p(n);
  for (std::size_t j = 0; j < n; ++j) {
    r[j] = clip.skeleton.joints[j].rest_rotation;
    p[j] = clip.skeleton.joints[j].offset;
  }
  WorldPose w;
  forward_kinematics(clip.skeleton, r, p, w);
  double size = 0.0;
  for (const Vec3& a : w.position)
    for (const Vec3& b : w.position) size = std::max(size, (a - b).norm());
  return size;
}

}  // namespace rotinterp::test
