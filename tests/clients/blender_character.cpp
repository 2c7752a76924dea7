#include "blender_character.h"

#include "client_fixture.h"
#include "support/run_cli.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

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
    c.actions = r.at("actions").get<std::size_t>();
    c.images = r.at("images").get<std::size_t>();
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

void expect_assimp_reads(const std::string& path) {
  const std::string log = path + ".assimp";
  EXPECT_EQ(std::system(("assimp info '" + path + "' >'" + log + "' 2>&1").c_str()), 0) << path << ": " << read_text(log);
}

std::vector<BlenderCharacter> expect_same_character(const std::vector<CharacterCase>& cases, double step,
                                                   const std::filesystem::path& dir, const std::string& extension) {
  std::vector<std::pair<std::string, std::string>> pairs;
  for (const CharacterCase& c : cases) {
    const std::string in = (kData / c.source).string();
    const std::string out = (dir / (std::to_string(pairs.size()) + extension)).string();
    const std::string verb = c.command.substr(0, c.command.find(' '));
    const auto r = run_cli(verb + " '" + in + "' -o '" + out + "'" + c.command.substr(verb.size()));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    if (r.exit_code != 0) return {};
    EXPECT_NE(r.out.find(" kept"), std::string::npos) << c.source << ": " << r.out;
    EXPECT_EQ(r.err.find("are not written"), std::string::npos) << c.source << ": " << r.err;
    EXPECT_EQ(r.err.find("not kept"), std::string::npos) << c.source << ": " << r.err;
    expect_assimp_reads(out);
    pairs.emplace_back(in, out);
  }
  const std::vector<BlenderCharacter> imports = blender_characters(pairs, step, dir);
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const BlenderCharacter &source = imports[2 * i], &ours = imports[2 * i + 1];
    const std::string what = cases[i].source + " (" + cases[i].command + ")";
    EXPECT_FALSE(source.meshes.empty()) << what;
    EXPECT_EQ(ours.meshes, source.meshes) << what;
    EXPECT_EQ(ours.images, source.images) << what;
    const std::set<std::string> takes = cases[i].take.empty() ? source.takes : std::set<std::string>{cases[i].take};
    EXPECT_EQ(ours.takes, takes) << what;
    // Within a format, every take written: one action per take and object, as the
    // source's (each take keys the objects the source's take of its name keys).
    if (cases[i].take.empty() && std::filesystem::path(pairs[i].first).extension() == extension) {
      EXPECT_EQ(ours.actions, source.actions) << what;
    }
    const PoseDeviation d = pose_deviation(ours, source);
    // Every take that moves bones (a glTF import makes an action per take and object;
    // those of objects other than the armature move none) is compared at three times.
    const auto posed = static_cast<std::size_t>(std::count_if(takes.begin(), takes.end(), [&](const std::string& t) { return source.poses.count(t) > 0; }));
    EXPECT_GE(posed, 1u) << what;
    EXPECT_EQ(d.times, 3 * posed) << what;
    EXPECT_LE(d.distance, 1e-3 * d.height) << what;
    std::printf("[ blender ] %s: %zu vertices, %zu take(s), worst %.4g mm of %.4g m at %zu times\n", what.c_str(),
                ours.meshes.empty() ? 0 : ours.meshes.front().vertices, ours.takes.size(), d.distance * 1000, d.height,
                d.times);
  }
  return imports;
}

}  // namespace rotinterp::test
