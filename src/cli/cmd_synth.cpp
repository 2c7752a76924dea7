// rotinterp synth OUT [--kind KIND] [--seconds S] [--fps HZ] [--seed N] [--joints N] [--quiet]
#include "common.h"
#include "options.h"
#include "rotinterp/clip/synth.h"
#include "rotinterp/clip/synth_spec.h"
#include "rotinterp/io/files/atomic_file.h"
#include "rotinterp/io/files/file_record.h"
#include "rotinterp/io/write.h"
#include "rotinterp/io/files/formats.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <ostream>
#include <string>

namespace rotinterp::cli {

namespace {

struct SynthArgs {
  std::string output, kind = "walk", seconds = "4", fps = "30", seed = "1", joints = "12";
  bool quiet = false;
};

int run_synth(const SynthArgs& a) {
  const auto started = std::chrono::steady_clock::now();
  SynthOptions o;
  auto kind = parse_synth_kind(a.kind);
  if (!kind) return fail_usage("--kind: " + kind.error());
  o.kind = *kind;
  {
    errno = 0;
    char* end = nullptr;
    o.seconds = std::strtod(a.seconds.c_str(), &end);
    if (a.seconds.empty() || end != a.seconds.c_str() + a.seconds.size() || errno == ERANGE || !std::isfinite(o.seconds) ||
        o.seconds <= 0.0)
      return fail_usage("--seconds '" + a.seconds + "' must be a number greater than 0");
  }
  auto fps = parse_rate_value("--fps", a.fps);
  if (!fps) return fail_usage(fps.error());
  o.fps = *fps;
  {
    errno = 0;
    char* end = nullptr;
    o.seed = std::strtoull(a.seed.c_str(), &end, 10);
    if (a.seed.empty() || a.seed[0] == '-' || end != a.seed.c_str() + a.seed.size() || errno == ERANGE)
      return fail_usage("--seed '" + a.seed + "' must be a whole number ≥ 0");
  }
  {
    errno = 0;
    char* end = nullptr;
    const long n = std::strtol(a.joints.c_str(), &end, 10);
    if (a.joints.empty() || end != a.joints.c_str() + a.joints.size() || errno == ERANGE || n < 1 || n > 10000)
      return fail_usage("--joints '" + a.joints + "' must be a whole number from 1 to 10000");
    o.joints = static_cast<int>(n);
  }
  if (!can_write_format(a.output))
    return fail_usage("output '" + a.output + "': unknown format (use " + format_names(writable, " or ", true) + ")");
  auto clip = make_synth_file_clip(o);
  if (!clip) return fail_usage(clip.error());
  // The spec next to the clip, so the analytic truth can be rebuilt (eval --truth).
  // It is written (not committed) first, so that once the clip is committed only a
  // rename is left to fail. An older spec is moved aside while the clip is written:
  // put back if the write fails, dropped if it succeeds or the run is interrupted,
  // so a new clip never sits beside the spec of another one.
  const std::filesystem::path spec_path = synth_spec_path(a.output);
  const std::string spec = synth_spec(o);
  AtomicOutput spec_out(spec_path, TempKind::unnamed);
  if (Status s = write_to(spec_out, [&](std::ostream& os) -> Status {
        os << spec << "\n";
        return Ok{};
      });
      !s)
    return fail(s.error());
  {
    AtomicOutput old_spec(spec_path);
    std::error_code ec;
    const bool had_spec = std::filesystem::exists(spec_path, ec);
    if (had_spec) std::filesystem::rename(spec_path, old_spec.temp_path(), ec);
    if (ec) return fail(spec_path.string() + ": cannot replace: " + ec.message());
    if (Status s = write_clip(*clip, a.output); !s) {
      if (had_spec) (void)old_spec.commit();
      return fail(s.error());
    }
  }
  if (Status s = spec_out.commit(); !s) return fail(s.error());
  if (!a.quiet) {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    fmt::print("{}: {} frames × {} joints ({}), {:.3f} s; spec in {}\n", a.output, clip->frame_count(),
               clip->skeleton.joints.size(), spec, seconds, spec_path.string());
  }
  return kExitOk;
}

}  // namespace

void add_synth_command(CLI::App& app, int& exit_code) {
  auto* sub = app.add_subcommand(
      "synth", "Write a synthetic clip whose motion is known analytically (random BVH rotation orders per joint)");
  auto a = std::make_shared<SynthArgs>();
  add_output_option(*sub, a->output, "Output file (bvh, fbx, glb, gltf, dae), -o OUT or just OUT; OUT.synth gets the spec",
                    "OUT")
      ->required();
  sub->add_option("--kind", a->kind,
                  "constant (constant angular velocity per joint), smooth (random rotation-vector curves), "
                  "spin (past 2π, accelerating), walk (31-joint walking figure); default walk");
  sub->add_option("--seconds", a->seconds, "Duration in seconds (default 4)");
  add_fps_option(*sub, a->fps, "default 30");
  sub->add_option("--seed", a->seed, "Random seed: rotation orders, axes, amplitudes (default 1)");
  sub->add_option("--joints", a->joints, "Joints for constant/smooth/spin (default 12; walk always has 31)");
  add_quiet_option(*sub, a->quiet);
  sub->callback([a, &exit_code] { exit_code = run_synth(*a); });
}

}  // namespace rotinterp::cli
