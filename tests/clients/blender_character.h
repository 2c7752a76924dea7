// Shared by the character tests: Blender imports a source FBX or GLB character and
// what rotinterp wrote from it (tests/clients/blender_character.py), and the two are
// compared as a user sees them, with nothing fitted: the meshes, the takes, and the
// deformed meshes at the same three times of each take.
#pragma once

#include "io/io_test_util.h"
#include "rotinterp/core/rotation.h"

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace rotinterp::test {

struct BlenderMesh {
  std::string name;
  std::size_t vertices = 0, faces = 0, materials = 0;
  std::vector<std::string> groups;  // vertex-group names
  bool operator==(const BlenderMesh& o) const {
    return name == o.name && vertices == o.vertices && faces == o.faces && materials == o.materials && groups == o.groups;
  }
};

// The deformed meshes at one time: their vertices' bounding box and centroid (world, metres).
struct BlenderPose {
  double time = 0.0;  // s, FBX time
  Vec3 low, high, centroid;
};

struct BlenderCharacter {
  std::vector<BlenderMesh> meshes;
  std::set<std::string> takes;  // the take of each action (blender_character.py: its name without "OBJECT|")
  std::size_t actions = 0;  // every action Blender made (one per take and object it moves)
  std::size_t images = 0;   // images with pixels (embedded, or found beside the file)
  std::map<std::string, std::vector<BlenderPose>> poses;  // per take: first, middle, last
};

// Runs Blender once on (source, ours) pairs; `step`: the grid (s) the middle time
// lies on, a key time of both. Returns each file's import, in order.
std::vector<BlenderCharacter> blender_characters(const std::vector<std::pair<std::string, std::string>>& pairs,
                                                 double step, const std::filesystem::path& dir);

// The largest difference between the two's bounding boxes and centroids at the
// same times of the same take (metres), and the figure's height (the source's box
// at its first take's first time). `times`: the times compared, over every take of
// the source; a take of the source that ours lacks compares none.
struct PoseDeviation {
  double distance = 0.0, height = 0.0;
  std::size_t times = 0;
};
PoseDeviation pose_deviation(const BlenderCharacter& ours, const BlenderCharacter& source);

// assimp's command line reads `path` (its output beside it, `path`.assimp).
void expect_assimp_reads(const std::string& path);

struct CharacterCase {
  std::string source;   // under kData, or an absolute path
  std::string command;  // "resample … --fps 30" or "reduce …"; IN and -o OUT put after the verb
  std::string take;     // the one take the command writes, "" where it writes every take of the source
};

// Runs each case's command to DIR/N`extension`, which must print what it kept, warn
// of no lost mesh, and be read by assimp's command line; then Blender imports each
// source and output (blender_characters, `step`), and the two must show the same
// meshes and takes (and, within one format, as many actions where every take is
// written), and deformed meshes within 0.1 % of the figure's height at the
// three times of each take. Returns the imports (source, ours, per case; none where a
// command failed).
std::vector<BlenderCharacter> expect_same_character(const std::vector<CharacterCase>& cases, double step,
                                                   const std::filesystem::path& dir, const std::string& extension);

}  // namespace rotinterp::test
