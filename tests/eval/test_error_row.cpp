// errors.csv rows survive a write/read round trip exactly (the basis of --merge).
#include "rotinterp/eval/error_row.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rotinterp {
namespace {

ErrorRow sample_row() {
  ErrorRow r;
  r.clip = "data/odd, \"name\".bvh";
  r.method = "squad";
  r.keep_every = 8;
  r.joint = "LeftHand";
  r.metres_per_unit = 0.0254;
  r.unit = "in (given: --unit in, \"quoted\")";
  r.frames = 2752;
  r.samples = 2752;
  r.mean_deg = 0.1 + 0.2;  // not exactly representable in short decimal
  r.rms_deg = 1.0 / 3.0;
  r.p95_deg = 2.5e-17;
  r.max_deg = 179.99999999999997;
  r.swing_rms_deg = std::sqrt(2.0);
  r.twist_rms_deg = 1e-300;
  r.pos_rms = 12.345678901234567;
  r.pos_max = 100;
  r.pos_rms_pct = 0.7;
  r.pos_max_pct = 3.2;
  r.shell_rms = 0.01;
  r.shell_max = 0.02;
  r.acc_rms = 1234.5;
  r.acc_rms_ref = 999.25;
  r.vel_jump_max = 17;
  r.acc_jump_max = 4e5;
  r.height = 170.25;
  return r;
}

void expect_same(const ErrorRow& a, const ErrorRow& b) {
  EXPECT_EQ(a.clip, b.clip);
  EXPECT_EQ(a.method, b.method);
  EXPECT_EQ(a.keep_every, b.keep_every);
  EXPECT_EQ(a.joint, b.joint);
  EXPECT_EQ(a.end_site, b.end_site);
  EXPECT_EQ(a.frames, b.frames);
  EXPECT_EQ(a.samples, b.samples);
  for (auto m : {&ErrorRow::mean_deg, &ErrorRow::rms_deg, &ErrorRow::p95_deg, &ErrorRow::max_deg,
                 &ErrorRow::swing_rms_deg, &ErrorRow::twist_rms_deg, &ErrorRow::pos_rms, &ErrorRow::pos_max,
                 &ErrorRow::pos_rms_pct, &ErrorRow::pos_max_pct, &ErrorRow::shell_rms, &ErrorRow::shell_max,
                 &ErrorRow::acc_rms, &ErrorRow::acc_rms_ref, &ErrorRow::vel_jump_max, &ErrorRow::acc_jump_max,
                 &ErrorRow::height, &ErrorRow::metres_per_unit})
    EXPECT_EQ(a.*m, b.*m);  // bit-exact
  EXPECT_EQ(a.unit, b.unit);
}

TEST(ErrorRow, RowsReadBackBitExactThroughCsv) {
  auto parser = ErrorRowParser::from_header(error_csv_schema().header());
  ASSERT_TRUE(parser.ok()) << parser.error();
  const ErrorRow r = sample_row();
  const std::string line = format_error_row(r);
  auto back = parser->parse(line);
  ASSERT_TRUE(back.ok()) << back.error();
  expect_same(r, *back);
  EXPECT_EQ(format_error_row(*back), line);
}

TEST(ErrorRow, EndSiteRowsLeaveAngleColumnsEmptyAndReadBack) {
  ErrorRow r = sample_row();
  r.end_site = true;
  r.joint = "EndSite_LeftHand";
  r.mean_deg = r.rms_deg = r.p95_deg = r.max_deg = r.swing_rms_deg = r.twist_rms_deg = 0;
  r.shell_rms = r.shell_max = r.acc_rms = r.acc_rms_ref = r.vel_jump_max = r.acc_jump_max = 0;
  const std::string line = format_error_row(r);
  EXPECT_NE(line.find(",,,,,,"), std::string::npos) << line;
  EXPECT_EQ(line.find("nan"), std::string::npos);
  auto back = ErrorRowParser::from_header(error_csv_schema().header())->parse(line);
  ASSERT_TRUE(back.ok()) << back.error();
  expect_same(r, *back);
}

TEST(ErrorRow, HeaderStartsWithTheDocumentedColumns) {
  EXPECT_EQ(error_csv_schema().header().rfind("clip,method,keep_every,joint,frames,mean_deg,rms_deg,p95_deg,max_deg,"
                                     "swing_rms_deg,twist_rms_deg,pos_rms_m,pos_max_m,",
                                     0),
            0u);
}

TEST(ErrorRow, MalformedLinesAreRejectedWithTheReason) {
  auto parser = *ErrorRowParser::from_header(error_csv_schema().header());
  std::string line = format_error_row(sample_row());
  EXPECT_FALSE(parser.parse("\"unterminated,squad").ok());
  std::string bad = line;
  bad.replace(bad.find(",8,"), 3, ",x,");
  auto r = parser.parse(bad);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("keep_every"), std::string::npos) << r.error();
  EXPECT_FALSE(ErrorRowParser::from_header("clip,method").ok());
}

}  // namespace
}  // namespace rotinterp
