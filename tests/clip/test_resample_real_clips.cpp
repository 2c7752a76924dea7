// resample_clip on the real clips of ../shared/data and through files (read_clip /
// write_clip), plus the measurement behind the default method.
#include "rotinterp/io/files/file_record.h"
#include "rotinterp/clip/metrics.h"
#include "rotinterp/clip/frames.h"
#include "rotinterp/clip/resample.h"
#include "rotinterp/clip/synth.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/io/read.h"
#include "rotinterp/io/write.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

using namespace rotinterp;
namespace fs = std::filesystem;

namespace {

constexpr double kDeg = 180.0 / kPi;

const char* const kBvhClips[] = {"bvh/cmu_01_01.bvh", "bvh/cmu_01_03.bvh", "bvh/assimp_Boxing_Toes.bvh",
                                 "bvh/NC_bandai1_walk_normal_001.bvh", "bvh/NC_bandai2_raise-up-both-hands_active_031.bvh"};

Clip load(const std::string& rel) {
  auto c = read_clip(fs::path(ROTINTERP_SHARED_DATA) / rel);
  EXPECT_TRUE(c.ok()) << rel << ": " << (c.ok() ? "" : c.error());
  return c.ok() ? std::move(c).value() : Clip{};
}

struct Diff {
  double max_deg = 0.0, mean_deg = 0.0, max_units = 0.0;
};

// Frame-by-frame difference of two clips with the same skeleton; a_step picks
// every a_step-th frame of a.
Diff diff(const Clip& a, const Clip& b, std::size_t a_step = 1) {
  Diff d;
  std::size_t count = 0;
  for (std::size_t j = 0; j < b.rotations.size(); ++j) {
    for (std::size_t k = 0; k < b.rotations[j].keys.size(); ++k) {
      const double e = angular_distance(a.rotations[j].keys[std::min(k * a_step, a.rotations[j].keys.size() - 1)],
                                        b.rotations[j].keys[k]) * kDeg;
      d.max_deg = std::max(d.max_deg, e);
      d.mean_deg += e;
      ++count;
    }
    if (a.translations[j] && b.translations[j])
      for (std::size_t k = 0; k < b.translations[j]->keys.size(); ++k)
        d.max_units = std::max(d.max_units, (a.translations[j]->keys[k * a_step] - b.translations[j]->keys[k]).norm());
  }
  d.mean_deg /= static_cast<double>(std::max<std::size_t>(count, 1));
  return d;
}

Result<Clip> at_rate(const Clip& in, const std::string& method, Rate fps) {
  ResampleOptions o;
  o.method = method;
  o.fps = fps;
  return resample_clip(in, o);
}

// Every clip of ../shared/data that loads (BVH and FBX; every take) and has a
// frame rate, sorted.
struct NamedClip {
  std::string name;
  Clip clip;
};
std::vector<NamedClip> every_real_clip() {
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(ROTINTERP_SHARED_DATA))
    if (e.is_regular_file() && (e.path().extension() == ".bvh" || e.path().extension() == ".fbx"))
      files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::vector<NamedClip> out;
  for (const fs::path& f : files)
    for (int take = 0;; ++take) {
      ReadOptions o;
      o.animation = std::to_string(take);
      auto c = read_clip(f, o);
      if (!c.ok()) break;  // past the last take, or a file we cannot read (named by eval's tests)
      // Clips with a frame rate: sparse-key files without one have no frames to keep.
      if (c->frame_count() >= 3 && clip_rate(*c)) out.push_back({f.filename().string() + "#" + std::to_string(take), std::move(*c)});
      if (f.extension() == ".bvh") break;
    }
  return out;
}

// Largest angle between consecutive keys of a track (rad).
double largest_step(const std::vector<Quat>& q) {
  double m = 0.0;
  for (std::size_t k = 1; k < q.size(); ++k) m = std::max(m, angular_distance(q[k - 1], q[k]));
  return m;
}

fs::path temp_file(const std::string& name) {
  return fs::temp_directory_path() / ("rotinterp_resample_" + std::to_string(::getpid()) + "_" + name);
}

}  // namespace

TEST(ResampleRealClips, SameRateReproducesEveryRealBvhForEveryMethod) {
  ASSERT_GE(methods().size(), 5u) << "the interpolators are not registered";
  for (const char* rel : kBvhClips) {
    const Clip in = load(rel);
    ASSERT_FALSE(in.rotations.empty());
    for (const MethodInfo& m : methods()) {
      ResampleOptions o;
      o.method = m.name;
      auto out = resample_clip(in, o);
      ASSERT_TRUE(out.ok()) << rel << " " << m.name << ": " << out.error();
      ASSERT_EQ(out->frame_count(), in.frame_count()) << rel;
      const Diff d = diff(in, *out);
      EXPECT_LT(d.max_deg, 1e-4) << rel << " " << m.name;
      EXPECT_LT(d.max_units, 1e-4) << rel << " " << m.name;
    }
  }
}

