// Summary aggregates: hand-computed values over a few rows.
#include "rotinterp/eval/summary.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rotinterp {
namespace {

ErrorRow row(const std::string& clip, const std::string& method, int keep, const std::string& joint, std::size_t n,
             double rms, double max) {
  ErrorRow r;
  r.clip = clip;
  r.method = method;
  r.keep_every = keep;
  r.joint = joint;
  r.frames = r.samples = n;
  r.mean_deg = rms;
  r.rms_deg = rms;
  r.p95_deg = max;
  r.max_deg = max;
  r.height = 2.0;
  r.shell_rms = 0.02;
  r.shell_max = 0.04;
  return r;
}

TEST(Summary, AggregatesAreSampleWeightedAndMaxOverAll) {
  SummaryBuilder b;
  b.add_clip({row("a", "slerp", 2, "j0", 100, 1.0, 2.0), row("a", "slerp", 2, "j1", 100, 3.0, 5.0),
              row("a", "slerp", 4, "j0", 100, 4.0, 9.0)});
  b.add_clip({row("b", "slerp", 2, "j0", 300, 2.0, 7.0), row("b", "slerp", 4, "j0", 300, 1.0, 1.5)});
  const Summary s = b.finish();
  ASSERT_EQ(s.entries.size(), 2u);
  const SummaryEntry& e = s.entries[0];
  EXPECT_EQ(e.method, "slerp");
  EXPECT_EQ(e.keep_every, 2);
  EXPECT_EQ(e.clips, 2u);
  EXPECT_EQ(e.joints, 3u);
  EXPECT_EQ(e.samples, 500u);
  EXPECT_DOUBLE_EQ(e.rms_deg, std::sqrt((100 * 1.0 + 100 * 9.0 + 300 * 4.0) / 500));
  EXPECT_DOUBLE_EQ(e.mean_deg, (100 * 1.0 + 100 * 3.0 + 300 * 2.0) / 500);
  EXPECT_DOUBLE_EQ(e.max_deg, 7.0);
  EXPECT_EQ(e.worst_clip, "b");
  EXPECT_DOUBLE_EQ(e.p95_deg, 5.0 + 0.9 * (7.0 - 5.0));  // p95 of {2, 5, 7}
  EXPECT_DOUBLE_EQ(e.shell_rms_pct, 1.0);                  // 0.02 of height 2
  // Worst clip: largest RMS at the largest spacing (4): clip a (4.0) over b (1.0).
  EXPECT_EQ(s.worst_clip, "a");
  EXPECT_EQ(s.worst_keep_every, 4);
  ASSERT_EQ(s.worst_clip_rows.size(), 1u);
  EXPECT_EQ(s.clips, 2u);
  EXPECT_NE(format_summary_table(s).find("slerp"), std::string::npos);
}

}  // namespace
}  // namespace rotinterp
