// The steps both the dispatch and the importer's in-process read run (read_parts.h).
#include "rotinterp/io/record/read_parts.h"
#include "rotinterp/io/files/formats.h"
#include "rotinterp/io/files/huge_pages.h"
#include "rotinterp/io/files/file_errors.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <memory>
#include <string_view>
#include <system_error>

namespace rotinterp {

namespace fs = std::filesystem;

namespace {

// A file's bytes, read with read(2) into one buffer sized from fstat. Not
// memory-mapped: a file truncated while it is parsed (an exporter still writing it)
// would raise SIGBUS in a mapping, while a read just ends early and the parser
// reports the file as truncated.
class FileText {
 public:
  Status open(const fs::path& path, const std::string& label) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return make_error(label + ": cannot open for reading: " + std::strerror(errno));
    struct stat st {};
    std::size_t capacity = (::fstat(fd, &st) == 0 && st.st_size > 0) ? static_cast<std::size_t>(st.st_size) : 0;
    buffer_.reset(new char[capacity + 1]);  // uninitialized: read(2) fills it
    advise_huge_pages(buffer_.get(), capacity + 1);
    ++capacity;  // one byte more than fstat said, so a full buffer means the file grew
    for (;;) {
      if (size_ == capacity) {
        std::unique_ptr<char[]> bigger(new char[2 * capacity]);
        std::memcpy(bigger.get(), buffer_.get(), size_);
        buffer_ = std::move(bigger);
        capacity *= 2;
      }
      const ssize_t got = ::read(fd, buffer_.get() + size_, capacity - size_);
      if (got < 0 && errno == EINTR) continue;
      if (got < 0) {
        const std::string why = std::strerror(errno);
        ::close(fd);
        return make_error(label + ": read failed: " + why);
      }
      if (got == 0) break;
      size_ += static_cast<std::size_t>(got);
    }
    ::close(fd);
    return Ok{};
  }
  std::string_view text() const { return std::string_view(buffer_.get(), size_); }

 private:
  std::unique_ptr<char[]> buffer_;
  std::size_t size_ = 0;
};

// The first `bytes` bytes of the file (fewer where it is shorter).
std::string file_head(const fs::path& path, std::size_t bytes) {
  std::ifstream f(path, std::ios::binary);
  std::string head(bytes, '\0');
  f.read(head.data(), static_cast<std::streamsize>(bytes));
  head.resize(static_cast<std::size_t>(f.gcount()));
  return head;
}

bool looks_like_bvh(const std::string& text) {
  std::size_t i = 0;
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) i = 3;  // UTF-8 BOM
  while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  return text.compare(i, 9, "HIERARCHY") == 0;
}

}  // namespace

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string extension_of(const fs::path& path) {
  std::string ext = lower(path.extension().string());
  if (!ext.empty() && ext[0] == '.') ext.erase(0, 1);
  return ext;
}

bool is_bvh(const fs::path& path, const std::string& ext) {
  if (is_format(ext, FormatId::bvh)) return true;
  return looks_like_bvh(file_head(path, 64));
}

// The clip comes from our pass: the file's values in double precision (assimp's
// float keys would use up half of the 1e-4° round-trip budget).
Result<BvhFile> read_bvh_file(const fs::path& path, ClipFileInfo& info, const Warnings& warn) {
  const std::string label = path.string();
  // A header that fails in the file's first MiB fails before the rest is read.
  const std::string head = file_head(path, kBvhHeadBytes + 1);
  // (A byte order mark and UTF-16 are left to parse_bvh, which skips UTF-8's and names UTF-16.)
  const bool marked = head.rfind("\xEF\xBB\xBF", 0) == 0 || head.rfind("\xFF\xFE", 0) == 0 ||
                      head.rfind("\xFE\xFF", 0) == 0 || (head.size() > 1 && (head[0] == '\0' || head[1] == '\0'));
  const std::string_view first = std::string_view(head).substr(0, kBvhHeadBytes);
  if (Status st = marked ? Status(Ok{}) : check_bvh_head(first, head.size() <= kBvhHeadBytes, label); !st)
    return st.failure();
  FileText text;
  if (Status st = text.open(path, label); !st) return make_error(st.error(), file_error::unreadable);
  Result<BvhFile> bvh = parse_bvh(text.text(), label);
  if (!bvh) return make_error(bvh.error(), file_error::unreadable);
  info.format = format_info(FormatId::bvh).name;
  if (bvh->extra_rows > 0)
    warn(label + ": " + std::to_string(bvh->extra_rows) + " data row(s) after the " + std::to_string(bvh->frames) +
         " declared frames ignored");
  return bvh;
}

Status bvh_file_to_clip(const BvhFile& bvh, const std::string& animation_name, const fs::path& path,
                        const ReadOptions& options, ClipFileInfo& info) {
  AnimationSummary s;
  s.name = animation_name;
  s.duration = static_cast<double>(bvh.frames - 1) * bvh.frame_time;
  s.ticks_per_second = 1.0 / bvh.frame_time;
  s.channels = bvh.joints.size();
  s.keys = bvh.frames;
  s.frame_rate_hz = 1.0 / bvh.frame_time;
  s.rate_stated = true;  // its Frame Time
  info.animations.push_back(s);
  if (!options.animation.empty() && options.animation != "0" && options.animation != s.name)
    return make_error(path.string() + ": a BVH file has one animation (0); there is no animation '" +
                      options.animation + "'");
  info.clip = bvh_to_clip(bvh, path.stem().string(), options.threads);
  return Ok{};
}

namespace {

// The clip's unit, decided once for every reader (clip/units.h): FBX states its own
// (the importer read UnitScaleFactor); glTF is metres by its spec and Collada's
// <unit> is applied by assimp, so both are in metres; any other file states none.
void settle_unit(ClipFileInfo& info, const std::string& label, const ReadOptions& options) {
  ClipUnit& unit = info.clip.unit;
  const FormatInfo* format = format_named(info.format);
  if (unit.origin != UnitOrigin::declared && format && format->unit == "metres")
    unit = {1.0, UnitOrigin::declared, "declared by the format: " + info.format + " is in metres"};
  if (unit.origin == UnitOrigin::declared) {
    if (options.unit)
      Warnings{&options.on_warning, &info.warnings}(label + ": the file declares its unit (" + unit_name(unit.metres_per_unit) +
                         "); --unit is ignored");
    return;
  }
  if (options.unit) {
    unit = {*options.unit, UnitOrigin::given, "given: --unit " + unit_name(*options.unit)};
    return;
  }
  unit = infer_unit(info.clip);
}

}  // namespace

Status check_clip(ClipFileInfo& info, const std::string& label, const ReadOptions& options) {
  info.clip.source_format = info.format;
  if (Status s = info.clip.validate(); !s) return make_error(label + ": " + s.error(), file_error::unreadable);
  const std::vector<Joint>& joints = info.clip.skeleton.joints;
  std::vector<std::size_t> depth(joints.size(), 1);
  for (std::size_t j = 0; j < joints.size(); ++j) {
    if (joints[j].parent >= 0) depth[j] = depth[static_cast<std::size_t>(joints[j].parent)] + 1;
    if (depth[j] > kMaxJointDepth)
      return make_error(label + ": joints nested more than " + std::to_string(kMaxJointDepth) +
                            " levels deep (the most rotinterp reads)",
                        file_error::unreadable);
  }
  settle_unit(info, label, options);
  return Ok{};
}

}  // namespace rotinterp
