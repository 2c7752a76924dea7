// Samples per second of every interpolator on a 31-joint, 10 000-key track set,
// with Eigen's Quaternion::slerp measured in the same run as the reference.
//
//   ./build/bench/bench_interp --benchmark_min_time=0.2
//
// "items_per_second" is samples per second. The track set: 31 joints × 10 000
// keys at 120 Hz of smooth random motion (angular velocity a sum of sinusoids,
// up to ~6 rad/s: key steps of a few degrees, like motion capture); the samples
// are a resampling at 240 Hz (k / rate, sorted).
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/interp/slerp.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

namespace {

using namespace rotinterp;

constexpr int kJoints = 31;
constexpr int kKeys = 10000;
constexpr double kKeyRate = 120.0;     // Hz
constexpr double kSampleRate = 240.0;  // Hz

std::vector<RotationTrack> make_tracks() {
  std::vector<RotationTrack> tracks;
  std::mt19937_64 rng(2026);
  std::normal_distribution<double> n(0.0, 1.0);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int j = 0; j < kJoints; ++j) {
    Vec3 amp[3], freq, phase;
    for (int c = 0; c < 3; ++c) {
      amp[c] = Vec3(n(rng), n(rng), n(rng)) * 1.2;
      freq[c] = 0.2 + 2.0 * u(rng);
      phase[c] = 6.28 * u(rng);
    }
    RotationTrack t;
    Quat q = Quat(n(rng), n(rng), n(rng), n(rng)).normalized();
    for (int k = 0; k < kKeys; ++k) {
      const double time = k / kKeyRate;
      t.times.push_back(time);
      t.keys.push_back(q);
      Vec3 omega = Vec3::Zero();
      for (int c = 0; c < 3; ++c) omega += amp[c] * std::sin(freq[c] * time + phase[c]);
      q = integrate_angular_velocity(q, omega, 1.0 / kKeyRate);
    }
    t.make_sign_continuous();
    tracks.push_back(std::move(t));
  }
  return tracks;
}

const std::vector<RotationTrack>& tracks() {
  static const std::vector<RotationTrack> t = make_tracks();
  return t;
}

const std::vector<double>& sample_times() {
  static const std::vector<double> s = [] {
    std::vector<double> v;
    const double end = (kKeys - 1) / kKeyRate;
    for (long k = 0; k / kSampleRate <= end; ++k) v.push_back(k / kSampleRate);
    return v;
  }();
  return s;
}

// The pair workload shared by the two slerp lines: consecutive keys, t in [0, 1).
struct Pairs {
  std::vector<Quat> a, b;
  std::vector<double> t;
};
const Pairs& pairs() {
  static const Pairs p = [] {
    Pairs p;
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (const RotationTrack& tr : tracks())
      for (std::size_t k = 0; k + 1 < tr.keys.size(); k += 3) {
        p.a.push_back(tr.keys[k]);
        p.b.push_back(tr.keys[k + 1]);
        p.t.push_back(u(rng));
      }
    return p;
  }();
  return p;
}

void BM_EigenSlerpPairs(benchmark::State& state) {
  const Pairs& p = pairs();
  std::vector<Quat> out(p.a.size());
  for (auto _ : state) {
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = p.a[i].slerp(p.t[i], p.b[i]);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * out.size()));
}
BENCHMARK(BM_EigenSlerpPairs);

void BM_RotinterpSlerpPairs(benchmark::State& state) {
  const Pairs& p = pairs();
  std::vector<Quat> out(p.a.size());
  for (auto _ : state) {
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = slerp(p.a[i], p.b[i], p.t[i]);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * out.size()));
}
BENCHMARK(BM_RotinterpSlerpPairs);

// Eigen's slerp as a track interpolator (same sorted segment walk as ours).
void BM_EigenSlerpTrack(benchmark::State& state) {
  const std::vector<double>& s = sample_times();
  std::vector<Quat> out(s.size());
  for (auto _ : state) {
    for (const RotationTrack& tr : tracks()) {
      std::size_t i = 0;
      for (std::size_t k = 0; k < s.size(); ++k) {
        while (i + 2 < tr.times.size() && s[k] >= tr.times[i + 1]) ++i;
        const double u = std::min(1.0, (s[k] - tr.times[i]) / (tr.times[i + 1] - tr.times[i]));
        out[k] = tr.keys[i].slerp(u, tr.keys[i + 1]);
      }
      benchmark::DoNotOptimize(out.data());
      benchmark::ClobberMemory();
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * s.size() * kJoints));
}
BENCHMARK(BM_EigenSlerpTrack)->Unit(benchmark::kMillisecond);

// A registered method: batch evaluation of every joint at the sorted sample times.
void BM_Method(benchmark::State& state, const std::string& name) {
  std::vector<std::unique_ptr<Interpolator>> joints;
  for (const RotationTrack& tr : tracks()) {
    auto r = make_interpolator(name, tr);
    if (!r) {
      state.SkipWithError(r.error().c_str());
      return;
    }
    joints.push_back(std::move(*r));
  }
  const std::vector<double>& s = sample_times();
  std::vector<Quat> out(s.size());
  for (auto _ : state) {
    for (const auto& j : joints) {
      j->evaluate(s.data(), s.size(), out.data());
      benchmark::DoNotOptimize(out.data());
      benchmark::ClobberMemory();
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * s.size() * kJoints));
}

// Building: keys per second (bf and c2 solve for their control points / rates).
void BM_Build(benchmark::State& state, const std::string& name) {
  for (auto _ : state) {
    for (const RotationTrack& tr : tracks()) {
      auto r = make_interpolator(name, tr);
      benchmark::DoNotOptimize(r);
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * kJoints * kKeys);
}

const int registered = [] {
  for (const MethodInfo& m : methods()) {
    benchmark::RegisterBenchmark(("BM_Method/" + m.name).c_str(), BM_Method, m.name)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("BM_Build/" + m.name).c_str(), BM_Build, m.name)->Unit(benchmark::kMillisecond);
  }
  return 0;
}();

}  // namespace

BENCHMARK_MAIN();
