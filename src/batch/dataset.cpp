// Datasets: clip discovery, shards, mirrored output paths and a folder's rate audit.
#include "rotinterp/batch/dataset.h"
#include "rotinterp/io/files/formats.h"

#include "rotinterp/io/files/file_record.h"
#include "rotinterp/clip/frames.h"
#include "rotinterp/io/read.h"
#include "rotinterp/io/write.h"

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
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

Result<std::vector<std::string>> discover_inputs(const std::vector<fs::path>& paths) {
  std::vector<std::string> files;
  for (const fs::path& p : paths) {
    std::error_code ec;
    const fs::file_status st = fs::status(p, ec);
    if (ec || !fs::exists(st)) return make_error(p.string() + ": no such file or directory");
    if (!fs::is_directory(st)) {
      files.push_back(p.string());
      continue;
    }
    fs::recursive_directory_iterator it(p, fs::directory_options::skip_permission_denied, ec), end;
    if (ec) return make_error(p.string() + ": " + ec.message());
    for (; it != end; it.increment(ec)) {
      if (ec) return make_error(p.string() + ": " + ec.message());
      const fs::path& f = it->path();
      const std::string name = f.filename().string();
      if (!name.empty() && name[0] == '.') {
        if (it->is_directory(ec)) it.disable_recursion_pending();
        continue;
      }
      if (!it->is_regular_file(ec)) continue;
      const std::string ext = f.extension().string();
      if (ext.size() > 1 && importable_extension(ext)) files.push_back(f.string());
    }
  }
  std::sort(files.begin(), files.end());
  files.erase(std::unique(files.begin(), files.end()), files.end());
  return files;
}

bool found_in_directory(const std::string& path, const std::vector<fs::path>& named) {
  for (const fs::path& p : named)
    if (p.string() == path) return false;
  return true;
}

std::vector<std::string> shard_of(const std::vector<std::string>& files, int index, int count) {
  std::vector<std::string> out;
  if (count < 1 || index < 1 || index > count) return out;
  for (std::size_t i = static_cast<std::size_t>(index - 1); i < files.size(); i += static_cast<std::size_t>(count))
    out.push_back(files[i]);
  return out;
}

Result<std::pair<int, int>> parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  auto number = [](const std::string& s, long& v) {
    if (s.empty() || s.size() > 7 || s.find_first_not_of("0123456789") != std::string::npos) return false;
    v = std::strtol(s.c_str(), nullptr, 10);
    return true;
  };
  long i = 0, n = 0;
  if (slash == std::string::npos || !number(text.substr(0, slash), i) || !number(text.substr(slash + 1), n) || n < 1 ||
      n > 1000000 || i < 1 || i > n)
    return make_error("--shard '" + text + "' is not I/N with 1 ≤ I ≤ N");
  return std::make_pair(static_cast<int>(i), static_cast<int>(n));
}

Result<std::vector<MirroredOutput>> mirror_outputs(const std::vector<std::string>& inputs,
                                                   const std::vector<fs::path>& named, const fs::path& out_dir,
                                                   const std::string& format) {
  std::vector<MirroredOutput> out;
  std::map<fs::path, std::string> taken;
  for (const std::string& input : inputs) {
    if (inside(input, out_dir)) continue;
    fs::path target = out_dir / relative_to_named(input, named);
    std::string ext = format.empty() ? target.extension().string() : "." + format;
    if (!can_write_format(fs::path("x" + ext))) ext = "." + std::string(formats().front().name);  // the default
    target.replace_extension(ext);
    const auto [at, fresh] = taken.emplace(target, input);
    if (!fresh)
      return make_error(at->second + " and " + input + " would both be written to " + target.string());
    out.push_back({input, target});
  }
  // Outputs of an earlier run inside the inputs are not inputs; but when that leaves
  // nothing (resample DIR -o DIR) the run would do nothing and say it succeeded.
  if (out.empty() && !inputs.empty())
    return make_error(out_dir.string() + ": all " + std::to_string(inputs.size()) +
                      " input file(s) lie inside this output folder, so none would be written; give -o a folder "
                      "outside the inputs");
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
