// rotinterp resample IN -o OUT [--fps HZ | --keep-every N] [--method NAME] [--method-for JOINT=NAME ...]
//                    [--translation linear|cubic] [--range START:END] [--anim NAME|INDEX] [--bvh-order ZXY] [--quiet]
#include "common.h"
#include "rotinterp/clip/frames.h"
#include "rotinterp/clip/resample.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/io/atomic_file.h"
#include "rotinterp/io/read.h"
#include "rotinterp/io/write.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp::cli {

namespace {

struct ResampleArgs {
  std::string input, output;
  std::string fps, keep_every, method = kDefaultResampleMethod, translation = "cubic", range, anim, bvh_order = "ZXY";
  std::vector<std::string> method_for;
  bool quiet = false;
  bool fbx_ascii = false;
};

// A number of seconds ≥ 0, or nothing for an empty text.
bool parse_seconds(const std::string& text, std::optional<double>& out) {
  if (text.empty()) return true;
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(v) || v < 0.0) return false;
  out = v;
  return true;
}

bool valid_bvh_order(std::string order) {
  std::sort(order.begin(), order.end());
  return order == "XYZ";
}

int run_resample(const ResampleArgs& a) {
  const auto started = std::chrono::steady_clock::now();
  ResampleOptions opt;
  // Everything that can be checked without the input is checked first (exit 2).
  if (!a.fps.empty() && !a.keep_every.empty()) return fail_usage("give either --fps or --keep-every, not both");
  if (!a.fps.empty()) {
    auto r = parse_rate_option("--fps", a.fps);
    if (!r) return fail_usage(r.error());
    opt.fps = *r;
  }
  if (!a.keep_every.empty()) {
    auto n = parse_whole_option("--keep-every", a.keep_every, 1, kMaxKeepEvery);
    if (!n) return fail_usage(n.error());
    opt.keep_every = static_cast<std::size_t>(*n);
  }
  if (!find_method(a.method)) return fail_usage("unknown method '" + a.method + "' (valid: " + method_names() + ")");
  opt.method = a.method;
  for (const std::string& item : a.method_for) {
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == item.size())
      return fail_usage("--method-for '" + item + "' must be JOINT=METHOD");
    const std::string joint = item.substr(0, eq), method = item.substr(eq + 1);
    if (!find_method(method))
      return fail_usage("unknown method '" + method + "' in --method-for " + item + " (valid: " + method_names() + ")");
    opt.method_for.emplace_back(joint, method);
  }
  auto translation = parse_translation_interp(a.translation);
  if (!translation) return fail_usage("--translation: " + translation.error());
  opt.translation = *translation;
  if (!a.range.empty()) {
    const std::size_t colon = a.range.find(':');
    std::optional<double> s, e;
    if (colon == std::string::npos || !parse_seconds(a.range.substr(0, colon), s) ||
        !parse_seconds(a.range.substr(colon + 1), e))
      return fail_usage("--range '" + a.range + "' must be START:END in seconds (either may be empty), e.g. 1.5:4");
    TimeRange r;
    if (s) r.start = *s;
    if (e) r.end = *e;
    if (!(r.end > r.start)) return fail_usage("--range '" + a.range + "': END must be after START");
    opt.range = r;
  }
  if (!valid_bvh_order(a.bvh_order)) return fail_usage("--bvh-order '" + a.bvh_order + "' must be a permutation of XYZ, e.g. ZXY");
  if (!can_write_format(a.output))
    return fail_usage("output '" + a.output + "': unknown format (use .bvh, .fbx, .glb, .gltf or .dae)");
  protect_input(a.input);
  if (Status s = check_not_an_input(a.output); !s) return fail(s.error());

  // Stage names on the progress line (reading and writing long clips take seconds).
  const bool show = !a.quiet && ::isatty(STDERR_FILENO);
  auto stage = [show](const std::string& what) {
    if (show) std::fprintf(stderr, "\r\033[K%s …", what.c_str());
  };
  ReadOptions read_options;
  read_options.animation = a.anim;
  stage("reading " + a.input);
  auto clip = read_clip(a.input, read_options);
  end_progress(a.quiet);
  if (!clip) return fail(clip.error());

  opt.progress = make_progress("resample", a.quiet);
  auto out = resample_clip(*clip, opt);
  end_progress(a.quiet);
  if (!out) return fail(a.input + ": " + out.error());

  WriteOptions write_options;
  write_options.bvh_order = a.bvh_order;
  write_options.fbx_ascii = a.fbx_ascii;
  write_options.on_warning = warn;
  stage("writing " + a.output);
  const Status written = write_clip(*out, a.output, write_options);
  end_progress(a.quiet);
  if (!written) return fail(written.error());

  if (!a.quiet) {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    const std::optional<Rate> in_rate = clip_rate(*clip);
    const std::string from = in_rate ? in_rate->to_string() + " Hz" : "unknown rate";
    std::string how;
    if (opt.keep_every)
      how = fmt::format("keys every {} frame{}", *opt.keep_every, *opt.keep_every == 1 ? "" : "s");
    else
      how = fmt::format("{} → {} Hz", from, opt.fps ? opt.fps->to_string() : (in_rate ? in_rate->to_string() : clip_rate(*out) ? clip_rate(*out)->to_string() : "?"));
    std::string methods = opt.method;
    if (!opt.method_for.empty()) methods += fmt::format(" (+{} per-joint override{})", opt.method_for.size(),
                                                        opt.method_for.size() == 1 ? "" : "s");
    fmt::print("{} → {}: {} → {} frames ({}), method {}, translation {}, {:.3f} s\n", a.input, a.output,
               clip->frame_count(), out->frame_count(), how, methods, translation_interp_name(opt.translation), seconds);
  }
  return kExitOk;
}

}  // namespace

