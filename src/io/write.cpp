// write_clip: BVH, FBX and glTF/GLB by our writers, Collada through assimp's exporter.
#include "rotinterp/io/write.h"

#include "rotinterp/io/atomic_file.h"
#include "rotinterp/io/bvh.h"
#include "export.h"
#include "fbx_write.h"
#include "gltf_write.h"

#include <cctype>

namespace rotinterp {

namespace {

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace

bool can_write_format(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  return ext == ".bvh" || ext == ".fbx" || ext == ".glb" || ext == ".gltf" || assimp_export_format(ext).has_value();
}

Status write_clip(const Clip& clip, const std::filesystem::path& path, const WriteOptions& options) {
  const std::string label = path.string();
  const std::string ext = lower_extension(path);
  if (clip.source_meshes > 0 && options.on_warning && can_write_format(path))
    options.on_warning(label + ": the source's " + std::to_string(clip.source_meshes) +
                       " mesh(es) and their skins are not written, only the skeleton and its motion");
  if (ext == ".bvh") {
    return write_file_atomically(path, [&](std::ostream& out) { return write_bvh(clip, out, options, label); });
  }
  if (ext == ".fbx") {
    Result<std::string> bytes = encode_fbx(clip, options.fbx_ascii ? FbxEncoding::ascii : FbxEncoding::binary);
    if (!bytes) return bytes.failure(label + ": ");
    return write_file_atomically(path, [&](std::ostream& out) -> Status {
      out.write(bytes->data(), static_cast<std::streamsize>(bytes->size()));
      return Ok{};
    });
  }
  if (ext == ".glb" || ext == ".gltf")
    return write_gltf(clip, path, ext == ".glb",
                      GltfKeys{options.gltf_own_key_times, options.gltf_cubic_rotations, options.gltf_cubic_translations});
  const std::optional<std::string> format = assimp_export_format(ext);
  if (!format)
    return make_error(label + ": cannot write '" + (ext.empty() ? std::string("(no extension)") : ext) +
                      "' files; use .bvh, .fbx, .gltf, .glb or .dae");
  return export_with_assimp(clip, path, *format);
}

}  // namespace rotinterp