TEST(ResampleRealClips, SameRateThroughBvhFilesReproducesTheInput) {
  for (const char* rel : kBvhClips) {
    const Clip in = load(rel);
    ResampleOptions o;
    auto out = resample_clip(in, o);
    ASSERT_TRUE(out.ok()) << out.error();
    const fs::path file = temp_file("same.bvh");
    ASSERT_TRUE(write_clip(*out, file).ok());
    auto back = read_clip(file);
    fs::remove(file);
    ASSERT_TRUE(back.ok()) << back.error();
    ASSERT_EQ(back->frame_count(), in.frame_count()) << rel;
    EXPECT_EQ(back->frame_time, in.frame_time) << rel;
    const Diff d = diff(in, *back);
    EXPECT_LT(d.max_deg, 1e-4) << rel;
    EXPECT_LT(d.max_units, 1e-4) << rel;
  }
}

TEST(ResampleRealClips, From120To30LandsOnEveryFourthFrame) {
  ASSERT_GE(methods().size(), 5u) << "the interpolators are not registered";
  const Clip in = load("bvh/cmu_01_01.bvh");  // Frame Time 0.008333
  ASSERT_EQ(clip_rate(in).value(), (Rate{120, 1}));
  for (const MethodInfo& m : methods()) {
    auto out = at_rate(in, m.name, Rate{30, 1});
    ASSERT_TRUE(out.ok()) << out.error();
    EXPECT_EQ(out->frame_count(), (in.frame_count() - 1) / 4 + 1);
    const Diff d = diff(in, *out, 4);
    EXPECT_LT(d.max_deg, 1e-6) << m.name;
    EXPECT_LT(d.max_units, 1e-9) << m.name;
  }
}

TEST(ResampleRealClips, UpsampleThenDownsampleReturnsTheInputFrames) {
  ASSERT_GE(methods().size(), 5u) << "the interpolators are not registered";
  const Clip in = load("bvh/NC_bandai1_walk_normal_001.bvh");  // 30 Hz, positions on every joint
  for (const MethodInfo& m : methods()) {
    auto hi = at_rate(in, m.name, Rate{120, 1});
    ASSERT_TRUE(hi.ok()) << hi.error();
    auto back = at_rate(*hi, m.name, Rate{30, 1});
    ASSERT_TRUE(back.ok()) << back.error();
    ASSERT_EQ(back->frame_count(), in.frame_count());
    const Diff d = diff(in, *back);
    EXPECT_LT(d.max_deg, 1e-6) << m.name;
    EXPECT_LT(d.max_units, 1e-9) << m.name;
  }
}

TEST(ResampleRealClips, SynthBvhWithRandomOrdersReadsBackAsItsAnalyticTruth) {
  for (SynthKind kind : {SynthKind::walk, SynthKind::spin}) {
    SynthOptions o;
    o.kind = kind;
    o.seconds = 2.0;
    o.fps = Rate{30, 1};
    o.seed = 11;
    const SynthMotion truth = make_synth_motion(o).value();
    const Clip clip = make_synth_file_clip(o).value();
    const fs::path file = temp_file(std::string(synth_kind_name(kind)) + ".bvh");
    ASSERT_TRUE(write_clip(clip, file).ok());
    auto back = read_clip(file);
    fs::remove(file);
    ASSERT_TRUE(back.ok()) << back.error();
    ASSERT_EQ(back->frame_count(), 61u);
    ASSERT_EQ(back->skeleton.joints.size(), clip.skeleton.joints.size());
    double worst = 0.0, worst_units = 0.0;
    for (std::size_t j = 0; j < clip.skeleton.joints.size(); ++j) {
      EXPECT_EQ(bvh_channels(*back, j), bvh_channels(clip, j));
      for (std::size_t k = 0; k < 61; ++k) {
        worst = std::max(worst, angular_distance(back->rotations[j].keys[k], truth.rotation(j, k / 30.0)) * kDeg);
        if (back->translations[j])
          worst_units = std::max(worst_units, (back->translations[j]->keys[k] - truth.translation(j, k / 30.0)).norm());
      }
    }
    EXPECT_LT(worst, 1e-4) << synth_kind_name(kind);
    EXPECT_LT(worst_units, 1e-4) << synth_kind_name(kind);
  }
}

