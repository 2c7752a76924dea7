// Reading clips from files: every format assimp imports (BVH, FBX, glTF/GLB,
// Collada, …), with BVH-specific care (channel layout and exact Frame Time from
// the file's header, validation assimp does not do).
//
// What the reader does (README "Formats" has the user's view):
//  * BVH: our own pass (io/bvh.h) validates the whole file first (before assimp
//    sees it: NaN/inf values, Frame Time ≤ 0 and short data fail fast) and gives the
//    layout, End Sites, exact Frame Time and every channel value in double precision,
//    including the position channels assimp drops (any layout but exactly 6
//    channels). Key k is at k·Frame Time. assimp is not needed for BVH; with
//    ReadOptions::cross_check_with_assimp it also imports the file and must agree
//    (joints, frames, rotations within float precision, else a warning).
//  * Other formats: joints are the animated nodes, the bones of meshes and all
//    their ancestors (the scene root only when its transform is not the identity);
//    assimp's `$AssimpFbx$` helper nodes are folded into their bone (static and
//    animated transforms composed, keys at the union of their times) so world poses
//    are exact. A uniform static scale on a node is baked into the translations of
//    its descendants; other scale is ignored with a warning. A leaf node carrying
//    unskinned meshes under an animated joint becomes an End Site of that joint at
//    its meshes' bounding-box centre (a prop or box hanging off its pivot).
//  * Every key is normalized and the track made sign-continuous.
//  * The clip's unit (Clip::unit) is settled here, once: declared by the file, given
//    (ReadOptions::unit) or inferred (clip/units.h).
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

namespace rotinterp {

// Ticks per second used when a file gives 0 (assimp's "not specified"): 25, the
// value assimp's own viewer assumes. A warning says so.
constexpr double kDefaultTicksPerSecond = 25.0;

// Receives one-line warnings ("<file>: <what>"): things the reader accepted but a
// user should know (extra BVH data rows, a default tick rate, ignored scale keys).
using WarningFn = std::function<void(const std::string& warning)>;

struct ReadOptions {
  // Which animation: its name, or its index as a decimal string; empty = the first.
  std::string animation;
  // Where warnings go; empty = dropped. The CLI prints them on stderr.
  WarningFn on_warning;
  // Metres per unit for a file that states no unit (BVH): the user's --unit. Empty =
  // inferred from the figure's size (clip/units.h infer_unit). A file that declares
  // its unit (FBX, glTF, Collada) keeps it, and a given unit is ignored with a warning.
  std::optional<double> unit;
  // FBX: true (default) keeps assimp's `$AssimpFbx$` pivot helper nodes and folds them
  // into their bones here, which is exact. false sets AI_CONFIG_IMPORT_FBX_PRESERVE_PIVOTS
  // off so assimp folds them itself; it then leaves animation channels that target the
  // removed helpers (assimp issues #1068, #4005, #6114) and their motion is lost.
  bool fold_fbx_helpers = true;
  // BVH: also import the file with assimp and compare its reading with ours (same
  // joints, one key per frame, rotations within float precision; a disagreement in
  // rotations, or assimp refusing the file, is a warning). Off by default: the clip
  // always comes from our own pass, which validates the whole file by itself, and
  // assimp's import costs more than the rest of a BVH read (README "Formats").
  bool cross_check_with_assimp = false;
  // FBX: also read the file's animation curves as stored — keys, tangents, takes,
  // layers — with our own FBX reader, in the importer process like the rest of the
  // read (ClipFileInfo::curves; `info --curves`). A malformed curve then refuses the
  // file (ErrorKind::unreadable). Off by default.
  bool read_curves = false;
  // Threads for a long BVH's conversion (core/work_queue.h thread_count: 0 = as many as
  // the machine has; it uses two at most). A caller reading files side by side gives 1.
  unsigned threads = 0;
  // Every assimp import (any file but a BVH read without the cross-check) runs in a
  // separate importer process (rotinterp-import, see find_importer()), which sends
  // its reading back; this process never calls assimp's importers. assimp 5.2.5
  // aborts or corrupts memory on some malformed files (a failed internal assertion,
  // a segfault on a curve without keys, a double free in ~aiScene): such a file is
  // one error (ErrorKind::crashed) instead of the end of a batch. Each reading
  // thread keeps one importer for file after file, replaced after a crash, a limit
  // below, or past 256 MiB resident; it ends with its thread (killed and reaped)
  // and with this process. It is killed when one file takes longer than this (the
  // file is refused, ErrorKind::timed_out)…
  double import_timeout_seconds = 600.0;
  // … or when its reply (the clip, 40 bytes a key) passes this many bytes
  // (ErrorKind::too_large).
  std::uint64_t max_import_bytes = std::uint64_t{4} << 30;
};

// Reads one animation of `path` into a validated Clip (tracks sign-continuous).
// Errors are one line and name the file; their kind (core/result.h) says whether
// the file was unreadable, held no animation, or made the importer crash, run too
// long or answer too much. Skeletons nested deeper than kMaxJointDepth (io/bvh.h)
// are refused in every format.
Result<Clip> read_clip(const std::filesystem::path& path, const ReadOptions& options = {});

// Whether read_clip() knows files with this extension ("fbx" or ".FBX"): BVH and
// every format assimp imports.
bool importable_extension(std::string extension);
// The formats read_clip reads, for messages: "bvh, fbx, glb, gltf, dae and 57 more
// formats assimp imports". A file with another extension (a .py, a .txt) is refused
// before any import: "<file>: not a motion file (formats read: …)".
std::string read_formats_text();

// The importer executable read_clip() starts for assimp imports, found in this
// order: the environment variable ROTINTERP_IMPORTER (a path); next to the running
// executable or to the library holding read_clip (same directory, or the
// installed libexec directory relative to bin/ or lib/); the path it was built at.
// An error when none is an executable file.
Result<std::filesystem::path> find_importer();

}  // namespace rotinterp
