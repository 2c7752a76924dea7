// write_clip: BVH, FBX and glTF/GLB by our writers, Collada through assimp's exporter;
// write_clips: several takes of one skeleton into one FBX or glTF/GLB.
#include "rotinterp/io/write.h"

#include "rotinterp/io/files/atomic_file.h"
#include "rotinterp/io/files/file_errors.h"
#include "rotinterp/io/files/formats.h"
#include "rotinterp/io/bvh/bvh.h"
#include "rotinterp/io/import/import.h"
#include "rotinterp/io/info.h"
#include "rotinterp/io/fbx/fbx_character.h"
#include "rotinterp/io/fbx/fbx_write.h"
#include "rotinterp/io/gltf/gltf_character.h"
#include "rotinterp/io/gltf/gltf_write.h"
#include "rotinterp/io/files/key_times.h"
#include "rotinterp/io/files/written_names.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <set>

namespace rotinterp {

namespace {

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// Skeletons compare within this: offsets relative to max(1, |offset|) in clip units,
// rest rotations as sin(half the angle between them), units relative.
constexpr double kSameSkeletonTolerance = 1e-9;

bool near(double a, double b) { return std::abs(a - b) <= kSameSkeletonTolerance * std::max(1.0, std::abs(a)); }

// Why `b`'s skeleton is not `a`'s, or "" when it is the same.
std::string skeleton_difference(const Clip& a, const Clip& b) {
  const auto& ja = a.skeleton.joints;
  const auto& jb = b.skeleton.joints;
  if (ja.size() != jb.size()) return std::to_string(jb.size()) + " joints, the first take has " + std::to_string(ja.size());
  for (std::size_t j = 0; j < ja.size(); ++j) {
    const std::string which = "joint " + std::to_string(j) + " ('" + jb[j].name + "')";
    if (ja[j].name != jb[j].name) return which + " is '" + ja[j].name + "' in the first take";
    if (ja[j].parent != jb[j].parent) return which + " has another parent than in the first take";
    for (int c = 0; c < 3; ++c)
      if (!near(ja[j].offset[c], jb[j].offset[c])) return which + " has another offset than in the first take";
    if ((ja[j].rest_rotation.conjugate() * jb[j].rest_rotation).vec().norm() > kSameSkeletonTolerance)
      return which + " has another rest rotation than in the first take";
  }
  if (!near(a.unit.metres_per_unit, b.unit.metres_per_unit)) return "another unit than the first take";
  return "";
}

// The take keyed from t = 0: every track's times moved back by its first key time.
Clip from_time_zero(const Clip& take) {
  const std::vector<double> times = all_key_times(take);
  if (times.empty() || times.front() == 0.0) return take;
  Clip out = take;
  const double t0 = times.front();
  for (RotationTrack& r : out.rotations)
    for (double& t : r.times) t -= t0;
  for (auto& tr : out.translations)
    if (tr)
      for (double& t : tr->times) t -= t0;
  return out;
}

// "Take N" for an empty name, " 2", " 3", … after a name already taken; each name
// readable (written_names.h) before it is compared.
std::vector<std::string> unique_take_names(const std::vector<Clip>& takes) {
  std::vector<std::string> names;
  std::set<std::string> used;
  for (std::size_t i = 0; i < takes.size(); ++i) {
    const std::string base = takes[i].name.empty() ? "Take " + std::to_string(i + 1) : readable_text(takes[i].name);
    std::string name = base;
    for (int k = 2; used.count(name); ++k) name = base + " " + std::to_string(k);
    used.insert(name);
    names.push_back(name);
  }
  return names;
}

bool is_gltf(const FormatInfo* format) { return format && (format->id == FormatId::glb || format->id == FormatId::gltf); }

std::vector<const Clip*> pointers_to(const std::vector<Clip>& takes) {
  std::vector<const Clip*> out;
  for (const Clip& c : takes) out.push_back(&c);
  return out;
}

GltfKeys gltf_keys(const WriteOptions& options) {
  return {options.gltf_own_key_times, options.gltf_cubic_rotations, options.gltf_cubic_translations};
}

// The character of the source kept: an FBX from an FBX 7 file (io/fbx/fbx_character.h),
// a .glb/.gltf from a glTF file (io/gltf/gltf_character.h), on_kept told what passed
// through; nullopt where the source is no such file or the character cannot be kept
// (a warning says why), and the caller writes the skeleton alone.
std::optional<Status> write_character(const std::vector<Clip>& takes, const std::filesystem::path& path,
                                      const WriteOptions& options) {
  const FormatInfo* source = options.source.empty() ? nullptr : format_of(options.source);
  const FormatInfo* output = format_of(path);
  if (takes.front().source_meshes == 0 || !source || !output) return std::nullopt;
  auto not_kept = [&](const std::string& why) -> std::optional<Status> {
    if (options.on_warning) options.on_warning(path.string() + ": the character is not kept: " + why);
    return std::nullopt;
  };
  auto kept = [&](const std::string& what) {
    if (options.on_kept) options.on_kept(path.string() + ": " + what);
  };
  if (output->id == FormatId::fbx && keeps_fbx_character(takes.front(), options.source)) {
    auto file = fbx_character_file(takes, options.source, options.fbx_ascii);
    if (!file) return not_kept(file.error());
    kept(file->kept.text());
    return write_file_atomically(path, [&](std::ostream& out) -> Status {
      out.write(file->bytes.data(), static_cast<std::streamsize>(file->bytes.size()));
      return Ok{};
    });
  }
  if (is_gltf(source) && is_gltf(output)) {
    auto written = write_gltf_character(pointers_to(takes), options.source, path, output->id == FormatId::glb, gltf_keys(options));
    if (!written && written.error_kind() != file_error::cannot_write) return not_kept(written.error());
    if (!written) return Status(written.failure());
    kept(written->text());
    return Status(Ok{});
  }
  if (is_gltf(output) && output->meshes) {  // any other character (FBX, Collada) as glTF: its body read by assimp
    for (std::size_t i = 1; i < takes.size(); ++i)  // one skeleton, which the body's skins name
      if (const std::string why = skeleton_difference(takes.front(), takes[i]); !why.empty())
        return Status(make_error(path.string() + ": take '" + takes[i].name + "' has another skeleton than take '" +
                                 takes.front().name + "': " + why));
    ReadOptions read;
    read.read_body = true;
    const Result<ClipFileInfo> source_file = inspect_clip(options.source, read);
    if (!source_file || !source_file->body) return not_kept(source_file ? "an FBX 6.1 file, whose motion rotinterp's own reader reads, but not its meshes"
                                                            : source_file.error());
    auto written = write_gltf(pointers_to(takes), path, output->id == FormatId::glb, gltf_keys(options), *source_file->body);
    if (!written && written.error_kind() != file_error::cannot_write) return not_kept(written.error());
    if (!written) return Status(written.failure());
    for (const std::string& note : written->notes)
      if (options.on_warning) options.on_warning(path.string() + ": " + note);
    kept(written->kept);
    return Status(Ok{});
  }
  return std::nullopt;
}

void warn_meshes_lost(const Clip& clip, const std::string& label, const WriteOptions& options) {
  if (clip.source_meshes > 0 && options.on_warning) options.on_warning(meshes_not_written(clip, label));
}

}  // namespace

bool keeps_fbx_character(const Clip& clip, const std::string& source) {
  const FormatInfo* format = source.empty() ? nullptr : format_of(source);
  return clip.source_meshes > 0 && format && format->id == FormatId::fbx;
}

std::string meshes_not_written(const Clip& clip, const std::string& label) {
  if (clip.source_meshes == 0) return "";
  return label + ": the source's " + std::to_string(clip.source_meshes) +
         " mesh(es) and their skins are not written, only the skeleton and its motion";
}

bool can_write_format(const std::filesystem::path& path) {
  const FormatInfo* format = format_of(path);
  return format && format->writes;
}

Status write_clip(const Clip& clip, const std::filesystem::path& path, const WriteOptions& options) {
  const std::string label = path.string();
  const std::string ext = lower_extension(path);
  const FormatInfo* known = format_of(path);
  const FormatId id = known && known->writes ? known->id : FormatId::dae;  // dae: assimp's exporters below
  if (format_info(id).meshes)
    if (std::optional<Status> written = write_character({clip}, path, options)) return *written;
  if (can_write_format(path)) warn_meshes_lost(clip, label, options);
  if (id == FormatId::bvh) {
    return write_file_atomically(path, [&](std::ostream& out) { return write_bvh(clip, out, options, label); });
  }
  if (id == FormatId::fbx) {
    Result<std::string> bytes = encode_fbx(clip, options.fbx_ascii ? FbxEncoding::ascii : FbxEncoding::binary);
    if (!bytes) return bytes.failure(label + ": ");
    return write_file_atomically(path, [&](std::ostream& out) -> Status {
      out.write(bytes->data(), static_cast<std::streamsize>(bytes->size()));
      return Ok{};
    });
  }
  if (id == FormatId::glb || id == FormatId::gltf)
    return write_gltf(clip, path, id == FormatId::glb, gltf_keys(options));
  const std::optional<std::string> format = assimp_export_format(ext);
  if (!format)
    return make_error(label + ": cannot write '" + (ext.empty() ? std::string("(no extension)") : ext) +
                      "' files; use " + format_names(writable, " or ", true));
  return export_with_assimp(clip, path, *format);
}

bool can_write_takes(const std::filesystem::path& path) {
  const FormatInfo* format = format_of(path);
  return format && format->writes && format->takes;
}

Status write_clips(const std::vector<Clip>& takes, const std::filesystem::path& path, const WriteOptions& options) {
  const std::string label = path.string();
  const std::string ext = lower_extension(path);
  const FormatInfo* known = format_of(path);
  const bool fbx = known && known->id == FormatId::fbx;
  if (!can_write_takes(path)) {
    if (!can_write_format(path))
      return make_error(label + ": cannot write '" + (ext.empty() ? std::string("(no extension)") : ext) +
                        "' files with several takes; use " + format_names(holds_takes, " or ", true));
    return make_error(label + ": a " + ext + " file holds one take; put {anim} in the output name to write one file per take");
  }
  if (takes.empty()) return make_error(label + ": no takes to write");
  const std::vector<std::string> names = unique_take_names(takes);
  // A character keeps the source's own time axis, not from t = 0. A glTF one needs
  // no common skeleton: each take's joints are the source's nodes of their names.
  auto character = [&]() -> std::optional<Status> {
    if (takes.front().source_meshes == 0 || options.source.empty()) return std::nullopt;
    std::vector<Clip> renamed = takes;
    for (std::size_t i = 0; i < takes.size(); ++i) renamed[i].name = names[i];
    return write_character(renamed, path, options);
  };
  if (!fbx)
    if (std::optional<Status> written = character()) return *written;
  std::vector<Clip> named;
  named.reserve(takes.size());
  for (std::size_t i = 0; i < takes.size(); ++i) {
    if (i > 0)
      if (const std::string why = skeleton_difference(takes.front(), takes[i]); !why.empty())
        return make_error(label + ": take '" + names[i] + "' has another skeleton than take '" + names[0] + "': " + why);
    named.push_back(from_time_zero(takes[i]));
    named.back().name = names[i];
  }
  if (fbx)
    if (std::optional<Status> written = character()) return *written;
  const auto with_meshes = std::find_if(takes.begin(), takes.end(), [](const Clip& c) { return c.source_meshes > 0; });
  if (with_meshes != takes.end()) warn_meshes_lost(*with_meshes, label, options);
  if (!fbx) {  // glTF or GLB
    return write_gltf(pointers_to(named), path, known->id == FormatId::glb, gltf_keys(options));
  }
  Result<std::string> bytes = encode_fbx_clips(named, options.fbx_ascii ? FbxEncoding::ascii : FbxEncoding::binary);
  if (!bytes) return bytes.failure(label + ": ");
  return write_file_atomically(path, [&](std::ostream& out) -> Status {
    out.write(bytes->data(), static_cast<std::streamsize>(bytes->size()));
    return Ok{};
  });
}

}  // namespace rotinterp
