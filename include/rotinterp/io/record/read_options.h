// What a read may be told (io/read.h reads with it; the importer process gets it
// whole, io/process). Plain data, below every reader that takes it.
#pragma once

#include <cstdint>
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
  // file (file_error::unreadable). Off by default.
  bool read_curves = false;
  // Also read the character's body — meshes, skins, materials and their images —
  // with assimp (ClipFileInfo::body), for a writer that keeps it in another format
  // (io/write.h: an FBX character written as GLB). Off by default.
  bool read_body = false;
  // glTF: read buffer files that lie outside the file's folder (a uri with `..`, an
  // absolute path, or a link leading out). Off by default: a file from elsewhere
  // should not make rotinterp read /etc or a home folder (docs/limits.md).
  bool allow_external_files = false;
  // Threads for a long BVH's conversion (core/work_queue.h thread_count: 0 = as many as
  // the machine has; it uses two at most). A caller reading files side by side gives 1.
  unsigned threads = 0;
  // Every assimp import (any file but a BVH read without the cross-check) runs in a
  // separate importer process (rotinterp-import, see find_importer()), which sends
  // its reading back; this process never calls assimp's importers. assimp 5.2.5
  // aborts or corrupts memory on some malformed files (a failed internal assertion,
  // a segfault on a curve without keys, a double free in ~aiScene): such a file is
  // one error (process_error::crashed) instead of the end of a batch. Each reading
  // thread keeps one importer for file after file, replaced after a crash, a limit
  // below, or past 256 MiB resident; it ends with its thread (killed and reaped)
  // and with this process. It is killed when one file takes longer than this (the
  // file is refused, process_error::timed_out)…
  double import_timeout_seconds = 600.0;
  // … or when its reply (the clip, 40 bytes a key) passes this many bytes
  // (process_error::too_large).
  std::uint64_t max_import_bytes = std::uint64_t{4} << 30;
};

}  // namespace rotinterp
