// Writing clips: BVH, FBX and glTF/GLB by writers of our own, Collada through
// assimp's exporter; several takes into one FBX or glTF/GLB (write_clips). The format follows the extension of the path. Every write is
// atomic (see io/files/atomic_file.h).
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"
#include "rotinterp/io/files/write_options.h"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace rotinterp {


// Writes `clip` to `path`; the format follows the extension (bvh, fbx, glb, gltf,
// dae). The clip must be sampled on a uniform grid of frame_time for BVH output.
// Atomic (io/files/atomic_file.h), missing folders created; an error about the output has
// file_error::cannot_write and names the file or folder.
Status write_clip(const Clip& clip, const std::filesystem::path& path, const WriteOptions& options = {});

// Writes several takes of one skeleton into one file: FBX (one AnimationStack and
// AnimationLayer per take, named by its Clip::name) or glTF/GLB (one animation per
// take, named). Every take is keyed from its own t = 0 (a take whose first key lies
// later is moved back by it): in FBX every stack's LocalStart/ReferenceStart is 0 and
// its LocalStop/ReferenceStop its own duration, all on one timeline from 0. TimeMode
// states the takes' rate where they share one, else none (each take's keys keep
// their own grid, which readers infer). The file's first take is the active one.
// Names: an empty name becomes "Take N" (N its place, from 1); a name already used
// gets " 2", " 3", … Every take must have the first's skeleton (joint names,
// parents, offsets and rest rotations within 1e-9, and its unit), else a one-line
// error naming the take that differs; a glTF character (WriteOptions::source) needs
// none, each take driving the source's nodes of its joints' names. Single-take formats (BVH, CSV, Collada) are
// refused ("FILE: a .bvh file holds one take; put {anim} in the output name to write
// one file per take"). Atomic like write_clip: the previous file stays whole on error.
// write_clip of one clip writes the same bytes as before (take name "clip" if empty).
Status write_clips(const std::vector<Clip>& takes, const std::filesystem::path& path, const WriteOptions& options = {});

// Whether an FBX written from `clip`, read from the file `source`, is that file's
// character with only its animation replaced (io/fbx/fbx_character.h): an FBX source
// with meshes.
bool keeps_fbx_character(const Clip& clip, const std::string& source);

// The warning that `clip`'s source meshes (and skins) are not written to `label`, one
// line; "" where the source had none.
std::string meshes_not_written(const Clip& clip, const std::string& label);

// Whether write_clip writes the format named by `path`'s extension (any case), so
// that callers can reject an output name before doing the work.
bool can_write_format(const std::filesystem::path& path);
// Whether write_clips writes several takes into that format (FBX, glTF/GLB).
bool can_write_takes(const std::filesystem::path& path);

}  // namespace rotinterp
