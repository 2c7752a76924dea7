// eval --metrics: the names, the columns each metric owns, and that a metric not
// chosen is neither computed nor written, while the chosen ones stay as they were.
#include "eval_cli_util.h"
#include "support/run_cli.h"

#include "rotinterp/eval/error_row.h"
#include "rotinterp/eval/evaluate_clip.h"
#include "rotinterp/io/read.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <string>

namespace rotinterp {
namespace {

namespace fs = std::filesystem;

const char* const kWalk = ROTINTERP_SHARED_DATA "/bvh/NC_bandai1_walk_normal_001.bvh";

MetricSet only(std::initializer_list<Metric> metrics) {
  MetricSet s = MetricSet::none();
  for (Metric m : metrics) s.add(m);
  return s;
}

TEST(MetricChoice, UnknownNamesAreRefusedWithTheValidOnesListed) {
  const auto r = parse_metrics("angle,speed");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("'speed'"), std::string::npos) << r.error();
  EXPECT_NE(r.error().find(metric_names()), std::string::npos) << r.error();
  EXPECT_FALSE(parse_metrics("").ok());
  EXPECT_FALSE(parse_metrics("angle,").ok());
}

TEST(MetricChoice, NamesReadBackAsTheSameSet) {
  for (unsigned bits = 1; bits < (1u << kMetricCount); ++bits) {
    const MetricSet s = MetricSet::of_bits(bits);
    const auto back = parse_metrics(metrics_text(s));
    ASSERT_TRUE(back.ok()) << metrics_text(s);
    EXPECT_EQ(*back, s) << metrics_text(s);
  }
  EXPECT_EQ(metrics_text(MetricSet::all()), "all");
  EXPECT_EQ(*parse_metrics("fk,angle,angle"), only({Metric::angle, Metric::fk}));
}

TEST(MetricChoice, TheCsvHasTheChosenMetricsColumnsAndReadsBack) {
  const MetricSet angle = only({Metric::angle});
  const auto& columns = error_csv_schema(angle).columns();
  for (const char* name : {"mean_deg", "rms_deg", "p95_deg", "max_deg", "keys", "unit"})
    EXPECT_NE(std::find(columns.begin(), columns.end(), name), columns.end()) << name;
  for (const char* name : {"swing_rms_deg", "pos_rms_m", "shell_rms_m", "acc_rms_dps2", "contact_frames", "looped"})
    EXPECT_EQ(std::find(columns.begin(), columns.end(), name), columns.end()) << name;
  // Every metric but seam: the file as before --metrics; seam's columns come with --loop alone.
  EXPECT_EQ(error_csv_schema(csv_metrics(MetricSet::all(), false)).size() + 5,
            error_csv_schema(csv_metrics(MetricSet::all(), true)).size());
  ErrorRow row;
  row.clip = "c", row.method = "slerp", row.joint = "j", row.frames = 9, row.samples = 9;
  row.mean_deg = 0.25, row.rms_deg = 0.5, row.p95_deg = 0.75, row.max_deg = 1.0, row.pos_rms = 7.0;
  const std::string header = error_csv_schema(angle).header();
  const auto parser = ErrorRowParser::from_header(header.substr(0, header.size() - 1));
  ASSERT_TRUE(parser.ok()) << parser.error();
  EXPECT_EQ(parser->metrics(), angle);
  const std::string line = format_error_row(row, angle);
  const auto back = parser->parse(line.substr(0, line.size() - 1));
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(back->max_deg, 1.0);
  EXPECT_EQ(back->pos_rms, 0.0);  // not a column of this file
}

TEST(MetricChoice, AChosenMetricIsComputedAsInAFullRunAndNoPosesWithoutOne) {
  auto clip = read_clip(kWalk);
  ASSERT_TRUE(clip.ok()) << clip.error();
  ClipEvalOptions all;
  all.methods = {"slerp", "c2"};
  all.keep_every = {4, 8};
  ClipEvalOptions angle = all;
  angle.metrics = only({Metric::angle});
  const auto ref = prepare_reference(*clip, "walk", angle);
  ASSERT_TRUE(ref.ok()) << ref.error();
  EXPECT_TRUE(ref->world.empty());  // no forward kinematics of the reference
  const auto full_rows = evaluate_clip(*clip, "walk", all);
  const auto angle_rows = evaluate_clip(*clip, "walk", angle);
  ASSERT_TRUE(full_rows.ok() && angle_rows.ok());
  std::size_t joint_rows = 0;
  for (const ErrorRow& r : *full_rows) joint_rows += !r.end_site;
  ASSERT_EQ(angle_rows->size(), joint_rows);  // no End Site rows: they hold fk alone
  std::size_t i = 0;
  for (const ErrorRow& r : *full_rows) {
    if (r.end_site) continue;
    const ErrorRow& a = (*angle_rows)[i++];
    ASSERT_EQ(a.joint, r.joint);
    EXPECT_EQ(a.mean_deg, r.mean_deg) << r.joint;
    EXPECT_EQ(a.rms_deg, r.rms_deg) << r.joint;
    EXPECT_EQ(a.p95_deg, r.p95_deg) << r.joint;
    EXPECT_EQ(a.max_deg, r.max_deg) << r.joint;
    EXPECT_EQ(a.swing_rms_deg, 0.0);
    EXPECT_EQ(a.pos_max, 0.0);
    EXPECT_EQ(a.acc_jump_max, 0.0);
    EXPECT_FALSE(a.foot);
  }
  ClipEvalOptions fk = all;
  fk.metrics = only({Metric::fk});
  const auto fk_rows = evaluate_clip(*clip, "walk", fk);
  ASSERT_TRUE(fk_rows.ok());
  ASSERT_EQ(fk_rows->size(), full_rows->size());
  for (std::size_t k = 0; k < fk_rows->size(); ++k) EXPECT_EQ((*fk_rows)[k].pos_max, (*full_rows)[k].pos_max);
}

TEST(MetricChoice, TheCommandWritesOnlyTheChosenColumnsAndRefusesUnknownNames) {
  const fs::path out = test::fresh_dir("metrics_angle");
  const auto r = test::run_cli(std::string("eval ") + kWalk + " -m slerp --keep-every 4 --metrics angle -o " +
                               out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(test::lines_of(test::slurp(out / "errors.csv"))[0],
            "clip,method,keep_every,joint,frames,mean_deg,rms_deg,p95_deg,max_deg,samples,height_m,kind,keys,"
            "motion_deg,metres_per_unit,unit");
  EXPECT_EQ(r.out.find("pos max"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("RMS°"), std::string::npos) << r.out;
  const auto j = nlohmann::json::parse(test::slurp(out / "summary.json"));
  EXPECT_EQ(j["options"]["metrics"], "angle");
  EXPECT_FALSE(j["results"][0].contains("pos_max_pct"));
  EXPECT_TRUE(j["results"][0].contains("rms_deg"));
  EXPECT_TRUE(fs::exists(out / "error_vs_spacing.png"));

  // Without angle: no plots, and no worst clip (it is the worst by angle).
  const fs::path fk = test::fresh_dir("metrics_fk");
  const auto f = test::run_cli(std::string("eval ") + kWalk + " -m slerp --keep-every 4 --metrics fk -o " + fk.string());
  ASSERT_EQ(f.exit_code, 0) << f.err;
  EXPECT_FALSE(fs::exists(fk / "error_vs_spacing.png"));
  EXPECT_EQ(f.out.find("plots"), std::string::npos) << f.out;
  EXPECT_FALSE(nlohmann::json::parse(test::slurp(fk / "summary.json")).contains("worst_clip"));

  const auto bad = test::run_cli(std::string("eval ") + kWalk + " --metrics angle,speed -o " + out.string());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("valid: all, " + metric_names()), std::string::npos) << bad.err;
}

TEST(MetricChoice, ShardsOfOneChoiceMergeAsASingleRunAndOtherChoicesAreRefused) {
  const fs::path in = test::clip_dir("metrics_shards", false);
  const fs::path single = test::fresh_dir("metrics_single"), a = test::fresh_dir("metrics_a"),
                 b = test::fresh_dir("metrics_b"), all = test::fresh_dir("metrics_all"),
                 merged = test::fresh_dir("metrics_merged");
  const std::string common = "eval " + in.string() + " -m slerp,c2 --keep-every 2,8 -q --no-plots -j 1 ";
  ASSERT_EQ(test::run_cli(common + "--metrics smoothness,fk -o " + single.string()).exit_code, 0);
  ASSERT_EQ(test::run_cli(common + "--metrics fk,smoothness --shard 1/2 -o " + a.string()).exit_code, 0);
  ASSERT_EQ(test::run_cli(common + "--metrics fk,smoothness --shard 2/2 -o " + b.string()).exit_code, 0);
  const auto r = test::run_cli("eval --merge " + a.string() + " " + b.string() + " -q -o " + merged.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(test::slurp(merged / "errors.csv"), test::slurp(single / "errors.csv"));
  EXPECT_EQ(test::slurp(merged / "clips.csv"), test::slurp(single / "clips.csv"));

  ASSERT_EQ(test::run_cli(common + "--shard 2/2 -o " + all.string()).exit_code, 0);
  const auto mixed = test::run_cli("eval --merge " + a.string() + " " + all.string() + " -q -o " +
                                   test::fresh_dir("metrics_mixed").string());
  EXPECT_EQ(mixed.exit_code, 1);
  EXPECT_NE(mixed.err.find("other options"), std::string::npos) << mixed.err;
}

}  // namespace
}  // namespace rotinterp
