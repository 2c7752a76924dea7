// The extensions assimp imports, asked of its importer's table once (no import).
#include "rotinterp/io/import/import.h"
#include "rotinterp/io/files/formats.h"
#include "rotinterp/io/record/read_parts.h"

#include <assimp/Importer.hpp>

#include <sstream>

namespace rotinterp {

const std::set<std::string>& assimp_import_extensions() {
  static const std::set<std::string> known = [] {
    std::string list;  // "*.3ds;*.bvh;…"
    Assimp::Importer().GetExtensionList(list);
    std::set<std::string> out{std::string(format_info(FormatId::bvh).name)};  // our own pass
    std::stringstream items(list);
    for (std::string item; std::getline(items, item, ';');)
      if (item.size() > 2 && item.compare(0, 2, "*.") == 0) out.insert(lower(item.substr(2)));
    return out;
  }();
  return known;
}

bool importable_extension(std::string extension) {
  extension = lower(std::move(extension));
  if (!extension.empty() && extension[0] == '.') extension.erase(0, 1);
  if (extension.empty()) return false;
  return assimp_import_extensions().count(extension) > 0;
}

std::string read_formats_text() {
  // The motion formats first (the ones write_clip writes, io/write.h), then the count of the rest.
  const std::set<std::string>& known = assimp_import_extensions();
  std::string s;
  std::size_t named = 0;
  for (const FormatInfo& f : formats())
    if (known.count(std::string(f.name))) s += (named++ ? ", " : "") + std::string(f.name);
  if (known.size() > named) s += " and " + std::to_string(known.size() - named) + " more formats assimp imports";
  return s;
}

}  // namespace rotinterp