// Rebuilt from every Nth frame, no method may move a joint between two output
// frames by more than twice the largest step that joint makes in the source (or
// 10°, for joints that hardly move): no snapping round on wide key steps.
TEST(ResampleRealClips, NoMethodStepsFurtherThanTwiceTheSourcesLargestStepOnAnyRealClip) {
  const std::vector<NamedClip> clips = every_real_clip();
  ASSERT_GE(clips.size(), 10u);
  for (const NamedClip& c : clips)
    for (const MethodInfo& m : methods())
      for (std::size_t n : {4u, 8u, 16u}) {
        ResampleOptions o;
        o.method = m.name;
        o.keep_every = n;
        auto out = resample_clip(c.clip, o);
        ASSERT_TRUE(out.ok()) << c.name << " " << m.name << ": " << out.error();
        for (std::size_t j = 0; j < c.clip.rotations.size(); ++j) {
          const double limit = std::max(2.0 * largest_step(c.clip.rotations[j].keys), 10.0 / kDeg);
          const double step = largest_step(out->rotations[j].keys);
          EXPECT_LE(step, limit) << c.name << " " << m.name << " N=" << n << " joint "
                                 << c.clip.skeleton.joints[j].name << ": " << step * kDeg << "° in one frame";
        }
      }
}

// The measurement behind kDefaultResampleMethod (README "Default method"): every
// real clip (every take) rebuilt from every Nth frame, N = 2, 4, 8, 16, with each
// method; over all joints × frames: mean, p99 and max of the angle to the
// original; the smoothness of the rebuilt motion (RMS angular acceleration at the
// source rate, and the mean over joints of the largest velocity / acceleration
// jump at a key); and the drift on held keys (largest angle from the key between
// two equal kept keys). Prints the table; checks the rule the README states.
TEST(ResampleRealClips, DefaultMethodIsChosenByAccuracySmoothnessAndHoldsOnRealClips) {
  struct Agg {
    std::vector<double> errors;
    double acc_sq = 0.0, acc_count = 0.0;
    double vel_jump = 0.0, acc_jump = 0.0, jump_count = 0.0;
    double hold_drift = 0.0;
  };
  const std::vector<std::size_t> spacings = {2, 4, 8, 16};
  std::map<std::string, std::map<std::size_t, Agg>> table;  // method → N → aggregate
  const std::vector<NamedClip> clips = every_real_clip();
  ASSERT_GE(clips.size(), 10u);
  for (const NamedClip& c : clips)
    for (const MethodInfo& m : methods())
      for (std::size_t n : spacings) {
        ResampleOptions o;
        o.method = m.name;
        o.keep_every = n;
        o.threads = 1;
        auto out = resample_clip(c.clip, o);
        ASSERT_TRUE(out.ok()) << out.error();
        Agg& agg = table[m.name][n];
        for (std::size_t j = 0; j < c.clip.rotations.size(); ++j) {
          const RotationTrack& src = c.clip.rotations[j];
          const std::vector<Quat>& got = out->rotations[j].keys;
          if (got.size() != src.keys.size()) continue;  // a joint keyed more sparsely than the frames
          for (std::size_t k = 0; k < src.keys.size(); ++k)
            agg.errors.push_back(angular_distance(src.keys[k], got[k]) * kDeg);
          if (src.keys.size() < 3) continue;
          const double dt = (src.times.back() - src.times.front()) / static_cast<double>(src.keys.size() - 1);
          const Smoothness sm = sampled_smoothness(got.data(), got.size(), dt);
          const double inner = static_cast<double>(got.size() - 2);
          agg.acc_sq += sm.acceleration_rms * sm.acceleration_rms * inner;
          agg.acc_count += inner;
          // The keys this joint was rebuilt from, for the jumps and the holds.
          std::vector<std::size_t> kept;
          for (std::size_t k = 0; k < src.keys.size(); k += n) kept.push_back(k);
          if (kept.back() != src.keys.size() - 1) kept.push_back(src.keys.size() - 1);
          RotationTrack sparse;
          for (std::size_t k : kept) {
            sparse.times.push_back(src.times[k]);
            sparse.keys.push_back(src.keys[k]);
          }
          auto curve = make_interpolator(m.name, sparse);
          ASSERT_TRUE(curve.ok()) << curve.error();
          const KeyJumps jumps = key_jumps(**curve, sparse.times);
          agg.vel_jump += jumps.velocity * kDeg;
          agg.acc_jump += jumps.acceleration * kDeg;
          agg.jump_count += 1.0;
          for (std::size_t i = 0; i + 1 < kept.size(); ++i)
            if (angular_distance(src.keys[kept[i]], src.keys[kept[i + 1]]) < 1e-9)
              for (std::size_t k = kept[i]; k <= kept[i + 1]; ++k)
                agg.hold_drift = std::max(agg.hold_drift, angular_distance(src.keys[kept[i]], got[k]) * kDeg);
        }
      }
  auto mean = [](const std::vector<double>& e) {
    double s = 0.0;
    for (double x : e) s += x;
    return s / static_cast<double>(e.size());
  };
  auto quantile = [](std::vector<double> e, double q) {
    const auto at = e.begin() + static_cast<std::ptrdiff_t>(q * static_cast<double>(e.size() - 1));
    std::nth_element(e.begin(), at, e.end());
    return *at;
  };
  std::map<std::size_t, double> best_mean, best_p99;
  std::printf("%-10s %3s %8s %8s %8s %11s %11s %11s %8s\n", "method", "N", "mean°", "p99°", "max°", "acc_rms°/s²",
              "vel_jump°/s", "acc_jump°/s²", "hold°");
  for (const auto& [name, byn] : table)
    for (const auto& [n, a] : byn) {
      const double mn = mean(a.errors), p99 = quantile(a.errors, 0.99);
      std::printf("%-10s %3zu %8.4f %8.3f %8.2f %11.0f %11.1f %11.0f %8.4f\n", name.c_str(), n, mn, p99,
                  quantile(a.errors, 1.0), std::sqrt(a.acc_sq / a.acc_count), a.vel_jump / a.jump_count,
                  a.acc_jump / a.jump_count, a.hold_drift);
      best_mean[n] = best_mean.count(n) ? std::min(best_mean[n], mn) : mn;
      best_p99[n] = best_p99.count(n) ? std::min(best_p99[n], p99) : p99;
    }
  // The rule (README): the default keeps holds exactly still and is C¹ (no
  // velocity jump at keys), and its mean and p99 are within 10 % of the best
  // method's at every spacing.
  const MethodInfo* d = find_method(kDefaultResampleMethod);
  ASSERT_NE(d, nullptr);
  EXPECT_TRUE(d->preserves_holds);
  EXPECT_GE(d->continuity, 1);
  for (std::size_t n : spacings) {
    const Agg& a = table[kDefaultResampleMethod][n];
    EXPECT_LE(mean(a.errors), 1.1 * best_mean[n]) << "N=" << n;
    EXPECT_LE(quantile(a.errors, 0.99), 1.1 * best_p99[n]) << "N=" << n;
    EXPECT_LT(a.hold_drift, 1e-6) << "N=" << n;
  }
}

