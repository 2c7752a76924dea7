// The text of render's options (command line, Python keywords): frame ranges, sizes, colourings, cameras.
#include "rotinterp/render/option_text.h"

#include "rotinterp/render/renderer.h"

#include <charconv>
#include <string>
#include <vector>

namespace rotinterp::render {

namespace {

Result<std::size_t> parse_count(std::string_view text, const char* what) {
  std::size_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size())
    return make_error(std::string(what) + " '" + std::string(text) + "' is not a non-negative integer");
  return value;
}

}  // namespace

Result<FrameRange> parse_frame_range(std::string_view text) {
  std::vector<std::string_view> parts;
  for (std::size_t begin = 0;;) {
    const std::size_t colon = text.find(':', begin);
    parts.push_back(text.substr(begin, colon == std::string_view::npos ? std::string_view::npos : colon - begin));
    if (colon == std::string_view::npos) break;
    begin = colon + 1;
  }
  if (parts.size() > 3) return make_error("--frames '" + std::string(text) + "' is not START[:END[:STEP]]");
  FrameRange r;
  auto start = parse_count(parts[0], "--frames start");
  if (!start) return start.failure();
  r.start = r.end = *start;
  if (parts.size() > 1) {
    auto end = parse_count(parts[1], "--frames end");
    if (!end) return end.failure();
    r.end = *end;
  }
  if (parts.size() > 2) {
    auto step = parse_count(parts[2], "--frames step");
    if (!step) return step.failure();
    r.step = *step;
  }
  if (r.end < r.start) return make_error("--frames '" + std::string(text) + "': END is before START");
  if (r.step == 0) return make_error("--frames '" + std::string(text) + "': STEP must be at least 1");
  return r;
}

Result<std::pair<int, int>> parse_size(std::string_view text) {
  const std::size_t x = text.find_first_of("xX");
  if (x == std::string_view::npos) return make_error("--size '" + std::string(text) + "' is not WxH (e.g. 960x540)");
  auto w = parse_count(text.substr(0, x), "--size width");
  auto h = parse_count(text.substr(x + 1), "--size height");
  if (!w || !h) return make_error("--size '" + std::string(text) + "' is not WxH (e.g. 960x540)");
  if (*w > 1000000 || *h > 1000000 || *w == 0 || *h == 0)
    return make_error("--size '" + std::string(text) + "' is outside 1…" + std::to_string(kMaxImageSide) + " per side");
  return std::pair<int, int>(static_cast<int>(*w), static_cast<int>(*h));
}

Result<Colouring> parse_colouring(std::string_view name) {
  if (name == "error") return Colouring::error;
  if (name == "method") return Colouring::method;
  return make_error("--colour '" + std::string(name) + "' is not error or method");
}

Result<View> parse_view(std::string_view name) {
  if (name == "overlay") return View::overlay;
  if (name == "side") return View::side;
  return make_error("--view '" + std::string(name) + "' is not overlay or side");
}

Status check_view_options(View view, bool colour_given, bool trail_given) {
  if (view == View::overlay && colour_given)
    return make_error("--colour applies to --view side: the overlay draws each method in its own colour");
  if (view == View::overlay && trail_given)
    return make_error("--trail draws one method's curve in each panel: use it with --view side");
  return Ok{};
}

Result<CameraMode> parse_camera(std::string_view name) {
  if (name == "fixed") return CameraMode::fixed;
  if (name == "follow") return CameraMode::follow;
  return make_error("--camera '" + std::string(name) + "' is not fixed or follow");
}

}  // namespace rotinterp::render
