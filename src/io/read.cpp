// The clip reader's dispatch: the file checked, then BVH by our own pass here and
// every other format (or a BVH to cross-check) by the importer process (import.h).
#include "rotinterp/io/read.h"

#include "rotinterp/io/files/one_line.h"
#include "rotinterp/io/import/import.h"
#include "rotinterp/io/process/importer.h"
#include "rotinterp/io/record/read_parts.h"

#include <new>
#include <set>
#include <sstream>
#include <stdexcept>

namespace rotinterp {

namespace {

namespace fs = std::filesystem;

// BVH by our own pass, in this process.
Status read_bvh(const fs::path& path, const ReadOptions& options, ClipFileInfo& info) {
  const Warnings warn{&options.on_warning, &info.warnings};
  Result<BvhFile> bvh = read_bvh_file(path, info, warn);
  if (!bvh) return bvh.failure();
  if (Status st = bvh_file_to_clip(*bvh, "", path, options, info); !st) return st;
  return check_clip(info, path.string(), options);
}

// The importer's reading, its warnings passed to on_warning once it is done, in order.
Result<ClipFileInfo> read_imported(const fs::path& path, const ReadOptions& options) {
  Result<wire::ReadOutcome> got = detail::read_in_importer(path, options);
  if (!got) return got.failure();
  for (const std::string& w : got->info.warnings)
    if (options.on_warning) options.on_warning(w);
  if (got->error) return make_error(*got->error, got->kind);
  return std::move(got->info);
}

Result<ClipFileInfo> load(const fs::path& path, const ReadOptions& options) {
  if (Status s = check_file(path, path.string()); !s) return s.failure();
  const std::string ext = extension_of(path);
  const bool bvh = is_bvh(path, ext);
  // A file of a format no reader knows (a .py, a .txt) is not handed to assimp, whose
  // tokenizers would name their own confusion instead.
  if (!bvh && !ext.empty() && !importable_extension(ext))
    return make_error(path.string() + ": not a motion file (formats read: " + read_formats_text() + ")",
                      ErrorKind::unreadable);
  if (!bvh || options.cross_check_with_assimp) return read_imported(path, options);
  ClipFileInfo info;
  info.format = ext;
  if (Status st = read_bvh(path, options, info); !st) return st.failure();
  return info;
}

}  // namespace



Result<ClipFileInfo> inspect_clip(const fs::path& path, const ReadOptions& options) {
  try {
    return load(path, options);
  } catch (const std::bad_alloc&) {
    return make_error(path.string() + ": out of memory while reading", ErrorKind::out_of_memory);
  } catch (const std::exception& e) {
    return make_error(path.string() + ": " + one_line(e.what()));
  }
}

Result<Clip> read_clip(const fs::path& path, const ReadOptions& options) {
  Result<ClipFileInfo> info = inspect_clip(path, options);
  if (!info) return info.failure();
  return std::move(info->clip);
}

}  // namespace rotinterp
