// The clip reader's dispatch: the file checked, then BVH by our own pass here and
// every other format (or a BVH to cross-check) by the importer process (import.h).
#include "rotinterp/io/read.h"

#include "rotinterp/io/files/one_line.h"
#include "rotinterp/io/import/import.h"
#include "rotinterp/io/process/importer.h"
#include "rotinterp/io/record/read_parts.h"
#include "rotinterp/io/files/file_errors.h"

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

// The outcome of a reading that failed with `error` before any reader ran.
ReadOutcome failed(const Error& error) {
  ReadOutcome out;
  out.error = error.message;
  out.kind = error.kind;
  return out;
}

// The importer's reading, its warnings passed to on_warning once it is done, in order.
ReadOutcome read_imported(const fs::path& path, const ReadOptions& options) {
  Result<ReadOutcome> got = detail::read_in_importer(path, options);
  if (!got) return failed(got.failure());
  for (const std::string& w : got->info.warnings)
    if (options.on_warning) options.on_warning(w);
  return std::move(*got);
}

ReadOutcome load(const fs::path& path, const ReadOptions& options) {
  if (Status s = check_file(path, path.string()); !s) return failed(s.failure());
  const std::string ext = extension_of(path);
  const bool bvh = is_bvh(path, ext);
  // A file of a format no reader knows (a .py, a .txt) is not handed to assimp, whose
  // tokenizers would name their own confusion instead.
  if (!bvh && !ext.empty() && !importable_extension(ext))
    return failed(make_error(path.string() + ": not a motion file (formats read: " + read_formats_text() + ")",
                             file_error::unreadable));
  if (!bvh || options.cross_check_with_assimp) return read_imported(path, options);
  ReadOutcome out;
  out.info.format = ext;
  if (Status st = read_bvh(path, options, out.info); !st) return failed(st.failure());
  return out;
}

}  // namespace



ReadOutcome inspect_clip_outcome(const fs::path& path, const ReadOptions& options) {
  try {
    return load(path, options);
  } catch (const std::bad_alloc&) {
    return failed(make_error(path.string() + ": out of memory while reading", file_error::out_of_memory));
  } catch (const std::exception& e) {
    return failed(make_error(path.string() + ": " + one_line(e.what())));
  }
}

Result<ClipFileInfo> inspect_clip(const fs::path& path, const ReadOptions& options) {
  return reading_or_failure(inspect_clip_outcome(path, options));
}

Result<Clip> read_clip(const fs::path& path, const ReadOptions& options) {
  Result<ClipFileInfo> info = inspect_clip(path, options);
  if (!info) return info.failure();
  return std::move(info->clip);
}

}  // namespace rotinterp