void add_resample_command(CLI::App& app, int& exit_code) {
  auto* sub = app.add_subcommand("resample", "Resample a clip: change its frame rate or rebuild it from sparse keys");
  auto a = std::make_shared<ResampleArgs>();
  sub->add_option("IN", a->input, "Input clip (BVH, FBX, glTF/GLB, Collada, … — anything assimp reads)")->required();
  sub->add_option("-o,--output", a->output, "Output file; the format follows the extension: bvh, fbx, glb, gltf, dae")
      ->required();
  sub->add_option("--fps", a->fps,
                  "Output rate in Hz: a decimal (30, 59.94) or a rational (30000/1001). Frames at start + k/HZ, "
                  "k = 0 … floor(duration·HZ + 1e-9); Frame Time = 1/HZ");
  sub->add_option("--keep-every", a->keep_every,
                  "Keep every Nth frame (and the last) as keys and rebuild every frame from them (N ≥ 1)");
  sub->add_option("--method", a->method,
                  std::string("Rotation interpolator for every joint (see 'rotinterp methods'); default ") +
                      kDefaultResampleMethod);
  sub->add_option("--method-for", a->method_for, "Per-joint override JOINT=METHOD (repeatable)");
  sub->add_option("--translation", a->translation,
                  "Translation tracks: linear, or cubic (default: C¹, Steffen tangents — never overshoots between keys)");
  sub->add_option("--range", a->range,
                  "Cut START:END (seconds from the first frame; either side may be empty) before resampling");
  sub->add_option("--anim", a->anim, "Animation to read: its name or index (default the first)");
  sub->add_option("--bvh-order", a->bvh_order,
                  "Euler order for BVH output of joints without a BVH layout (non-BVH input); default ZXY");
  sub->add_flag("--fbx-ascii", a->fbx_ascii, "FBX output as ASCII FBX 7.4 (default: binary FBX 7.4, which Blender needs)");
  sub->add_flag("-q,--quiet", a->quiet, "No progress and no summary line");
  sub->callback([a, &exit_code] { exit_code = run_resample(*a); });
}

}  // namespace rotinterp::cli
