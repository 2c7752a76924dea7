// resample_clip on the real clips of ../shared/data and through files (read_clip /
// write_clip), plus the measurement behind the default method.
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
    const Clip clip = make_synth_clip(o).value();
    const fs::path file = temp_file(std::string(synth_kind_name(kind)) + ".bvh");
    ASSERT_TRUE(write_clip(clip, file).ok());
    auto back = read_clip(file);
    fs::remove(file);
    ASSERT_TRUE(back.ok()) << back.error();
    ASSERT_EQ(back->frame_count(), 61u);
    ASSERT_EQ(back->skeleton.joints.size(), clip.skeleton.joints.size());
    double worst = 0.0, worst_units = 0.0;
    for (std::size_t j = 0; j < clip.skeleton.joints.size(); ++j) {
      EXPECT_EQ(back->skeleton.joints[j].channels, clip.skeleton.joints[j].channels);
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

// The measurement behind kDefaultResampleMethod (README "rotinterp resample"):
// keep every 4th / 8th frame of the real BVH clips, rebuild with each method,
// compare with the original frames (every joint, every frame). Prints the table;
// checks that error grows with key spacing and that the default is within 10 % of
// the best mean at both spacings.
TEST(ResampleRealClips, DefaultMethodIsAmongTheMostAccurateOnRealClips) {
  ASSERT_GE(methods().size(), 5u) << "the interpolators are not registered";
  struct Agg {
    std::vector<double> errors;
    double seconds = 0.0;
  };
  std::map<std::string, std::map<std::size_t, Agg>> table;  // method → N → errors over all clips
  for (const char* rel : kBvhClips) {
    const Clip in = load(rel);
    if (in.frame_count() < 100) continue;
    for (const MethodInfo& m : methods())
      for (std::size_t n : {4u, 8u}) {
        ResampleOptions o;
        o.method = m.name;
        o.keep_every = n;
        o.threads = 1;
        const auto t0 = std::chrono::steady_clock::now();
        auto out = resample_clip(in, o);
        Agg& agg = table[m.name][n];
        agg.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        ASSERT_TRUE(out.ok()) << out.error();
        for (std::size_t j = 0; j < in.rotations.size(); ++j)
          for (std::size_t k = 0; k < in.rotations[j].keys.size(); ++k)
            agg.errors.push_back(angular_distance(in.rotations[j].keys[k], out->rotations[j].keys[k]) * kDeg);
      }
  }
  ASSERT_FALSE(table.empty()) << "no interpolators registered";
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
  double best4 = 1e9, best8 = 1e9;
  std::printf("%-10s %9s %9s %9s %9s %9s %9s %8s\n", "method", "mean4", "p99_4", "max4", "mean8", "p99_8", "max8",
              "time_s");
  for (const auto& [name, byn] : table) {
    const Agg &a4 = byn.at(4), &a8 = byn.at(8);
    std::printf("%-10s %9.4f %9.3f %9.2f %9.4f %9.3f %9.2f %8.3f\n", name.c_str(), mean(a4.errors),
                quantile(a4.errors, 0.99), quantile(a4.errors, 1.0), mean(a8.errors), quantile(a8.errors, 0.99),
                quantile(a8.errors, 1.0), a4.seconds + a8.seconds);
    EXPECT_GT(mean(a8.errors), mean(a4.errors)) << name;
    best4 = std::min(best4, mean(a4.errors));
    best8 = std::min(best8, mean(a8.errors));
  }
  ASSERT_TRUE(table.count(kDefaultResampleMethod));
  EXPECT_LE(mean(table[kDefaultResampleMethod][4].errors), 1.1 * best4);
  EXPECT_LE(mean(table[kDefaultResampleMethod][8].errors), 1.1 * best8);
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
  ASSERT_TRUE(write_clip(make_synth_clip(o).value(), in_file).ok());
  auto in = read_clip(in_file);
  ASSERT_TRUE(in.ok()) << in.error();
  std::set<std::vector<Channel>> orders;
  for (const Joint& j : in->skeleton.joints) orders.insert(j.channels);
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
