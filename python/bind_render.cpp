// rotinterp.render: the comparison frames `rotinterp render` draws (render/comparison.h),
// with the command's options under the same names and in the same forms. Compiled
// only where the renderer is built (python/CMakeLists.txt).
#include "common.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/render/comparison.h"
#include "rotinterp/render/option_text.h"
#include "rotinterp/render/context.h"
#include "rotinterp/render/renderer.h"
#include "rotinterp/render/video.h"

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp::python {
namespace {

std::vector<std::string> render(const py::object& input, const std::optional<std::string>& out_dir,
                                const std::optional<std::vector<std::string>>& method_names_in, long long keep_every,
                                const std::optional<std::string>& frames, const std::string& size,
                                const std::string& trail, double trail_window, bool sheet, const std::string& view,
                                const std::optional<std::string>& colour,
                                const std::optional<std::string>& camera, const std::string& focus, bool strip,
                                const std::optional<std::string>& video, double video_fps,
                                const std::optional<std::string>& backend) {
  render::ComparisonOptions o;
  if (!out_dir && !video) value_error("render: give out_dir (frame PNGs), video, or both");
  bool source = false;  // "source": the file's own motion, a panel beside the methods
  if (method_names_in) {
    for (const std::string& m : *method_names_in) {
      source = source || is_source_method(m);
      o.methods.push_back(is_source_method(m) ? std::string(kSourceMethodName) : m);
    }
  } else {
    for (const MethodInfo& m : methods()) o.methods.push_back(m.name);
  }
  if (o.methods.empty()) value_error("methods: no method given (valid: " + method_names() + ")");
  for (const std::string& m : o.methods)
    if (!is_source_method(m)) method_of(m, "methods: ");
  if (source && py::isinstance<Clip>(input))
    value_error("methods: 'source' replays a file's own motion: give the file's path (FBX, glTF, BVH), not a Clip");
  if (keep_every < 1) value_error("keep_every must be a whole number >= 1, got " + std::to_string(keep_every));
  o.keep_every = static_cast<std::size_t>(keep_every);
  if (frames) o.frames = checked(render::parse_frame_range(*frames));
  const auto wh = checked(render::parse_size(size));
  o.width = wh.first;
  o.height = wh.second;
  if (Status s = render::check_image_size(o.width, o.height, view == "side" ? static_cast<int>(o.methods.size()) : 1); !s)
    value_error("size: " + s.error());
  if (backend) {
    const render::Backend b = checked(render::parse_backend(*backend));
    if (!render::backend_available(b)) value_error(std::string(render::backend_name(b)) + " is not available");
    o.backend = b;
  }
  o.trail_joint = trail;
  if (!(trail_window >= 0.0) || !std::isfinite(trail_window))
    value_error("trail_window must be a number of seconds >= 0");
  o.trail_window = trail_window;
  if (sheet && !out_dir) value_error("sheet needs out_dir");
  o.sheet = sheet;
  o.view = checked(render::parse_view(view));
  if (Status s = render::check_view_options(o.view, colour.has_value(), !trail.empty()); !s) value_error(s.error());
  if (colour) o.colouring = checked(render::parse_colouring(*colour));
  if (camera) o.camera = checked(render::parse_camera(*camera));
  o.focus_joint = focus;
  o.strip = strip;
  o.pngs = out_dir.has_value();
  if (video) {
    const auto format = checked(render::video_format(*video));
    if (Status s = render::check_video_size(format, o.width, o.height); !s) value_error(s.error());
    if (video_fps < 0.0 || video_fps > 1000.0 || !std::isfinite(video_fps))
      value_error("video_fps must be within (0, 1000]");
    o.video = *video;
    o.video_fps = video_fps;
  }
  const Clip clip = source ? read_path_with_source_motion(py::str(input).cast<std::string>(), o.source)
                          : clip_or_path(input);
  Result<render::ComparisonResult> r = make_error("");
  {
    py::gil_scoped_release release;
    r = render::render_comparison(clip, out_dir ? std::filesystem::path(*out_dir) : std::filesystem::path(), o);
  }
  const render::ComparisonResult result = checked(std::move(r));
  std::vector<std::string> files;
  for (const auto& f : result.files) files.push_back(f.string());
  return files;
}

}  // namespace

void bind_render(py::module_& m) {
  m.def("render", &render, py::arg("input"), py::arg("out_dir") = py::none(), py::arg("methods") = py::none(),
        py::arg("keep_every") = 10, py::arg("frames") = py::none(), py::arg("size") = "960x540",
        py::arg("trail") = "", py::arg("trail_window") = 1.0, py::arg("sheet") = false, py::arg("view") = "overlay", py::arg("colour") = py::none(),
        py::arg("camera") = py::none(), py::arg("focus") = "", py::arg("strip") = true, py::arg("video") = py::none(),
        py::arg("video_fps") = 0.0, py::arg("backend") = py::none());
}

}  // namespace rotinterp::python
