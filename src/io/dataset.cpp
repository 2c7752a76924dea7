#include "rotinterp/io/dataset.h"

#include "rotinterp/clip/bvh_layout.h"
#include "rotinterp/clip/frames.h"
#include "rotinterp/io/write.h"

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <system_error>
#include <tuple>
#include <utility>

namespace rotinterp {

namespace fs = std::filesystem;

namespace {

// `path` lies inside directory `dir` (both as the filesystem resolves them).
bool inside(const fs::path& path, const fs::path& dir) {
  std::error_code ec;
  const fs::path p = fs::weakly_canonical(path, ec), d = fs::weakly_canonical(dir, ec);
  if (ec) return false;
  const fs::path rel = p.lexically_relative(d);
  return !rel.empty() && *rel.begin() != "..";
}

// The input's path as it goes under the output directory.
fs::path relative_to_named(const std::string& input, const std::vector<fs::path>& named) {
  const fs::path in(input);
  fs::path best;
  std::size_t best_length = 0;
  for (const fs::path& n : named) {
    if (n.string() == input) return in.filename();  // named itself
    const fs::path rel = in.lexically_relative(n);
    if (!rel.empty() && *rel.begin() != ".." && n.string().size() >= best_length) {
      best = rel;
      best_length = n.string().size();
    }
  }
  return best.empty() ? in.filename() : best;
}

// Size and CRC-32 of a file's bytes; false when it cannot be read.
bool fingerprint(const std::string& path, std::uintmax_t& size, unsigned long& crc) {
  std::ifstream f(path, std::ios::binary);
  if (!f) return false;
  std::vector<char> buffer(1 << 16);
  crc = crc32(0L, Z_NULL, 0);
  size = 0;
  while (f) {
    f.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    const auto n = static_cast<std::size_t>(f.gcount());
    crc = crc32(crc, reinterpret_cast<const Bytef*>(buffer.data()), static_cast<uInt>(n));
    size += n;
  }
  return f.eof();
}

bool same_bytes(const std::string& a, const std::string& b) {
  std::ifstream fa(a, std::ios::binary), fb(b, std::ios::binary);
  if (!fa || !fb) return false;
  std::vector<char> ba(1 << 16), bb(1 << 16);
  while (fa && fb) {
    fa.read(ba.data(), static_cast<std::streamsize>(ba.size()));
    fb.read(bb.data(), static_cast<std::streamsize>(bb.size()));
    if (fa.gcount() != fb.gcount() || !std::equal(ba.begin(), ba.begin() + fa.gcount(), bb.begin())) return false;
  }
  return fa.eof() && fb.eof();
}

}  // namespace

Result<std::vector<MirroredOutput>> mirror_outputs(const std::vector<std::string>& inputs,
                                                   const std::vector<fs::path>& named, const fs::path& out_dir,
                                                   const std::string& format) {
  std::vector<MirroredOutput> out;
  std::map<fs::path, std::string> taken;
  for (const std::string& input : inputs) {
    if (inside(input, out_dir)) continue;
    fs::path target = out_dir / relative_to_named(input, named);
    std::string ext = format.empty() ? target.extension().string() : "." + format;
    if (!can_write_format(fs::path("x" + ext))) ext = ".bvh";
    target.replace_extension(ext);
    const auto [at, fresh] = taken.emplace(target, input);
    if (!fresh)
      return make_error(at->second + " and " + input + " would both be written to " + target.string());
    out.push_back({input, target});
  }
  return out;
}

std::vector<std::vector<std::string>> duplicate_files(const std::vector<std::string>& files) {
  // Candidates by (size, CRC-32); the bytes decide.
  std::map<std::pair<std::uintmax_t, unsigned long>, std::vector<std::string>> by_fingerprint;
  for (const std::string& f : files) {
    std::uintmax_t size = 0;
    unsigned long crc = 0;
    if (fingerprint(f, size, crc)) by_fingerprint[{size, crc}].push_back(f);
  }
  std::vector<std::vector<std::string>> groups;
  for (auto& [key, candidates] : by_fingerprint) {
    std::sort(candidates.begin(), candidates.end());
    std::vector<bool> placed(candidates.size(), false);
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      if (placed[i]) continue;
      std::vector<std::string> group = {candidates[i]};
      for (std::size_t k = i + 1; k < candidates.size(); ++k)
        if (!placed[k] && same_bytes(candidates[i], candidates[k])) {
          group.push_back(candidates[k]);
          placed[k] = true;
        }
      if (group.size() > 1) groups.push_back(std::move(group));
    }
  }
  std::sort(groups.begin(), groups.end());
  return groups;
}

std::string rate_label_note(const Clip& clip) {
  const std::string& written = frame_time_text(clip);
  const std::optional<Rate> rate = clip_rate(clip);
  if (written.empty() || !rate || !(clip.frame_time > 0.0)) return {};
  // Worth a line: the face value is more than 10 ppm off (".016667": 20 ppm), or on
  // the other side of a whole number, where a script's int(1 / frame_time) takes
  // another rate (59 for 60 Hz). ".0333333" (30.00003 Hz) is not.
  const double spelled = 1.0 / clip.frame_time, hz = rate->hz();
  if (std::abs(spelled - hz) <= 1e-5 * hz && std::floor(spelled) == std::floor(hz)) return {};
  char face[32];
  std::snprintf(face, sizeof face, "%.6g", spelled);
  return "Frame Time " + written + " is " + face + " Hz; read as " + rate->to_string() + " Hz, the rate it rounds";
}

}  // namespace rotinterp
