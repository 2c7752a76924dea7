// The clip reader's dispatch: the file checked, then BVH by our own pass here and
// every other format (or a BVH to cross-check) by the importer process (import.h).
#include "rotinterp/io/read.h"

#include "assimp_text.h"
#include "import.h"
#include "read_parts.h"

#include <assimp/Importer.hpp>

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

// assimp's extension list ("*.3ds;*.bvh;…") with bvh, asked once: only the table, no import.
const std::set<std::string>& known_extensions() {
  static const std::set<std::string> known = [] {
    std::string list;
    Assimp::Importer().GetExtensionList(list);
    std::set<std::string> out{"bvh"};
    std::stringstream items(list);
    for (std::string item; std::getline(items, item, ';');)
      if (item.size() > 2 && item.compare(0, 2, "*.") == 0) out.insert(lower(item.substr(2)));
    return out;
  }();
  return known;
}
}  // namespace

bool importable_extension(std::string extension) {
  extension = lower(std::move(extension));
  if (!extension.empty() && extension[0] == '.') extension.erase(0, 1);
  if (extension.empty()) return false;
  return known_extensions().count(extension) > 0;
}

std::string read_formats_text() {
  // The motion formats first (the ones write_clip writes, io/write.h), then the count of the rest.
  const std::set<std::string>& known = known_extensions();
  std::string s;
  std::size_t named = 0;
  for (const char* f : {"bvh", "fbx", "glb", "gltf", "dae"})
    if (known.count(f)) s += (named++ ? ", " : "") + std::string(f);
  if (known.size() > named) s += " and " + std::to_string(known.size() - named) + " more formats assimp imports";
  return s;
}

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
