// Finding the clips of an evaluation and splitting them into shards.
#pragma once

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
// (ErrorKind::no_animation: a mesh next to the clips).
bool found_in_directory(const std::string& path, const std::vector<std::filesystem::path>& named);

// Shard `index` of `count` (1 ≤ index ≤ count): files[i] for i ≡ index − 1 (mod count).
// Deterministic and balanced; the shards of one list partition it.
std::vector<std::string> shard_of(const std::vector<std::string>& files, int index, int count);

// Parses "I/N" (1 ≤ I ≤ N ≤ 1 000 000).
Result<std::pair<int, int>> parse_shard(const std::string& text);

}  // namespace rotinterp
