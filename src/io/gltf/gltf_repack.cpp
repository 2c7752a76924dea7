// The source's buffers packed into one without its animations (gltf_repack.h).
#include "gltf_repack.h"

#include "rotinterp/io/files/input_file.h"

#include <algorithm>
#include <cctype>
#include <functional>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

namespace rotinterp::gltf {

namespace {

// Every accessor reference outside animations: (object holding it, key).
void for_each_accessor_use(json& doc, const std::function<void(json&, const std::string&)>& use) {
  auto each_value = [&](json& map) {
    if (map.is_object())
      for (auto& [key, value] : map.items()) use(map, key);
  };
  if (doc.contains("meshes"))
    for (json& mesh : doc["meshes"])
      if (mesh.contains("primitives"))
        for (json& primitive : mesh["primitives"]) {
          if (primitive.contains("attributes")) each_value(primitive["attributes"]);
          if (primitive.contains("indices")) use(primitive, "indices");
          if (primitive.contains("targets"))
            for (json& target : primitive["targets"]) each_value(target);
        }
  if (doc.contains("skins"))
    for (json& skin : doc["skins"])
      if (skin.contains("inverseBindMatrices")) use(skin, "inverseBindMatrices");
  if (doc.contains("nodes"))
    for (json& node : doc["nodes"])
      if (node.contains("extensions") && node["extensions"].contains("EXT_mesh_gpu_instancing"))
        each_value(node["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]);
}

// Every buffer-view reference but the accessors': images, Draco-compressed primitives.
void for_each_other_view_use(json& doc, const std::function<void(json&, const std::string&)>& use) {
  if (doc.contains("images"))
    for (json& image : doc["images"])
      if (image.contains("bufferView")) use(image, "bufferView");
  if (doc.contains("meshes"))
    for (json& mesh : doc["meshes"])
      if (mesh.contains("primitives"))
        for (json& primitive : mesh["primitives"])
          if (primitive.contains("extensions") && primitive["extensions"].contains("KHR_draco_mesh_compression"))
            use(primitive["extensions"]["KHR_draco_mesh_compression"], "bufferView");
}

// An accessor's views: its own and its sparse indices' and values'.
void for_each_view_of(json& accessor, const std::function<void(json&, const std::string&)>& use) {
  if (accessor.contains("bufferView")) use(accessor, "bufferView");
  if (accessor.contains("sparse")) {
    use(accessor["sparse"]["indices"], "bufferView");
    use(accessor["sparse"]["values"], "bufferView");
  }
}

std::string mime_type_of(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".png") return "image/png";
  if (ext == ".jpg" || ext == ".jpeg") return "image/jpeg";
  if (ext == ".webp") return "image/webp";
  if (ext == ".ktx2") return "image/ktx2";
  return "";
}

// Appends `bytes` at an offset congruent to `modulo_4` (mod 4); returns the offset.
std::size_t append_aligned(std::string& bin, std::string_view bytes, std::size_t modulo_4) {
  while (bin.size() % 4 != modulo_4 % 4) bin.push_back('\0');
  const std::size_t at = bin.size();
  bin.append(bytes);
  return at;
}

}  // namespace

Builder repack_without_animations(json& doc, Buffers& buffers, const std::filesystem::path& folder,
                                  std::size_t& embedded_images) {
  const std::size_t accessor_count = doc.contains("accessors") ? doc["accessors"].size() : 0;
  const std::size_t view_count = doc.contains("bufferViews") ? doc["bufferViews"].size() : 0;
  auto index_of = [](const json& holder, const std::string& key, std::size_t count, const char* what) {
    const std::uint64_t i = whole(holder, key.c_str());
    if (i >= count) throw std::runtime_error(std::string(what) + " " + std::to_string(i) + " does not exist");
    return static_cast<std::size_t>(i);
  };
  // The accessors the animations alone use go, then the views only they used.
  std::set<std::size_t> animation_accessors, used_accessors;
  if (doc.contains("animations"))
    for (const json& animation : doc["animations"])
      if (animation.contains("samplers"))
        for (const json& sampler : animation["samplers"])
          for (const char* key : {"input", "output"})
            animation_accessors.insert(index_of(sampler, key, accessor_count, "accessor"));
  for_each_accessor_use(doc, [&](json& holder, const std::string& key) {
    used_accessors.insert(index_of(holder, key, accessor_count, "accessor"));
  });
  std::vector<long> new_accessor(accessor_count, -1);
  json accessors = json::array();
  std::vector<bool> view_used(view_count, false), view_dropped(view_count, false);
  for (std::size_t a = 0; a < accessor_count; ++a) {
    json& accessor = doc["accessors"][a];
    const bool dropped = animation_accessors.count(a) && !used_accessors.count(a);
    for_each_view_of(accessor, [&](json& holder, const std::string& key) {
      const std::size_t v = index_of(holder, key, view_count, "buffer view");
      (dropped ? view_dropped : view_used)[v] = true;
    });
    if (dropped) continue;
    new_accessor[a] = static_cast<long>(accessors.size());
    accessors.push_back(accessor);
  }
  for_each_other_view_use(doc, [&](json& holder, const std::string& key) {
    view_used[index_of(holder, key, view_count, "buffer view")] = true;
  });
  // Kept: every view some kept thing uses, and any view nothing we know uses.
  Builder out;
  std::vector<long> new_view(view_count, -1);
  for (std::size_t v = 0; v < view_count; ++v) {
    if (view_dropped[v] && !view_used[v]) continue;
    json view = doc["bufferViews"][v];
    if (view.contains("extensions"))
      throw std::runtime_error("buffer view " + std::to_string(v) + " has extensions, which point into the buffers");
    const std::string_view buffer = buffers.bytes(whole(view, "buffer"));
    const std::uint64_t offset = whole(view, "byteOffset", 0), length = whole(view, "byteLength");
    if (offset > buffer.size() || length > buffer.size() - offset)
      throw std::runtime_error("buffer view " + std::to_string(v) + " passes its buffer's end");
    view["buffer"] = 0;
    view["byteOffset"] = append_aligned(out.bin, buffer.substr(offset, length), offset);
    new_view[v] = static_cast<long>(out.views.size());
    out.views.push_back(std::move(view));
  }
  // Every reference renumbered.
  auto renumber = [](const std::vector<long>& map) {
    return [&map](json& holder, const std::string& key) { holder[key] = map[whole(holder, key.c_str())]; };
  };
  for (json& accessor : accessors) for_each_view_of(accessor, renumber(new_view));
  for_each_accessor_use(doc, renumber(new_accessor));
  for_each_other_view_use(doc, renumber(new_view));
  // Images in files beside the source go into the buffer.
  if (doc.contains("images"))
    for (json& image : doc["images"]) {
      if (!image.contains("uri") || !image["uri"].is_string()) continue;
      const std::string uri = image["uri"].get<std::string>();
      if (uri.rfind("data:", 0) == 0) continue;
      const std::string what = "image uri '" + uri + "'";
      if (uri.find(':') != std::string::npos) throw std::runtime_error(what + " is not a file beside the source");
      auto file = referenced_file(folder, percent_decoded(uri), false, what);
      if (!file) throw std::runtime_error(file.error());
      auto bytes = read_input_file(*file, what);
      if (!bytes) throw std::runtime_error(bytes.error());
      std::string mime = image.value("mimeType", mime_type_of(*file));
      if (mime.empty()) throw std::runtime_error(what + ": no mimeType and no known image extension");
      const std::size_t at = append_aligned(out.bin, *bytes, 0);
      out.views.push_back({{"buffer", 0}, {"byteOffset", at}, {"byteLength", bytes->size()}});
      image.erase("uri");
      image["mimeType"] = mime;
      image["bufferView"] = out.views.size() - 1;
      ++embedded_images;
    }
  append_aligned(out.bin, {}, 0);  // the animations' floats start 4-aligned
  out.accessors = std::move(accessors);
  doc.erase("animations");
  return out;
}

}  // namespace rotinterp::gltf
