// `rotinterp info --curves --sample 24 --json`: the curves read in the importer
// process and sampled on the file's own time axis match every DCC value of
// dcc_reference.tsv within 1e-4 of the curve's range; the JSON has the shape.
#include "io/dcc_reference.h"  // the DCC values, shared with tests/io
#include "support/run_cli.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace rotinterp {
namespace {

TEST(InfoCurvesCli, SamplesAt24HzMatchEveryDccReferenceValue) {
  std::size_t matched = 0, total = 0;
  for (const test::DccCase& c : test::dcc_cases()) {
    SCOPED_TRACE(c.name + " " + c.file);
    const test::CliResult r = test::run_cli("info '" + c.file + "' --curves --sample 24 --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json doc = nlohmann::json::parse(r.out);
    ASSERT_EQ(doc.size(), 1u);  // {"curves": [...]} and nothing else
    const nlohmann::json* curve = nullptr;
    for (const nlohmann::json& e : doc.at("curves"))
      if ((c.node.front() == '(' || e.at("node") == c.node) && e.at("property") == c.property &&
          e.at("channel") == std::string(1, c.channel) && e.at("layer") == c.layer && !e.at("keys").empty())
        curve = &e;
    ASSERT_NE(curve, nullptr);
    const nlohmann::json& key = curve->at("keys").at(0);
    for (const char* field : {"t", "value", "interpolation", "tangent"}) EXPECT_TRUE(key.contains(field)) << field;
    const std::vector<double> samples = curve->at("samples").get<std::vector<double>>();
    ASSERT_GE(samples.size() + 1, c.values.size());
    for (std::size_t i = 0; i < c.values.size() && i < samples.size(); ++i) {
      ++total;
      if (std::abs(samples[i] - c.values[i]) <= c.tolerance()) ++matched;
      else ADD_FAILURE() << "sample " << i << ": " << samples[i] << " against " << c.values[i];
    }
  }
  EXPECT_EQ(matched, total);
  EXPECT_GE(total, 250u);
  std::printf("matched %zu of %zu DCC values\n", matched, total);
}

TEST(InfoCurvesCli, CurvesOfANonFbxFileAreRefusedInOneLine) {
  const test::CliResult r = test::run_cli("info '" + (test::kData / "bvh/bvhio_example.bvh").string() + "' --curves");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("--curves reads FBX files only"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace rotinterp
