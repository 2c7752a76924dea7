// Whole datasets: finding the clips of a folder run and splitting them into shards,
// where each one's output goes, and what a folder of clips holds (the rate audit of
// `rotinterp info --summary`). Used by eval, resample and info.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace rotinterp {

// Every file named in `paths`, and every regular file under a named directory
// (recursively, following no symlinked directories, skipping hidden entries) whose
// extension read_clip knows (importable_extension). Paths as strings in the form they were found
// ("data/bvh/a.bvh" under "data"), duplicates removed, sorted bytewise — the order
// of errors.csv. Error for a path that does not exist.
Result<std::vector<std::string>> discover_inputs(const std::vector<std::filesystem::path>& paths);

// True when `path` was found inside a directory rather than named itself: such a
// file is skipped quietly when read_clip says it holds no animation
// (file_error::no_animation: a mesh next to the clips).
bool found_in_directory(const std::string& path, const std::vector<std::filesystem::path>& named);

// Shard `index` of `count` (1 ≤ index ≤ count): files[i] for i ≡ index − 1 (mod count).
// Deterministic and balanced; the shards of one list partition it.
std::vector<std::string> shard_of(const std::vector<std::string>& files, int index, int count);

// Parses "I/N" (1 ≤ I ≤ N ≤ 1 000 000).
Result<std::pair<int, int>> parse_shard(const std::string& text);

struct MirroredOutput {
  std::string input;
  std::filesystem::path output;
};

// Where each input of a folder run goes: OUT_DIR/<its path relative to the named
// directory it was found in, or its file name when it was named itself>, with the
// extension of `format` ("bvh", "glb", …; empty: the input's own where
// can_write_format() takes it, else bvh). Inputs that lie inside `out_dir` are left
// out, so a second run does not take the first one's outputs as inputs. Error (one
// line naming both) when two inputs would share an output.
Result<std::vector<MirroredOutput>> mirror_outputs(const std::vector<std::string>& inputs,
                                                   const std::vector<std::filesystem::path>& named,
                                                   const std::filesystem::path& out_dir, const std::string& format);

// Groups of files with the same bytes (each group sorted, ≥ 2 paths, groups in the
// order of their first path). Files that cannot be read are left out.
std::vector<std::vector<std::string>> duplicate_files(const std::vector<std::string>& files);

// When the clip's Frame Time as written in its file, taken at face value, is not the
// rate rotinterp recognizes in it (".016667" is 59.9988 Hz, read as 60 Hz): one line
// saying so, for a face value more than 10 ppm off or across a whole number (where
// int(1 / frame_time) gives another rate). Empty otherwise, and for clips without a
// written Frame Time.
std::string rate_label_note(const Clip& clip);

}  // namespace rotinterp
