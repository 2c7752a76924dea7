// `source`: a file's own motion, whatever its format, for resample -m source, eval
// --truth source and render's source panel, which ask no more than this header gives.
//
// What each format replays (joint j's local rotation at clip time t):
//  * FBX: the Lcl Rotation curves as the file stores them (io/fbx/fbx_source.h);
//  * glTF/GLB: the selected animation's rotation samplers as the glTF spec evaluates
//    them: STEP, LINEAR (shortest-path slerp), CUBICSPLINE (io/gltf/gltf_source.h);
//  * BVH: its frames, which are the clip's keys (every frame a key): between frames,
//    the shortest-arc slerp of the two neighbouring frames (track/sample.h), since a
//    BVH stores nothing between them.
// A joint the file gives no rotation of its own (no curves, no rotation channel in the
// animation, a name two glTF nodes share) is sampled from the clip's keys the same way.
// Other formats (Collada, …) store no motion we replay: a one-line refusal naming
// the file.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"
#include "rotinterp/io/fbx/fbx_source.h"
#include "rotinterp/io/files/source_method.h"
#include "rotinterp/io/record/clip_file.h"
#include "rotinterp/io/read.h"

#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace rotinterp {



// A clip read for `source`, with its motion.
struct FileSource {
  Clip clip;                 // as read_clip() reads the file
  SourceMotion motion;       // every joint (see above)
  std::vector<bool> own;     // per joint: motion replays the file's own data, not the clip's keys
  std::string replays;       // what `own` joints replay, for messages: "the file's curves", …
  // FBX only: the curves as stored, which resample writes back to an .fbx as they are.
  std::shared_ptr<const SourceClip> fbx;
  std::size_t own_joints() const;
};

// Reads `path` as read_clip() does (options.animation selects the animation) and its
// own motion. Errors (one line naming the file): as read_clip()'s; a format with no
// motion to replay; FBX without an animation stack or rotation curves; a glTF file
// whose samplers do not read, or without a rotation channel on any joint.
Result<FileSource> read_file_source(const std::filesystem::path& path, const ReadOptions& options);

// read_file_source's clip, its motion into `motion`: what render -m source draws.
Result<Clip> read_clip_with_source_motion(const std::filesystem::path& path, const ReadOptions& options,
                                          SourceMotion& motion);

// Sets every rotation key of each joint of `clip` (the source's joints, by index) that
// `source` replays, except those named in `keep`, to source.motion at the key's time,
// and makes those tracks sign-continuous. Returns how many joints were replayed.
std::size_t replay_source_rotations(Clip& clip, const FileSource& source, const std::vector<std::string>& keep);

// ---- FBX: the file's curves (io/fbx/fbx_source.h replays them) ----

// Reads `path` in the importer process, as read_clip() does, with its curves.
// Errors (one line naming the file): not an FBX file, a file without an animation
// stack, and every error read_clip() gives.
Result<SourceClip> read_source_clip(const std::filesystem::path& path, const ReadOptions& options);

// The same from a file already read with ReadOptions::read_curves (inspect_clip).
Result<SourceClip> source_clip_of(ClipFileInfo&& info, const std::string& label);

// The file's own motion (io/source_motion.h): joint j's local rotation at clip time t,
// evaluated from its curves where it has them (FileSource::own) and sampled from
// `source.clip`'s keys elsewhere (as eval --truth source reads it; render -m source
// draws it). Errors as fbx_joint_curves's.
Result<FileSource> fbx_file_source(std::shared_ptr<const SourceClip> source, const std::string& label);

// Its motion alone.
Result<SourceMotion> source_motion(std::shared_ptr<const SourceClip> source, const std::string& label);

}  // namespace rotinterp
