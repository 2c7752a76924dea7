// Field-by-field identity of what the reader reports, doubles bit for bit (so 0.0
// and -0.0 differ, and a NaN equals only the same NaN).
#pragma once

#include "rotinterp/io/files/file_record.h"
#include "rotinterp/io/info.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

namespace rotinterp::test {

inline bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

inline ::testing::AssertionResult same_doubles(const double* a, const double* b, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i)
    if (!same_bits(a[i], b[i]))
      return ::testing::AssertionFailure() << "element " << i << ": " << a[i] << " vs " << b[i];
  return ::testing::AssertionSuccess();
}
inline ::testing::AssertionResult same(const Vec3& a, const Vec3& b) { return same_doubles(a.data(), b.data(), 3); }
inline ::testing::AssertionResult same(const Quat& a, const Quat& b) {
  return same_doubles(a.coeffs().data(), b.coeffs().data(), 4);
}

inline void expect_identical(const Clip& a, const Clip& b, const std::string& where) {
  SCOPED_TRACE(where);
  EXPECT_EQ(a.name, b.name);
  ASSERT_EQ(a.skeleton.joints.size(), b.skeleton.joints.size());
  for (std::size_t j = 0; j < a.skeleton.joints.size(); ++j) {
    const Joint &x = a.skeleton.joints[j], &y = b.skeleton.joints[j];
    SCOPED_TRACE("joint " + std::to_string(j));
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.parent, y.parent);
    EXPECT_TRUE(same(x.offset, y.offset));
    EXPECT_TRUE(same(x.rest_rotation, y.rest_rotation));
    EXPECT_EQ(bvh_channels(a, j), bvh_channels(b, j));
  }
  ASSERT_EQ(a.skeleton.end_sites.size(), b.skeleton.end_sites.size());
  for (std::size_t e = 0; e < a.skeleton.end_sites.size(); ++e) {
    const EndSite &x = a.skeleton.end_sites[e], &y = b.skeleton.end_sites[e];
    SCOPED_TRACE("end site " + std::to_string(e));
    EXPECT_EQ(x.parent, y.parent);
    EXPECT_TRUE(same(x.offset, y.offset));
    EXPECT_EQ(x.name, y.name);
  }
  ASSERT_EQ(a.rotations.size(), b.rotations.size());
  for (std::size_t j = 0; j < a.rotations.size(); ++j) {
    const RotationTrack &x = a.rotations[j], &y = b.rotations[j];
    SCOPED_TRACE("rotation track " + std::to_string(j));
    ASSERT_EQ(x.times.size(), y.times.size());
    EXPECT_TRUE(same_doubles(x.times.data(), y.times.data(), x.times.size()));
    ASSERT_EQ(x.keys.size(), y.keys.size());
    for (std::size_t k = 0; k < x.keys.size(); ++k) EXPECT_TRUE(same(x.keys[k], y.keys[k])) << "key " << k;
  }
  ASSERT_EQ(a.translations.size(), b.translations.size());
  for (std::size_t j = 0; j < a.translations.size(); ++j) {
    SCOPED_TRACE("translation track " + std::to_string(j));
    ASSERT_EQ(a.translations[j].has_value(), b.translations[j].has_value());
    if (!a.translations[j]) continue;
    const TranslationTrack &x = *a.translations[j], &y = *b.translations[j];
    ASSERT_EQ(x.times.size(), y.times.size());
    EXPECT_TRUE(same_doubles(x.times.data(), y.times.data(), x.times.size()));
    ASSERT_EQ(x.keys.size(), y.keys.size());
    for (std::size_t k = 0; k < x.keys.size(); ++k) EXPECT_TRUE(same(x.keys[k], y.keys[k])) << "key " << k;
  }
  EXPECT_TRUE(same_bits(a.frame_time, b.frame_time)) << a.frame_time << " vs " << b.frame_time;
  EXPECT_EQ(bvh_layout(a) == nullptr, bvh_layout(b) == nullptr);
  EXPECT_TRUE(same_bits(stated_rate_hz(a.source_record), stated_rate_hz(b.source_record)));
  EXPECT_EQ(frame_time_text(a), frame_time_text(b));
  EXPECT_TRUE(same_bits(a.unit.metres_per_unit, b.unit.metres_per_unit))
      << a.unit.metres_per_unit << " vs " << b.unit.metres_per_unit;
  EXPECT_EQ(a.unit.origin, b.unit.origin);
  EXPECT_EQ(a.unit.reason, b.unit.reason);
  EXPECT_EQ(a.source_format, b.source_format);
}

inline void expect_identical(const ClipFileInfo& a, const ClipFileInfo& b, const std::string& where) {
  SCOPED_TRACE(where);
  EXPECT_EQ(a.format, b.format);
  ASSERT_EQ(a.animations.size(), b.animations.size());
  for (std::size_t i = 0; i < a.animations.size(); ++i) {
    const AnimationSummary &x = a.animations[i], &y = b.animations[i];
    SCOPED_TRACE("animation " + std::to_string(i));
    EXPECT_EQ(x.name, y.name);
    EXPECT_TRUE(same_bits(x.duration, y.duration)) << x.duration << " vs " << y.duration;
    EXPECT_TRUE(same_bits(x.ticks_per_second, y.ticks_per_second)) << x.ticks_per_second << " vs " << y.ticks_per_second;
    EXPECT_EQ(x.default_rate, y.default_rate);
    EXPECT_EQ(x.channels, y.channels);
  }
  EXPECT_EQ(a.selected, b.selected);
  expect_identical(a.clip, b.clip, where);
  EXPECT_EQ(a.warnings, b.warnings);
  EXPECT_EQ(a.folded_helpers, b.folded_helpers);
  EXPECT_EQ(a.holds, b.holds);
}

}  // namespace rotinterp::test
