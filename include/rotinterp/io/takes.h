// Several takes of one file: which ones an --anim value names (resample, reduce and
// eval read several; info and render one), and a take's name as part of a file name.
#pragma once

#include "rotinterp/core/result.h"
#include "rotinterp/io/info.h"
#include "rotinterp/io/read.h"

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace rotinterp {

// What `--anim all` is.
inline constexpr const char* kAllTakes = "all";
// Where an output name gets each take's name (take_file_part).
inline constexpr const char* kTakePlaceholder = "{anim}";

// Whether `anim` names several takes: "all", or a comma list ("walk,run", "0,2").
bool names_several_takes(const std::string& anim);

struct TakeRef {
  std::size_t index = 0;  // 0-based, in the file
  std::string name;       // as the file names it (may be empty)
};

// The takes `anim` names in `path`, in the order given ("": the first; "all": the file's order; a
// name that holds a comma is matched whole first). Each item is a take's name or its
// 0-based index; a take named twice is taken once. Errors: one line naming the file
// and the item that names no take (with the takes it has), and every read error.
Result<std::vector<TakeRef>> select_takes(const std::filesystem::path& path, const std::string& anim,
                                          const ReadOptions& options);
// The same over the takes a read listed (ClipFileInfo::animations); `label` names the file.
Result<std::vector<TakeRef>> choose_takes(const std::vector<AnimationSummary>& takes, const std::string& anim,
                                          const std::string& label);

// `take`'s name as a file-name part: ASCII letters, digits, '.', '-' and '_' kept,
// every other byte '_' ("anim 2" → "anim_2"); "take<index>" where that leaves nothing
// but '_' and '.'.
std::string take_file_part(const TakeRef& take);

// `pattern` with every kTakePlaceholder replaced by take_file_part(take).
std::string with_take_name(const std::string& pattern, const TakeRef& take);

}  // namespace rotinterp
