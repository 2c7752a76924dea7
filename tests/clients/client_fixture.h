// Shared by the client tests: one Blender process imports a list of files
// (tests/clients/blender_dump.py), and what it shows is compared with what it shows
// for the source, at true size and with nothing fitted: Blender turns every format
// Z-up in metres itself, so two imports of the same motion must coincide.
#pragma once

#include "io/io_test_util.h"
#include "rotinterp/core/rotation.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace rotinterp::test {

// One file as Blender shows it (blender_dump.py documents the fields).
struct BlenderImport {
  int armatures = 0;
  double fps = 0.0;                      // the scene's rate after the import
  std::vector<std::string> bones;        // of the one armature
  std::vector<std::string> connected;    // bones Blender connected to their parent
  std::vector<double> times;             // s, the clip time of each key Blender shows
  std::vector<std::vector<Vec3>> heads;  // [key][bone], world, metres
  std::vector<std::string> objects;      // armature and empty objects (FBX Nulls)
  std::vector<std::vector<Vec3>> origins;  // [key][object], their FBX node origins, metres
  std::vector<std::string> actions;        // every action's name, as Blender made them
  // Where there are several actions (takes): each one played on the armature, its keys.
  struct ActionKeys {
    std::vector<double> times;               // s
    std::vector<std::vector<Vec3>> heads;    // [key][bone], world, metres
    std::vector<std::vector<Vec3>> origins;  // [key][object], as `origins`
  };
  std::map<std::string, ActionKeys> action_keys;
};

// `b` playing one of its actions: that action's keys as the import's own (none where
// it has no such action).
BlenderImport playing(const BlenderImport& b, const std::string& action);

// Runs Blender once with tests/clients/`script` on `args` then `files` (quoted),
// writing DIR/STEM.json (the script's first argument) and DIR/STEM.log; returns the JSON.
nlohmann::json run_blender(const std::string& script, const std::string& args, const std::vector<std::string>& files,
                           const std::filesystem::path& dir, const std::string& stem);

// Runs tests/clients/blender_nla_rig.py: a Blender-made armature with two takes
// (Walk, Wave), `skinned` deforming a mesh of its own; returns the stem of the
// DIR/rig.fbx and DIR/rig.glb it exported. Throws where Blender fails.
std::string make_blender_rig(const std::filesystem::path& dir, bool skinned);

// Runs Blender once on `files` (a BVH may end in "@SCALE", its global_scale;
// default 0.01) and returns each import by its entry in `files`.
std::vector<BlenderImport> blender_imports(const std::vector<std::string>& files, const std::filesystem::path& dir);

// Blender's up axis is Z: the figure's height is the vertical extent of its bone
// heads at the first key (metres).
double figure_height(const BlenderImport& source);

// Keys of `ours` and `source` lie at the same clip times when within this (s).
constexpr double kSameKeyTime = 1e-4;

// Where two imports are compared: at every key of ours (sparse keys: reduce), or at
// every key of the source within ours' span (a resample at the file's rate, whose
// frames between a sparse source's keys have no pose in the source to compare).
enum class CompareAt { every_key_of_ours, every_key_of_the_source };

// The largest distance between a joint of `ours` and the same node of `source` at
// the same key time, over the keys `at` says, with nothing fitted. Joints are
// matched by name: a bone of `source`, else an object (Blender makes FBX Nulls the
// armature object or empties). `problem` is non-empty when a joint, a bone of
// `source` or a key time to compare has no counterpart. `cut`: the key of `ours` at
// t is the source's at cut + t (s; resample --range starts its output at 0).
struct Deviation {
  double distance = 0.0;  // metres
  std::string joint;
  double time = 0.0;  // s, the source's
  std::string problem;
  std::size_t keys = 0;  // key times compared
};
Deviation worst_deviation(const BlenderImport& ours, const BlenderImport& source, double cut = 0.0,
                          CompareAt at = CompareAt::every_key_of_ours);

}  // namespace rotinterp::test
