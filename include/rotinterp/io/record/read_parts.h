// The steps of a read that the dispatch (read.cpp) and the importer's in-process
// read (read_in_process.cpp) share: checking the file, telling BVH apart, our own
// BVH pass, and the final check of the clip (io/record, below both). No assimp here.
#pragma once

#include "rotinterp/core/result.h"
#include "rotinterp/io/bvh/bvh.h"
#include "rotinterp/io/files/input_file.h"
#include "rotinterp/io/record/clip_file.h"
#include "rotinterp/io/record/read_options.h"

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace rotinterp {

// Where a read's warnings go: a list (the ClipFileInfo's, or the importer's
// outcome), a WarningFn, or both.
struct Warnings {
  const WarningFn* fn = nullptr;
  std::vector<std::string>* list = nullptr;
  void operator()(const std::string& w) const {
    if (list) list->push_back(w);
    if (fn && *fn) (*fn)(w);
  }
};

std::string lower(std::string s);

// "fbx" for "x/y.FBX": lower case, no dot.
std::string extension_of(const std::filesystem::path& path);

// BVH content: by extension, or a HIERARCHY first under another one.
bool is_bvh(const std::filesystem::path& path, const std::string& ext);

// Our BVH pass, first half: the file parsed (info.format set, extra data rows a
// warning).
Result<BvhFile> read_bvh_file(const std::filesystem::path& path, ClipFileInfo& info, const Warnings& warn);

// Our BVH pass, second half: the file's one animation (named `animation_name`,
// which only assimp's reading gives) summarized in `info`, options.animation
// checked against it, and the clip.
Status bvh_file_to_clip(const BvhFile& bvh, const std::string& animation_name, const std::filesystem::path& path,
                        const ReadOptions& options, ClipFileInfo& info);

// What every read checks last: a valid clip whose joints nest no deeper than BVH
// allows (scene_to_clip takes any depth assimp gives; callers may walk the tree).
// Sets the clip's source_format from info.format, and settles its unit (Clip::unit:
// declared by the file, else ReadOptions::unit, else inferred; clip/units.h).
Status check_clip(ClipFileInfo& info, const std::string& label, const ReadOptions& options);

}  // namespace rotinterp
