// The format registry (io/files, so that every io target and the CLI see it): every
// file format rotinterp writes or reads by name, with
// what it keeps, declared once here (as interp/interpolator.h declares the methods).
// The CLI's option texts and checks, info, folder runs, the writers' dispatch and the
// docs' table read it; no other place names a format.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace rotinterp {

// Which writer and reader serve a format (write.cpp's dispatch).
enum class FormatId { bvh, fbx, glb, gltf, dae };

struct FormatInfo {
  FormatId id;
  std::string_view name;   // the lower-case extension without its dot: "fbx"
  std::string_view title;  // for people: "FBX"
  bool reads = true;       // read_clip reads it (every one here; assimp reads more, read.h)
  bool writes = true;      // write_clip writes it
  // What a written file keeps:
  bool takes = false;      // several takes in one file (write_clips)
  bool curves = false;     // sparse keys with their interpolation (reduce -o, -m source)
  bool bvh_layout = false; // a BVH source's channel layout, read back as written
  // A character's meshes, skins and materials, from a source of its own kind (FBX from
  // FBX 7, glTF/GLB from glTF): the source with only its animation replaced (io/write.h).
  bool meshes = false;
  // Stores a value per frame at one rate (BVH): a clip with sparse keys must be
  // resampled on its frame grid before it is written.
  bool frames_only = false;
  // How a read file gets its unit: "inferred" (the figure's size; --unit), "declared"
  // (the file states it) or "metres" (the format's own; Collada's <unit> is applied
  // on reading).
  std::string_view unit;
};

// Every format, in the order messages list them.
const std::vector<FormatInfo>& formats();

// The format of a name or extension ("fbx", ".FBX"), or of a path's extension;
// nullptr for one the registry does not know.
const FormatInfo* format_named(std::string_view name_or_extension);
const FormatInfo* format_of(const std::filesystem::path& path);
const FormatInfo& format_info(FormatId id);
// Whether a name or extension ("fbx", ".FBX", a ClipFileInfo::format) is format `id`.
bool is_format(std::string_view name_or_extension, FormatId id);

// The names of the formats `keep` accepts, for messages: "bvh, fbx, glb, gltf or dae"
// (`last` between the last two; ", " with `last` = ", "); `dot` puts a '.' before each.
std::string format_names(bool (*keep)(const FormatInfo&), std::string_view last = " or ", bool dot = false);
inline bool writable(const FormatInfo& f) { return f.writes; }
inline bool holds_takes(const FormatInfo& f) { return f.takes; }
inline bool keeps_curves(const FormatInfo& f) { return f.curves; }

}  // namespace rotinterp