TEST(ResampleRealClips, ConstantAngularVelocityBvhWithRandomOrdersResampledTo50HzMatchesTheAnalyticMotion) {
  SynthOptions o;
  o.kind = SynthKind::constant;
  o.seconds = 3.0;
  o.fps = Rate{30, 1};
  o.seed = 17;
  o.joints = 15;
  const SynthMotion truth = make_synth_motion(o).value();
  const fs::path in_file = temp_file("cav30.bvh"), out_file = temp_file("cav50.bvh");
  ASSERT_TRUE(write_clip(make_synth_file_clip(o).value(), in_file).ok());
  auto in = read_clip(in_file);
  ASSERT_TRUE(in.ok()) << in.error();
  std::set<std::vector<Channel>> orders;
  for (std::size_t j = 0; j < in->skeleton.joints.size(); ++j) orders.insert(bvh_channels(*in, j));
  EXPECT_GE(orders.size(), 4u);  // the file really mixes rotation orders
  for (const char* method : {"slerp", "squad", "bf"}) {
    ResampleOptions r;
    r.method = method;
    r.fps = Rate{50, 1};
    auto out = resample_clip(*in, r);
    ASSERT_TRUE(out.ok()) << out.error();
    ASSERT_TRUE(write_clip(*out, out_file).ok());
    auto back = read_clip(out_file);  // through the written BVH, in each joint's own order
    ASSERT_TRUE(back.ok()) << back.error();
    ASSERT_EQ(back->frame_count(), 151u);
    double worst = 0.0, worst_units = 0.0;
    for (std::size_t j = 0; j < back->rotations.size(); ++j)
      for (std::size_t k = 0; k < 151; ++k) {
        const double t = k / 50.0;
        worst = std::max(worst, angular_distance(back->rotations[j].keys[k], truth.rotation(j, t)) * kDeg);
        if (back->translations[j])
          worst_units = std::max(worst_units, (back->translations[j]->keys[k] - truth.translation(j, t)).norm());
      }
    EXPECT_LT(worst, 1e-3) << method;
    EXPECT_LT(worst_units, 1e-4) << method;  // a straight root path, reproduced exactly (up to 6 printed decimals)
    std::printf("%s: max %.2e deg, %.2e units from the analytic motion\n", method, worst, worst_units);
  }
  fs::remove(in_file);
  fs::remove(out_file);
}
