// render's comparison drawn: each frame's image, the sheet and the video, from the plan.
#include "rotinterp/render/comparison.h"

#include "comparison_panels.h"
#include "png_writers.h"

#include "rotinterp/render/layout.h"
#include "rotinterp/render/video.h"

#include <fmt/format.h>

#include <memory>

namespace rotinterp::render {

namespace fs = std::filesystem;

Result<ComparisonResult> render_comparison(const Clip& clip, const fs::path& out_dir,
                                           const ComparisonOptions& options) {
  auto planned = ComparisonPlan::make(clip, options);
  if (!planned) return planned.failure();
  const ComparisonPlan& plan = *planned;
  const std::vector<std::size_t>& frames = plan.frames();
  std::error_code ec;
  if (options.pngs && fs::exists(out_dir, ec) && !fs::is_directory(out_dir, ec))
    return make_error(out_dir.string() + ": is an existing file, not a directory for the frames");

  auto context = create_context(options.backend ? *options.backend : default_backend());
  if (!context) return context.failure();
  auto renderer = Renderer::create(std::move(context).value(), plan.scene());
  if (!renderer) return renderer.failure();

  ComparisonResult result;
  result.gl = (*renderer)->gl_description();
  result.followed = plan.followed();
  std::unique_ptr<VideoWriter> video;
  if (!options.video.empty()) {
    result.video_fps = options.video_fps > 0.0 ? options.video_fps : plan.video_fps();
    auto opened = VideoWriter::open(options.video, options.width, options.height, result.video_fps);
    if (!opened) return opened.failure();
    video = std::move(opened).value();
  }
  const std::size_t total = frames.size() + (options.sheet ? 1 : 0);
  PngWriters writers(options.pngs ? options.progress : ProgressFn{}, total);
  bool writing = true;  // no write has failed yet
  std::vector<Panel> sheet;
  int rows = 0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    ComparisonPlan::Frame frame = plan.frame(i);
    if (options.sheet) {  // cell (row p, column i) at p · frames + i
      rows = static_cast<int>(frame.cells.size());
      sheet.resize(frames.size() * frame.cells.size());
      for (std::size_t p = 0; p < frame.cells.size(); ++p) sheet[p * frames.size() + i] = std::move(frame.cells[p]);
    }
    auto image = (*renderer)->render(frame.panels, options.width, options.height, plan.columns());
    if (!image) return image.failure();
    if (video) {
      if (Status s = video->write(*image); !s) return s.failure();
      if (!options.pngs && options.progress) options.progress(i + 1, frames.size());
    }
    if (!options.pngs) continue;
    fs::path path = out_dir / fmt::format("frame_{:06d}.png", frames[i]);
    result.files.push_back(path);
    if (!writers.push(std::move(path), std::move(image).value())) {
      writing = false;
      break;
    }
  }
  if (options.sheet && writing) {
    const Rect size =
        sheet_size(grid_layout(rows, plan.columns(), options.width, options.height).front(), frames.size(), rows);
    auto image = (*renderer)->render(sheet, size.width, size.height, static_cast<int>(frames.size()));
    if (!image) return image.failure();
    result.files.push_back(out_dir / "sheet.png");
    (void)writers.push(result.files.back(), std::move(image).value());
  }
  if (Status s = writers.finish(); !s) return s.failure();
  if (video) {
    if (Status s = video->finish(); !s) return s.failure();
    result.video_frames = video->frames();
    result.files.push_back(options.video);
  }
  return result;
}

}  // namespace rotinterp::render
