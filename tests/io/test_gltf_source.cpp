// `source` for glTF (io/gltf/gltf_source.h): the file's samplers, read by our own reader and
// evaluated as the glTF 2.0 spec's Appendix C defines them, checked against the spec's
// formulas written out here, independently of the library, and against assimp's keys.
#include "gltf_fixture.h"
#include "io_test_util.h"
#include "rotinterp/io/gltf/gltf_source.h"
#include "rotinterp/io/source_motion.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace rotinterp {
namespace {

using test::FixtureSampler;

// ---- The spec's formulas, on plain arrays (x, y, z, w as stored) ----

std::vector<double> element(const FixtureSampler& s, std::size_t width, std::size_t k, std::size_t which) {
  const std::size_t at = s.interpolation == "CUBICSPLINE" ? (3 * k + which) * width : k * width;
  return {s.values.begin() + static_cast<long>(at), s.values.begin() + static_cast<long>(at + width)};
}
std::vector<double> normalized(std::vector<double> v) {
  double n = 0;
  for (double x : v) n += x * x;
  for (double& x : v) x /= std::sqrt(n);
  return v;
}

// The spec's value of sampler `s` at time t: clamped outside the keys; STEP holds vₖ;
// LINEAR: lerp, or for rotations a = acos|vₖ·vₖ₊₁|, s = sign(vₖ·vₖ₊₁),
// v = sin(a(1−u))/sin(a)·vₖ + s·sin(a·u)/sin(a)·vₖ₊₁; CUBICSPLINE: Hermite with
// m₀ = Δ·bₖ, m₁ = Δ·aₖ₊₁, then a rotation normalized.
std::vector<double> spec_value(const FixtureSampler& s, double t) {
  const bool rotation = s.path == "rotation";
  const std::size_t width = rotation ? 4 : 3, n = s.times.size();
  const std::size_t mid = s.interpolation == "CUBICSPLINE" ? 1 : 0;
  auto value = [&](std::size_t k) { return rotation ? normalized(element(s, width, k, mid)) : element(s, width, k, mid); };
  if (t <= s.times.front()) return value(0);
  if (t >= s.times.back()) return value(n - 1);
  std::size_t k = 0;
  while (!(t < s.times[k + 1])) ++k;
  const double dt = s.times[k + 1] - s.times[k], u = (t - s.times[k]) / dt;
  if (s.interpolation == "STEP") return value(k);
  std::vector<double> out(width);
  if (s.interpolation == "LINEAR") {
    const std::vector<double> a = value(k), b = value(k + 1);
    if (!rotation) {
      for (std::size_t c = 0; c < width; ++c) out[c] = (1 - u) * a[c] + u * b[c];
      return out;
    }
    double d = 0;
    for (std::size_t c = 0; c < 4; ++c) d += a[c] * b[c];
    const double angle = std::acos(std::min(1.0, std::abs(d))), sign = d < 0 ? -1.0 : 1.0;
    for (std::size_t c = 0; c < 4; ++c)
      out[c] = angle < 1e-12 ? a[c]
                             : std::sin(angle * (1 - u)) / std::sin(angle) * a[c] +
                                   sign * std::sin(angle * u) / std::sin(angle) * b[c];
    return out;
  }
  const std::vector<double> p0 = element(s, width, k, 1), m0 = element(s, width, k, 2), p1 = element(s, width, k + 1, 1),
                            m1 = element(s, width, k + 1, 0);
  const double u2 = u * u, u3 = u2 * u;
  for (std::size_t c = 0; c < width; ++c)
    out[c] = (2 * u3 - 3 * u2 + 1) * p0[c] + (u3 - 2 * u2 + u) * dt * m0[c] + (-2 * u3 + 3 * u2) * p1[c] +
             (u3 - u2) * dt * m1[c];
  return rotation ? normalized(out) : out;
}

// The rotation angle (radians) between a library quaternion and a spec one.
double angle_between(const Quat& q, const std::vector<double>& xyzw) {
  const double d = q.x() * xyzw[0] + q.y() * xyzw[1] + q.z() * xyzw[2] + q.w() * xyzw[3];
  return 2.0 * std::acos(std::min(1.0, std::abs(d)));
}
Quat to_quat(const std::vector<double>& xyzw) { return Quat(xyzw[3], xyzw[0], xyzw[1], xyzw[2]); }

GltfAnimations parse(const std::string& bytes) {
  auto read = parse_gltf_animations(bytes, std::filesystem::temp_directory_path(), "fixture");
  EXPECT_TRUE(read.ok()) << read.error();
  return read.ok() ? *read : GltfAnimations{};
}

// The library's sampler for a fixture sampler (by node and path).
const GltfSampler* sampler_of(const GltfAnimations& file, const FixtureSampler& s) {
  for (std::size_t n = 0; n < file.node_names.size(); ++n)
    if (file.node_names[n] == s.node) {
      const int i = s.path == "rotation" ? file.animations.at(0).nodes[n].rotation : file.animations.at(0).nodes[n].translation;
      return i < 0 ? nullptr : &file.animations[0].samplers[static_cast<std::size_t>(i)];
    }
  return nullptr;
}

// Times from before the first key to after the last, every 1 ms, and every key time.
std::vector<double> probe_times(const FixtureSampler& s) {
  std::vector<double> out = s.times;
  for (int i = 0; i <= 2000; ++i) out.push_back(i * 1e-3);
  return out;
}

TEST(GltfSource, EverySamplerKindFollowsTheSpecsFormulasBetweenAndAtKeys) {
  for (bool glb : {true, false}) {
    const GltfAnimations file = parse(test::fixture_file(glb));
    ASSERT_EQ(file.animations.size(), 1u);
    EXPECT_EQ(file.node_names, (std::vector<std::string>{"Root", "Linear", "Cubic", "Stepped"}));
    for (const FixtureSampler& s : test::fixture_samplers()) {
      SCOPED_TRACE(s.node + " " + s.path + " " + s.interpolation + (glb ? " (glb)" : " (gltf, data: uri)"));
      const GltfSampler* mine = sampler_of(file, s);
      ASSERT_NE(mine, nullptr);
      double worst = 0.0;
      for (double t : probe_times(s)) {
        const std::vector<double> want = spec_value(s, t);
        if (s.path == "rotation") {
          worst = std::max(worst, angle_between(gltf_rotation_at(*mine, t), want));
        } else {
          const Vec3 v = gltf_vector_at(*mine, t);
          worst = std::max(worst, (v - Vec3(want[0], want[1], want[2])).norm());
        }
      }
      EXPECT_LT(worst, 1e-6);
    }
  }
}

TEST(GltfSource, ALinearStepPast90DegreesWithAStoredSignFlipTakesTheShortPath) {
  const FixtureSampler s = test::fixture_samplers()[0];
  const GltfAnimations file = parse(test::fixture_file(true));
  const GltfSampler& mine = *sampler_of(file, s);
  // Keys 1 and 2 are stored with a negative dot product; halfway, the short path is
  // half the angle between the orientations, not half of the long way round.
  for (std::size_t k = 0; k + 1 < s.times.size(); ++k) {
    const Quat a = to_quat(normalized(element(s, 4, k, 0))), b = to_quat(normalized(element(s, 4, k + 1, 0)));
    const double step = angle_between(a, normalized(element(s, 4, k + 1, 0)));
    const Quat mid = gltf_rotation_at(mine, 0.5 * (s.times[k] + s.times[k + 1]));
    EXPECT_NEAR(angle_between(mid, {a.x(), a.y(), a.z(), a.w()}), step / 2, 1e-9) << "interval " << k;
    EXPECT_NEAR(angle_between(mid, {b.x(), b.y(), b.z(), b.w()}), step / 2, 1e-9) << "interval " << k;
    if (k == 0) {
      EXPECT_GT(step, kPi / 2);  // the fixture's step over 90°
    }
  }
}

TEST(GltfSource, CubicSplineIsItsKeyValueAtEveryKeyAndStepHoldsThePreviousKey) {
  const std::vector<FixtureSampler> samplers = test::fixture_samplers();
  const GltfAnimations file = parse(test::fixture_file(true));
  const FixtureSampler& cubic = samplers[2];
  for (std::size_t k = 0; k < cubic.times.size(); ++k)
    EXPECT_LT(angle_between(gltf_rotation_at(*sampler_of(file, cubic), cubic.times[k]), normalized(element(cubic, 4, k, 1))),
              1e-12) << "key " << k;
  const FixtureSampler& step = samplers[3];
  for (std::size_t k = 0; k + 1 < step.times.size(); ++k)
    for (double u : {0.0, 0.25, 0.999999}) {
      const double t = step.times[k] + u * (step.times[k + 1] - step.times[k]);
      EXPECT_LT(angle_between(gltf_rotation_at(*sampler_of(file, step), t), normalized(element(step, 4, k, 0))), 1e-12);
    }
  const FixtureSampler& moves = samplers[4];
  EXPECT_EQ(gltf_vector_at(*sampler_of(file, moves), 1.4999), Vec3(1, 0.5, 0));
  EXPECT_EQ(gltf_vector_at(*sampler_of(file, moves), 1.5), Vec3(2, 0.5, 0));
}

// Through the clip reader: joints matched by name, clip time = glTF time (assimp does
// not re-base glTF keys), and at every key of a LINEAR sampler the replay is assimp's key.
TEST(GltfSource, ReadAsAClipTheReplayIsOnTheClipsClockAndEqualsAssimpsKeys) {
  test::TempDir dir;
  const auto path = dir / "fixture.glb";
  test::write_text(path, test::fixture_file(true));
  auto source = read_file_source(path, {});
  ASSERT_TRUE(source.ok()) << source.error();
  const Clip& clip = source->clip;
  std::printf("fixture clip: start %.3f s, end %.3f s\n", clip.start_time(), clip.end_time());
  EXPECT_EQ(source->own_joints(), 3u);
  for (const FixtureSampler& s : test::fixture_samplers()) {
    if (s.path != "rotation") continue;
    SCOPED_TRACE(s.node);
    const int found = clip.skeleton.find(s.node);
    ASSERT_GE(found, 0);
    const auto j = static_cast<std::size_t>(found);
    EXPECT_TRUE(source->own[j]);
    // Between keys: the spec's value at clip time t taken as glTF time t.
    // (A time within float round-off of a STEP key is that key, as assimp read it.)
    for (double t : probe_times(s)) {
      bool at_key = false;
      for (double key : s.times) at_key = at_key || (std::abs(key - t) < 1e-6 && t != key);
      if (!(at_key && s.interpolation == "STEP")) {
        EXPECT_LT(angle_between(source->motion(j, t), spec_value(s, t)), 1e-6) << t;
      }
    }
    // At the keys assimp read: every key for LINEAR (assimp slerps too), the sampler's own
    // keys for STEP and CUBICSPLINE (between them assimp slerps the values, the file does not).
    const RotationTrack& keys = clip.rotations[j];
    double worst = 0.0;
    std::size_t compared = 0;
    for (std::size_t k = 0; k < keys.times.size(); ++k) {
      bool own_key = s.interpolation == "LINEAR";
      for (double t : s.times) own_key = own_key || std::abs(t - keys.times[k]) < 1e-6;
      if (!own_key) continue;
      ++compared;
      worst = std::max(worst, angle_between(source->motion(j, keys.times[k]),
                                            {keys.keys[k].x(), keys.keys[k].y(), keys.keys[k].z(), keys.keys[k].w()}));
    }
    EXPECT_GE(compared, s.times.size());
    EXPECT_LT(worst * 180.0 / kPi, 1e-4);
  }
}

// Each file a buffer may name is checked before it is read.
TEST(GltfSource, ABufferUriThatLeavesTheFilesFolderIsRefusedInOneLine) {
  test::TempDir dir;
  for (const char* uri : {"../outside.bin", "sub/../../outside.bin", "/etc/hostname", "file:///etc/hostname",
                          "http://example.com/a.bin", "C:/a.bin"}) {
    auto read = parse_gltf_animations(test::fixture_file(false, uri), dir.path(), "fixture.gltf");
    ASSERT_FALSE(read.ok()) << uri;
    const bool scheme = std::string(uri).find(':') != std::string::npos;
    EXPECT_NE(read.error().find("fixture.gltf: glTF animations: buffer 0: uri '" + std::string(uri) + "' " +
                                (scheme ? "is not a relative file in the file's folder"
                                        : "leads out of the file's folder (refused unless --allow-external-files, in Python "
                                          "allow_external_files=True)")),
              std::string::npos)
        << read.error();
    EXPECT_EQ(read.error().find('\n'), std::string::npos);
  }
}

TEST(GltfSource, ABufferFileBesideTheGltfIsReadLikeTheEmbeddedOne) {
  test::TempDir dir;
  const std::string glb = test::fixture_file(true);
  const std::uint32_t json_length = static_cast<unsigned char>(glb[12]) | static_cast<unsigned char>(glb[13]) << 8 |
                                    static_cast<unsigned char>(glb[14]) << 16 | static_cast<unsigned>(static_cast<unsigned char>(glb[15])) << 24;
  std::filesystem::create_directories(dir / "bin folder");
  test::write_text(dir / "bin folder/data.bin", glb.substr(20 + json_length + 8));
  const GltfAnimations embedded = parse(glb);
  auto beside = parse_gltf_animations(test::fixture_file(false, "bin%20folder/data.bin"), dir.path(), "fixture.gltf");
  ASSERT_TRUE(beside.ok()) << beside.error();
  ASSERT_EQ(beside->animations.at(0).samplers.size(), embedded.animations.at(0).samplers.size());
  for (std::size_t i = 0; i < embedded.animations[0].samplers.size(); ++i)
    EXPECT_EQ(beside->animations[0].samplers[i].values, embedded.animations[0].samplers[i].values);
}

// An accessor whose elements would pass its buffer view, or a view its buffer, is
// refused before anything is read from it.
TEST(GltfSource, AnAccessorOrViewPastItsBufferIsRefused) {
  using nlohmann::json;
  const json good = json::parse(test::fixture_file(false));
  const std::vector<std::pair<std::string, std::function<void(json&)>>> breaks = {
      {"pass its buffer view", [](json& d) { d["accessors"][0]["count"] = 1000; }},
      {"pass its buffer view", [](json& d) { d["accessors"][1]["byteOffset"] = 4; }},
      {"pass its buffer view", [](json& d) { d["accessors"][0]["count"] = std::uint64_t{1} << 62; }},
      {"its buffer view passes its buffer's end", [](json& d) { d["bufferViews"][0]["byteOffset"] = 1u << 30; }},
      {"its buffer view passes its buffer's end", [](json& d) { d["bufferViews"][0]["byteLength"] = 1u << 30; }},
      {"declares", [](json& d) { d["buffers"][0]["byteLength"] = 1u << 30; }},
      {"does not exist", [](json& d) { d["animations"][0]["channels"][0]["sampler"] = 99; }},
      {"is sparse", [](json& d) { d["accessors"][0]["sparse"] = json::object(); }},
      {"component type 5125", [](json& d) { d["accessors"][0]["componentType"] = 5125; }},
  };
  for (const auto& [message, damage] : breaks) {
    json doc = good;
    damage(doc);
    auto read = parse_gltf_animations(doc.dump(), std::filesystem::temp_directory_path(), "bad.gltf");
    ASSERT_FALSE(read.ok()) << message;
    EXPECT_NE(read.error().find("bad.gltf: glTF animations: "), std::string::npos) << read.error();
    EXPECT_NE(read.error().find(message), std::string::npos) << read.error();
  }
  EXPECT_FALSE(parse_gltf_animations("glTF\x02", ".", "short.glb").ok());
}

}  // namespace
}  // namespace rotinterp
