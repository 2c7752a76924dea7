// render -m source (issue 32): an FBX file's own curves drawn as a panel beside the
// interpolators; at the file's keys it is the file's pose, between the kept keys it
// is not slerp's; a file without curves is refused in one line, nothing written.
#include "png_pixels.h"
#include "support/run_cli.h"

#include "rotinterp/interp/interpolator.h"
#include "rotinterp/io/fbx/fbx_source.h"
#include "rotinterp/io/source_motion.h"
#include "rotinterp/render/comparison.h"
#include "rotinterp/render/layout.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <string>

namespace rotinterp::render {
namespace {

namespace fs = std::filesystem;

const std::string kRun = std::string(ROTINTERP_SHARED_DATA) + "/fbx/digitalrune_Marine_Run.fbx";
const std::string kWalk = std::string(ROTINTERP_SOURCE_DIR) + "/samples/walk.bvh";

TEST(RenderSource, SlerpAndSourceDrawTwoPanelsTheSourceOneUnlikeSlerpsBetweenKeys) {
  const fs::path dir = test::fresh_dir("source");
  const std::string common = " --frames 15 --size 320x180 --view side --backend osmesa -q";  // frame 15: between keys 10 and 20
  const auto both = test::run_cli("render " + kRun + " -m slerp,source -o " + (dir / "both").string() + common);
  ASSERT_EQ(both.exit_code, 0) << both.err;
  const auto twice = test::run_cli("render " + kRun + " -m slerp,slerp -o " + (dir / "twice").string() + common);
  ASSERT_EQ(twice.exit_code, 0) << twice.err;
  const test::Pixels a = test::read_png(dir / "both" / "frame_000015.png");
  const test::Pixels b = test::read_png(dir / "twice" / "frame_000015.png");
  ASSERT_TRUE(a.ok() && b.ok());
  const auto panels = grid_layout(2, automatic_columns(2, 320, 180), 320, 180);
  ASSERT_EQ(panels.size(), 2u);
  // The first panel is slerp's in both (the source errs ~0°, so the frame's colour
  // scale is slerp's); the second is the source's, a figure of its own.
  EXPECT_EQ(test::differing_pixels(test::crop(a, panels[0]), test::crop(b, panels[0])), 0u);
  EXPECT_GT(test::differing_pixels(test::crop(a, panels[1]), test::crop(b, panels[1])), 200u);
  EXPECT_GT(test::distinct_colours(test::crop(a, panels[1])), 20u);
  fs::remove_all(dir);
}

TEST(RenderSource, TheSourcePanelIsTheFilesPoseAtItsKeysAndNotSlerpsBetweenKeepEveryKeys) {
  ReadOptions options;
  auto read = read_source_clip(kRun, options);
  ASSERT_TRUE(read.ok()) << read.error();
  auto file = std::make_shared<const SourceClip>(std::move(*read));
  auto motion = source_motion(file, kRun);
  ASSERT_TRUE(motion.ok()) << motion.error();
  const Clip& clip = file->clip;  // its frames are the file's keys (assimp sampled the curves there)
  auto source = comparison_errors(clip, kSourceMethodName, 10, std::nullopt, *motion);
  ASSERT_TRUE(source.ok()) << source.error();
  auto slerp = comparison_errors(clip, "slerp", 10);
  ASSERT_TRUE(slerp.ok()) << slerp.error();
  ASSERT_EQ(source->size(), slerp->size());
  double source_worst = 0.0, slerp_worst = 0.0;
  for (std::size_t f = 0; f < source->size(); ++f) {
    source_worst = std::max(source_worst, (*source)[f].max);
    if (f % 10 != 0) slerp_worst = std::max(slerp_worst, (*slerp)[f].max);
  }
  std::printf("source: worst %.3g° over %zu frames; slerp between keys: worst %.3g°\n", source_worst, source->size(),
              slerp_worst);
  EXPECT_LT(source_worst, 1e-2);  // float keys in the file, assimp's float math
  EXPECT_GT(slerp_worst, 1.0);
}

// Collada: no curves, samplers or frames of its own that we replay (io/source_motion.h).
TEST(RenderSource, AFileWithNoMotionToReplayIsRefusedInOneLineNamingItAndNothingIsWritten) {
  const fs::path dae_dir = test::fresh_dir("source_dae_input");
  const std::string dae = (dae_dir / "walk.dae").string();
  ASSERT_EQ(test::run_cli("resample " + kWalk + " -o " + dae + " -q").exit_code, 0);
  const fs::path dir = test::fresh_dir("source_dae");
  const auto r = test::run_cli("render " + dae + " -m source -o " + dir.string() + " --size 160x90 -q");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find(dae + ": --method source replays a file's own motion"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("source"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(dir));
  fs::remove_all(dae_dir);
}

TEST(RenderSource, SourceIsListedApartFromTheRegistryAndNeedsTheFilesMotion) {
  const fs::path dir = test::fresh_dir("source_none");
  // `methods` lists it after the registry's, as the file's curves, not a curve through keys.
  EXPECT_FALSE(find_method(kSourceMethodName));
  auto list = test::run_cli("methods --json");
  ASSERT_EQ(list.exit_code, 0) << list.err;
  const auto doc = nlohmann::json::parse(list.out);
  ASSERT_EQ(doc.size(), methods().size() + 1);
  for (std::size_t i = 0; i < methods().size(); ++i) {
    EXPECT_EQ(doc[i]["name"], methods()[i].name);
    EXPECT_EQ(doc[i]["replays_file_curves"], false);
  }
  EXPECT_EQ(doc.back()["name"], "source");
  EXPECT_EQ(doc.back()["replays_file_curves"], true);
  EXPECT_TRUE(doc.back()["preserves_holds"].is_null());
  ReadOptions options;
  auto read = read_source_clip(kRun, options);
  ASSERT_TRUE(read.ok()) << read.error();
  ComparisonOptions comparison;
  comparison.methods = {kSourceMethodName};
  comparison.frames = FrameRange{15, 15, 1};
  comparison.width = 160;
  comparison.height = 90;
  auto r = render_comparison(read->clip, dir, comparison);  // no `source` given
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("source"), std::string::npos) << r.error();
  EXPECT_FALSE(fs::exists(dir));
}

}  // namespace
}  // namespace rotinterp::render
