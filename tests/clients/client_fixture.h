// Shared by the client tests: clips resampled once by the CLI, each written both in
// the format under test and as BVH (the reference: forward kinematics of the same
// resample), and the checks every written file must pass.
#pragma once

#include "io/io_test_util.h"
#include "rotinterp/clip/clip.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace rotinterp::test {

// One resample of a shared clip: `args` are the resample options after IN -o OUT.
struct ClientCase {
  std::string name;    // e.g. "bandai_walk"
  std::string source;  // path under ../shared/data
  std::string args;    // e.g. "--fps 60 --range 0:1"
};

// World positions of every joint at every frame of a BVH reference.
struct Reference {
  Clip clip;
  std::vector<std::vector<Vec3>> frames;  // [frame][joint]
  double height = 0.0;  // largest side of the rest pose's bounding box
};
// `without_translation`: joints whose translation keys the client is known to drop
// (their rest offset is used instead).
Reference load_reference(const std::filesystem::path& bvh, const std::vector<std::string>& without_translation = {});

// Largest distance, over every named joint and frame, between `positions` (one row
// per frame, in `names` order) mapped by the best similarity transform (Umeyama:
// rotation, uniform scale, translation) and the reference, and where it is;
// distance -1 when a name is not a reference joint or the frame counts differ.
struct Residual {
  double distance = -1.0;
  std::string joint;
  std::size_t frame = 0;
  double scale = 0.0;  // of the similarity: reference units per unit of `positions`
};
Residual max_similarity_residual(const Reference& ref, const std::vector<std::string>& names,
                                 const std::vector<std::vector<Vec3>>& positions);

}  // namespace rotinterp::test
