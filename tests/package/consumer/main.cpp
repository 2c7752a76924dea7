// Links every library of an installed package and calls each:
//   core:   exp/log agree;
//   io:     a BVH written to DIR and read back (read_clip, write_clip);
//   eval:   the read clip (5 frames: 2N + 1 for N = 2) evaluated with slerp from every 2nd frame;
//   render: a PNG written to DIR (when the package has the renderer).
// Usage: consumer DIR
#include <rotinterp/core/rotation.h>
#include <rotinterp/eval/evaluate_clip.h>
#include <rotinterp/io/read.h>
#include <rotinterp/io/write.h>
#if WITH_RENDER
#include <rotinterp/render/image.h>
#endif

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace {

const char* const kBvh =
    "HIERARCHY\n"
    "ROOT Hips\n"
    "{\n"
    "  OFFSET 0 0 0\n"
    "  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
    "  JOINT Chest\n"
    "  {\n"
    "    OFFSET 0 10 0\n"
    "    CHANNELS 3 Zrotation Xrotation Yrotation\n"
    "    End Site\n"
    "    {\n"
    "      OFFSET 0 10 0\n"
    "    }\n"
    "  }\n"
    "}\n"
    "MOTION\n"
    "Frames: 5\n"
    "Frame Time: 0.033333\n"
    "0 0 0 0 0 0 0 0 0\n"
    "0 0 0 10 0 0 20 0 0\n"
    "0 0 0 20 0 0 40 0 0\n"
    "0 0 0 30 0 0 50 0 0\n"
    "0 0 0 40 0 0 55 0 0\n";

int fail(const char* what, const std::string& message) {
  std::fprintf(stderr, "consumer: %s: %s\n", what, message.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) return fail("usage", "consumer DIR");
  const std::filesystem::path dir = argv[1];

  const rotinterp::RotVec v(0.1, -0.2, 0.3);
  const double err = (rotinterp::log(rotinterp::exp(v)).vec() - v.vec()).norm();
  std::printf("core: round-trip error %.3g\n", err);
  if (!(err < 1e-12)) return fail("core", "exp/log round trip");

  std::ofstream(dir / "in.bvh") << kBvh;
  rotinterp::Result<rotinterp::Clip> clip = rotinterp::read_clip(dir / "in.bvh");
  if (!clip) return fail("io", clip.error());
  if (rotinterp::Status s = rotinterp::write_clip(*clip, dir / "out.bvh"); !s) return fail("io", s.error());
  rotinterp::Result<rotinterp::Clip> again = rotinterp::read_clip(dir / "out.bvh");
  if (!again) return fail("io", again.error());
  std::printf("io: %zu joints, %zu frames\n", again->skeleton.joints.size(), again->frame_count());

  rotinterp::ClipEvalOptions options;
  options.methods = {"slerp"};
  options.keep_every = {2};
  auto rows = rotinterp::evaluate_clip(*again, "out.bvh", options);
  if (!rows) return fail("eval", rows.error());
  std::printf("eval: %zu rows\n", rows->size());
  if (rows->empty()) return fail("eval", "no rows");

#if WITH_RENDER
  rotinterp::render::Image image(4, 2);
  if (rotinterp::Status s = rotinterp::render::write_png(image, dir / "image.png"); !s) return fail("render", s.error());
  std::printf("render: %ju bytes of PNG\n", static_cast<std::uintmax_t>(std::filesystem::file_size(dir / "image.png")));
#endif
  return 0;
}
