#include "rotinterp/io/files/formats.h"

#include <algorithm>
#include <cctype>

namespace rotinterp {

const std::vector<FormatInfo>& formats() {
  // id, name, title, reads, writes, takes, curves, bvh_layout, meshes, frames_only, unit
  static const std::vector<FormatInfo> all = {
      {FormatId::bvh, "bvh", "BVH", true, true, false, false, true, false, true, "inferred"},
      {FormatId::fbx, "fbx", "FBX", true, true, true, true, true, true, false, "declared"},
      {FormatId::glb, "glb", "GLB", true, true, true, true, false, true, false, "metres"},
      {FormatId::gltf, "gltf", "glTF", true, true, true, true, false, true, false, "metres"},
      {FormatId::dae, "dae", "Collada", true, true, false, false, false, false, false, "metres"},
  };
  return all;
}

const FormatInfo& format_info(FormatId id) {
  for (const FormatInfo& f : formats())
    if (f.id == id) return f;
  return formats().front();  // unreachable: every id has its entry
}

bool is_format(std::string_view name_or_extension, FormatId id) {
  const FormatInfo* f = format_named(name_or_extension);
  return f && f->id == id;
}

const FormatInfo* format_named(std::string_view name) {
  if (!name.empty() && name.front() == '.') name.remove_prefix(1);
  for (const FormatInfo& f : formats())
    if (f.name.size() == name.size() &&
        std::equal(name.begin(), name.end(), f.name.begin(),
                   [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == b; }))
      return &f;
  return nullptr;
}

const FormatInfo* format_of(const std::filesystem::path& path) {
  const std::string ext = path.extension().string();
  return ext.empty() ? nullptr : format_named(ext);
}

std::string format_names(bool (*keep)(const FormatInfo&), std::string_view last, bool dot) {
  std::vector<std::string> names;
  for (const FormatInfo& f : formats())
    if (keep(f)) names.push_back((dot ? "." : "") + std::string(f.name));
  std::string s;
  for (std::size_t i = 0; i < names.size(); ++i)
    s += (i == 0 ? "" : i + 1 == names.size() ? std::string(last) : std::string(", ")) + names[i];
  return s;
}

}  // namespace rotinterp
