// make_interpolator on a track passed with std::move: the track's storage becomes the
// curve's keys (no copy of them, counted by this binary's operator new), and the curve
// is the one built from a copy, bit for bit.
#include "rotinterp/interp/interpolator.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <string>
#include <utility>
#include <vector>

namespace {
std::atomic<bool> counting_allocations{false};
std::atomic<std::size_t> bytes_allocated{0};
}  // namespace

// Replaced for the whole test binary; counts only between the two flag flips below.
void* operator new(std::size_t size) {
  if (counting_allocations.load()) bytes_allocated += size;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
// The pair of the operator new above (GCC cannot tell that it is the replaced one).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#pragma GCC diagnostic pop

namespace rotinterp {
namespace {

// 10 000 keys of a turning joint, every third key stored in the other hemisphere and
// slightly off unit (within kUnitNormTolerance), so preparing them aligns and normalizes.
RotationTrack turning_track() {
  RotationTrack track;
  for (int k = 0; k < 10000; ++k) {
    const double t = k / 120.0;
    Quat q(Eigen::AngleAxisd(0.7 * t, Vec3(std::sin(t), std::cos(0.3 * t), 1.0).normalized()));
    q.coeffs() *= (k % 3 == 0 ? -1.0 : 1.0) * (1.0 + 1e-10);
    track.times.push_back(t);
    track.keys.push_back(q);
  }
  return track;
}

TEST(MoveBuild, AMovedTrackBecomesTheCurvesKeysWithoutACopyAndGivesTheSameCurve) {
  for (const char* method : {"slerp", "nlerp", "c2"}) {
    RotationTrack track = turning_track();
    const RotationTrack copy = track;
    const std::size_t key_bytes = track.keys.size() * sizeof(Quat);
    auto from_copy = make_interpolator(method, copy);
    ASSERT_TRUE(from_copy) << method;

    bytes_allocated = 0;
    counting_allocations = true;
    auto from_move = make_interpolator(method, std::move(track));
    counting_allocations = false;
    ASSERT_TRUE(from_move) << method;
    // slerp and nlerp allocate nothing a key (c2 adds its rates, whatever its solver needs).
    if (std::string(method) != "c2") {
      EXPECT_LT(bytes_allocated.load(), key_bytes / 10) << method;
    }

    std::vector<double> at;
    for (int i = -10; i < 20000; i += 7) at.push_back(i / 240.0 + 1e-4);
    std::vector<Quat> a(at.size()), b(at.size());
    (*from_copy)->evaluate(at.data(), at.size(), a.data());
    (*from_move)->evaluate(at.data(), at.size(), b.data());
    for (std::size_t i = 0; i < at.size(); ++i) ASSERT_EQ(a[i].coeffs(), b[i].coeffs()) << method << " at " << at[i];
  }
}

}  // namespace
}  // namespace rotinterp
