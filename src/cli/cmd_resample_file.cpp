// One file's resample: read (one take), resample, write; the source's own FBX curves written back where they can be.
#include "cmd_resample.h"
#include "common.h"
#include "rotinterp/io/files/file_record.h"
#include "rotinterp/clip/frames.h"
#include "rotinterp/clip/resample_loop.h"
#include "rotinterp/io/files/atomic_file.h"
#include "rotinterp/io/fbx/fbx_source.h"
#include "rotinterp/io/files/formats.h"
#include "rotinterp/io/read.h"
#include "rotinterp/io/write.h"

#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rotinterp::cli {

Result<ResampledFile> resample_input(FileRun& run, const ResampleArgs& a, const ResampleOptions& opt,
                                     const std::function<void(const std::string&)>& stage) {
  run.started = std::chrono::steady_clock::now();
  ReadOptions read_options;
  read_options.animation = a.anim;
  read_options.unit = a.unit_m;
  read_options.allow_external_files = a.allow_external_files;
  read_options.on_warning = warn;
  read_options.threads = opt.threads;
  stage("reading " + run.input);
  // --method source: the frames come from the grid and the default method, then the
  // joints the file has its own motion for are evaluated on them (io/source_motion.h).
  const bool source = opt.method == kSourceMethodName;
  std::optional<FileSource> own;
  Result<Clip> clip = make_error("");
  if (source) {
    auto read = read_file_source(run.input, read_options);
    if (!read) return read.failure();
    own = std::move(*read);
    clip = own->clip;
  } else {
    clip = read_clip(run.input, read_options);
  }
  if (!clip) return clip.failure();
  run.frame_time = frame_time_text(*clip);
  run.rate = clip_rate(*clip);
  run.frames = clip->frame_count();
  run.joints = clip->skeleton.joints.size();
  run.duration = clip->end_time() - clip->start_time();
  run.unit = clip->unit;

  Result<Clip> out = make_error("");
  if (a.loop_request) {
    auto cycle = resample_cycle(*clip, opt, a.loop_request->form);
    if (!cycle) return cycle.failure(run.input + ": ");
    run.cycle = cycle->summary();
    out = std::move(cycle->clip);
  } else {
    ResampleOptions base = opt;
    if (source) base.method = kDefaultResampleMethod;
    out = resample_clip(std::move(*clip), base);  // the clip is not needed after
  }
  if (!out) return out.failure(run.input + ": ");
  ResampledFile done{std::move(*out), std::move(own), {}};
  for (const auto& [joint, method] : opt.method_for) done.keep.push_back(joint);  // they keep their method
  if (done.own) {
    run.replayed = replay_source_rotations(done.clip, *done.own, done.keep);
    run.replays = done.own->replays;
  }
  if (a.out_unit_m) convert_unit(done.clip, *a.out_unit_m, "--out-unit " + a.out_unit);
  run.output_metres_per_unit = done.clip.unit.metres_per_unit;
  run.output_frames = done.clip.frame_count();
  run.output_rate = clip_rate(done.clip);
  return done;
}

WriteOptions resample_write_options(const ResampleArgs& a, const ResampleOptions& opt, FileRun& run) {
  WriteOptions write_options;
  write_options.source = run.input;
  write_options.on_kept = [&run](const std::string& kept) { run.kept = kept; };
  write_options.bvh_order = a.bvh_order;
  write_options.fbx_ascii = a.fbx_ascii;
  write_options.on_warning = warn;
  write_options.threads = opt.threads;
  return write_options;
}

Status write_resampled(FileRun& run, const ResampledFile& done, const ResampleArgs& a, const ResampleOptions& opt,
                       const std::function<void(const std::string&)>& stage) {
  stage("writing " + run.output.string());
  const std::optional<FileSource>& own = done.own;
  const Clip* out = &done.clip;
  const std::vector<std::string>& keep = done.keep;
  Status written = Ok{};
  const FormatInfo* out_format = format_of(run.output);
  if (own && own->fbx && !opt.fps && out_format && out_format->id == FormatId::fbx) {
    // The source's own key times: its curves go back as stored (io/fbx/fbx_source.h).
    auto fbx = encode_source_fbx(*out, *own->fbx, keep, a.fbx_ascii, run.input);
    if (!fbx) return fbx.failure();
    run.copied_curves = fbx->copied;
    written = write_file_atomically(run.output, [&](std::ostream& stream) -> Status {
      stream.write(fbx->bytes.data(), static_cast<std::streamsize>(fbx->bytes.size()));
      return Ok{};
    });
  } else {
    written = write_clip(*out, run.output, resample_write_options(a, opt, run));
  }
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - run.started).count();
  return written;
}

Status resample_file(FileRun& run, const ResampleArgs& a, const ResampleOptions& opt,
                     const std::function<void(const std::string&)>& stage) {
  Result<ResampledFile> done = resample_input(run, a, opt, stage);
  if (!done) return done.failure();
  return write_resampled(run, *done, a, opt, stage);
}

}  // namespace rotinterp::cli
