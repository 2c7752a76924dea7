// The video outputs: MP4, GIF and PNGs through ffmpeg, the same bytes for the same
// command, and a failing ffmpeg leaving the previous file and no temporary.
#include "png_pixels.h"
#include "support/run_cli.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <unistd.h>

namespace rotinterp::render {
namespace {

namespace fs = std::filesystem;
using test::fresh_dir;
using test::run_cli;

// ---- video --------------------------------------------------------------------------

std::string probe(const fs::path& video, const std::string& entries) {
  const std::string cmd = "ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=" + entries +
                          " -of csv=p=0 " + video.string();
  std::string out;
  if (std::FILE* pipe = ::popen(cmd.c_str(), "r")) {
    char buf[256];
    while (std::fgets(buf, sizeof buf, pipe)) out += buf;
    ::pclose(pipe);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == ',')) out.pop_back();
  return out;
}

const std::string kSample = std::string(ROTINTERP_SOURCE_DIR) + "/samples/walk.bvh";  // 121 frames at 30 Hz

TEST(Video, Mp4HasTheFramesSizeAndRateAskedNoPngsAndTheSameBytesEachTime) {
  const fs::path dir = fresh_dir("mp4");
  fs::create_directories(dir);
  const fs::path video = dir / "walk.mp4";
  auto r = run_cli("render " + kSample + " --video " + video.string() +
                   " --methods slerp,squad --frames 10:45 --size 320x180 -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(probe(video, "width,height,r_frame_rate,nb_read_frames,codec_name"), "h264,320,180,30/1,36");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1) << "only the video";
  const std::string first = test::slurp(video);
  r = run_cli("render " + kSample + " --video " + video.string() + " --methods slerp,squad --frames 10:45 --size 320x180 -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(test::slurp(video), first) << "the same command gives the same bytes";
  // --video-fps, and every frame of the clip by default.
  r = run_cli("render " + kSample + " --video " + video.string() + " --methods slerp --size 160x90 --video-fps 12 -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(probe(video, "width,height,r_frame_rate,nb_read_frames"), "160,90,12/1,121");
  fs::remove_all(dir);
}

TEST(Video, GifAndPngsTogetherAndTheSameCommandGivesTheSameBytes) {
  const fs::path dir = fresh_dir("gif");
  const std::string args = "render " + kSample + " -o " + (dir / "png").string() + " --video " +
                           (dir / "walk.gif").string() + " --methods slerp --frames 20:29 --size 160x90 -q";
  auto r = run_cli(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(probe(dir / "walk.gif", "codec_name,width,height,nb_read_frames"), "gif,160,90,10");
  EXPECT_TRUE(fs::exists(dir / "png" / "frame_000020.png"));
  const std::string gif = test::slurp(dir / "walk.gif"), png = test::slurp(dir / "png" / "frame_000025.png");
  r = run_cli(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(test::slurp(dir / "walk.gif"), gif);
  EXPECT_EQ(test::slurp(dir / "png" / "frame_000025.png"), png);
  fs::remove_all(dir);
}

TEST(Video, AFailingFfmpegGivesOneLineAndLeavesThePreviousFileAndNoTemporary) {
  const fs::path dir = fresh_dir("ffmpeg_fails");
  fs::create_directories(dir / "bin");
  {
    std::ofstream fake(dir / "bin" / "ffmpeg");
    fake << "#!/bin/sh\ncat >/dev/null\necho 'libx264: out of cheese' >&2\nexit 1\n";
  }
  fs::permissions(dir / "bin" / "ffmpeg", fs::perms::owner_all);
  std::ofstream(dir / "old.mp4") << "previous";
  const fs::path err = dir / "err.txt";
  const std::string cmd = "PATH=" + (dir / "bin").string() + ":$PATH " + ROTINTERP_CLI + " render " + kSample +
                          " --video " + (dir / "old.mp4").string() + " --methods slerp --frames 0:3 --size 64x48 -q 2>" +
                          err.string();
  const int status = std::system(cmd.c_str());
  EXPECT_EQ(WEXITSTATUS(status), 1);
  EXPECT_EQ(test::slurp(err), "rotinterp: " + kSample + ": " + (dir / "old.mp4").string() +
                                  ": ffmpeg failed: libx264: out of cheese\n");
  EXPECT_EQ(test::slurp(dir / "old.mp4"), "previous");
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(dir)) files += e.is_regular_file();
  EXPECT_EQ(files, 2u) << "old.mp4 and err.txt: no temporary left";
  fs::remove_all(dir);
}

TEST(Video, BadRequestsAreUsageErrorsWithOneLine) {
  const fs::path dir = fresh_dir("video_usage");
  struct Case {
    std::string args;
    int code;
    std::string message;
  };
  const std::vector<Case> cases = {
      {"--video " + (dir / "a.avi").string(), 2, "--video '" + (dir / "a.avi").string() + "': unknown format (use .mp4 or .gif)"},
      {"--video " + (dir / "a.mp4").string() + " --size 161x90", 2, "--video: H.264 (.mp4) needs an even width and height, not 161x90"},
      {"", 2, "render: give -o DIR (frame PNGs), --video FILE, or both"},
      {"--video " + (dir / "a.mp4").string() + " --sheet", 2, "--sheet needs -o DIR"},
      {"--video " + (dir / "a.mp4").string() + " --anim 5", 1, "there is no animation '5'"},
  };
  for (const Case& c : cases) {
    const auto r = run_cli("render " + kSample + " --methods slerp --frames 0:3 -q " + c.args);
    EXPECT_EQ(r.exit_code, c.code) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_FALSE(fs::exists(dir / "a.mp4"));
  fs::remove_all(dir);
}
}  // namespace
}  // namespace rotinterp::render
