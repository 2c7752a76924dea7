#include "blender_character.h"

#include "client_fixture.h"

#include <nlohmann/json.hpp>

#include <algorithm>

namespace rotinterp::test {

namespace {

Vec3 point(const nlohmann::json& p) { return {p[0].get<double>(), p[1].get<double>(), p[2].get<double>()}; }

}  // namespace

std::vector<BlenderCharacter> blender_characters(const std::vector<std::pair<std::string, std::string>>& pairs,
                                                 double step, const std::filesystem::path& dir) {
  std::vector<std::string> files;
  for (const auto& [source, ours] : pairs) files.push_back(source), files.push_back(ours);
  const nlohmann::json all = run_blender("blender_character.py", " " + std::to_string(step), files, dir, "character");
  std::vector<BlenderCharacter> out;
  for (const std::string& f : files) {
    const nlohmann::json& r = all.at(f);
    BlenderCharacter c;
    for (const auto& m : r.at("meshes"))
      c.meshes.push_back({m.at("name").get<std::string>(), m.at("vertices").get<std::size_t>(),
                          m.at("faces").get<std::size_t>(), m.at("materials").get<std::size_t>(),
                          m.at("groups").get<std::vector<std::string>>()});
    for (const auto& take : r.at("takes")) c.takes.insert(take.get<std::string>());
    for (const auto& [take, poses] : r.at("poses").items())
      for (const auto& p : poses)
        c.poses[take].push_back({p.at("time").get<double>(), point(p.at("min")), point(p.at("max")), point(p.at("centroid"))});
    out.push_back(std::move(c));
  }
  return out;
}

PoseDeviation pose_deviation(const BlenderCharacter& ours, const BlenderCharacter& source) {
  PoseDeviation d;
  if (!source.poses.empty() && !source.poses.begin()->second.empty()) {
    const BlenderPose& first = source.poses.begin()->second.front();
    d.height = first.high.z() - first.low.z();
  }
  for (const auto& [take, theirs] : source.poses) {
    const auto mine = ours.poses.find(take);
    if (mine == ours.poses.end()) continue;
    for (std::size_t i = 0; i < std::min(mine->second.size(), theirs.size()); ++i) {
      const BlenderPose &a = mine->second[i], &b = theirs[i];
      for (const auto& [p, q] : {std::pair{a.low, b.low}, {a.high, b.high}, {a.centroid, b.centroid}})
        d.distance = std::max(d.distance, (p - q).cwiseAbs().maxCoeff());
      ++d.times;
    }
  }
  return d;
}

}  // namespace rotinterp::test
