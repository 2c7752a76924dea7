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
    c.actions = r.at("actions").size();
    for (const auto& a : r.at("actions")) {
      const std::string name = a.get<std::string>();
      const std::size_t first = name.find('|'), last = name.rfind('|');
      c.takes.insert(first != std::string::npos && last > first ? name.substr(first + 1, last - first - 1) : name);
    }
    for (const auto& p : r.at("poses"))
      c.poses.push_back({p.at("time").get<double>(), point(p.at("min")), point(p.at("max")), point(p.at("centroid"))});
    out.push_back(std::move(c));
  }
  return out;
}

PoseDeviation pose_deviation(const BlenderCharacter& ours, const BlenderCharacter& source) {
  PoseDeviation d;
  if (!source.poses.empty()) d.height = source.poses.front().high.z() - source.poses.front().low.z();
  for (std::size_t i = 0; i < std::min(ours.poses.size(), source.poses.size()); ++i) {
    const BlenderPose &a = ours.poses[i], &b = source.poses[i];
    for (const auto& [p, q] : {std::pair{a.low, b.low}, {a.high, b.high}, {a.centroid, b.centroid}})
      d.distance = std::max(d.distance, (p - q).cwiseAbs().maxCoeff());
    ++d.times;
  }
  return d;
}

std::vector<BlenderCharacter> expect_same_character(const std::vector<CharacterCase>& cases, double step,
                                                   const std::filesystem::path& dir, const std::string& extension) {
  std::vector<std::pair<std::string, std::string>> pairs;
  for (const CharacterCase& c : cases) {
    const std::string in = (kData / c.source).string();
    const std::string out = (dir / (std::to_string(pairs.size()) + extension)).string();
    const std::string verb = c.command.substr(0, c.command.find(' '));
    const auto r = run_cli(verb + " " + in + " -o " + out + c.command.substr(verb.size()));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    if (r.exit_code != 0) return {};
    EXPECT_NE(r.out.find(" kept"), std::string::npos) << c.source << ": " << r.out;
    EXPECT_EQ(r.err.find("are not written"), std::string::npos) << c.source << ": " << r.err;
    EXPECT_EQ(r.err.find("not kept"), std::string::npos) << c.source << ": " << r.err;
    const auto log = dir / (std::to_string(pairs.size()) + ".assimp");
    EXPECT_EQ(std::system(("assimp info '" + out + "' >" + log.string() + " 2>&1").c_str()), 0) << out << ": " << read_text(log);
    pairs.emplace_back(in, out);
  }
  const std::vector<BlenderCharacter> imports = blender_characters(pairs, step, dir);
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const BlenderCharacter &source = imports[2 * i], &ours = imports[2 * i + 1];
    const std::string& name = pairs[i].first;
    EXPECT_FALSE(source.meshes.empty()) << name;
    EXPECT_EQ(ours.meshes, source.meshes) << name;
    EXPECT_EQ(ours.takes, source.takes) << name;
    const PoseDeviation d = pose_deviation(ours, source);
    EXPECT_EQ(d.times, 3u) << name;
    EXPECT_LE(d.distance, 1e-3 * d.height) << name;
    std::printf("[ blender ] %s (%s): %zu vertices, worst %.4g mm of %.4g m at 3 times\n", name.c_str(),
                cases[i].command.c_str(), ours.meshes.empty() ? 0 : ours.meshes.front().vertices, d.distance * 1000,
                d.height);
  }
  return imports;
}

}  // namespace rotinterp::test
