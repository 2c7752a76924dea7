// A synthetic clip's spec line, and the spec file beside the clip that rebuilds its motion.
#include "rotinterp/clip/synth_spec.h"

#include <charconv>
#include <fstream>
#include <sstream>

namespace rotinterp {

namespace {

std::string number_text(double x) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

}  // namespace

std::string synth_spec(const SynthOptions& o) {
  return std::string("kind=") + synth_kind_name(o.kind) + " seconds=" + number_text(o.seconds) +
         " fps=" + o.fps.to_string() + " seed=" + std::to_string(o.seed) +
         " joints=" + std::to_string(o.kind == SynthKind::walk ? 31 : o.joints);
}

Result<SynthOptions> parse_synth_spec(std::string_view spec) {
  SynthOptions o;
  std::istringstream in{std::string(spec)};
  std::string item;
  while (in >> item) {
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos) return make_error("synth spec item '" + item + "' is not key=value");
    const std::string key = item.substr(0, eq), value = item.substr(eq + 1);
    const char* first = value.data();
    const char* last = value.data() + value.size();
    if (key == "kind") {
      auto k = parse_synth_kind(value);
      if (!k) return k.failure();
      o.kind = *k;
    } else if (key == "fps") {
      auto r = parse_rate(value);
      if (!r) return r.failure();
      o.fps = *r;
    } else if (key == "seconds") {
      if (std::from_chars(first, last, o.seconds).ptr != last) return make_error("synth spec: bad seconds '" + value + "'");
    } else if (key == "seed") {
      if (std::from_chars(first, last, o.seed).ptr != last) return make_error("synth spec: bad seed '" + value + "'");
    } else if (key == "joints") {
      if (std::from_chars(first, last, o.joints).ptr != last) return make_error("synth spec: bad joints '" + value + "'");
    } else {
      return make_error("synth spec: unknown key '" + key + "'");
    }
  }
  return o;
}

std::filesystem::path synth_spec_path(const std::filesystem::path& clip_file) {
  std::filesystem::path p = clip_file;
  p += ".synth";
  return p;
}

Result<SynthMotion> read_synth_spec(const std::filesystem::path& clip_file) {
  const std::filesystem::path p = synth_spec_path(clip_file);
  std::ifstream in(p);
  std::string line;
  if (!in || !std::getline(in, line)) return make_error(p.string() + ": no synth spec (not made by rotinterp synth?)");
  auto o = parse_synth_spec(line);
  if (!o) return o.failure(p.string() + ": ");
  auto m = make_synth_motion(*o);
  if (!m) return m.failure(p.string() + ": ");
  return m;
}

}  // namespace rotinterp
