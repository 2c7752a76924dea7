#include "client_fixture.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace rotinterp::test {

namespace {

std::vector<std::vector<Vec3>> points(const nlohmann::json& rows) {
  std::vector<std::vector<Vec3>> out;
  for (const auto& row : rows) {
    out.emplace_back();
    for (const auto& p : row) out.back().emplace_back(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
  }
  return out;
}

std::vector<std::string> strings(const nlohmann::json& r, const char* key) {
  return r.contains(key) ? r[key].get<std::vector<std::string>>() : std::vector<std::string>{};
}

}  // namespace

std::vector<BlenderImport> blender_imports(const std::vector<std::string>& files, const std::filesystem::path& dir) {
  const auto json = dir / "blender.json", log = dir / "blender.log";
  std::string cmd = "blender -b --factory-startup --python " + std::string(ROTINTERP_SOURCE_DIR) +
                    "/tests/clients/blender_dump.py -- " + json.string();
  for (const std::string& f : files) cmd += " '" + f + "'";
  cmd += " >" + log.string() + " 2>&1";
  if (std::system(cmd.c_str()) != 0)
    throw std::runtime_error("Blender failed (is it installed? scripts/install-deps.sh adds it):\n" + read_text(log));
  std::ifstream in(json);
  const nlohmann::json all = nlohmann::json::parse(in);
  std::vector<BlenderImport> out;
  for (const std::string& f : files) {
    const nlohmann::json& r = all.at(f);
    BlenderImport b;
    b.armatures = r.at("armatures").get<int>();
    b.fps = r.at("fps").get<double>();
    b.bones = strings(r, "bones");
    b.connected = strings(r, "connected");
    b.objects = strings(r, "objects");
    if (r.contains("times")) b.times = r["times"].get<std::vector<double>>();
    if (r.contains("positions")) b.heads = points(r["positions"]);
    if (r.contains("object_positions")) b.origins = points(r["object_positions"]);
    out.push_back(std::move(b));
  }
  return out;
}

double figure_height(const BlenderImport& source) {
  if (source.heads.empty() || source.heads.front().empty()) return 0.0;
  double lo = INFINITY, hi = -INFINITY;
  for (const Vec3& p : source.heads.front()) lo = std::min(lo, p.z()), hi = std::max(hi, p.z());
  return hi - lo;
}

Deviation worst_deviation(const BlenderImport& ours, const BlenderImport& source, double cut) {
  Deviation d;
  // Where each joint of ours is in `source`: a bone (index ≥ 0) or an object (−1 − index).
  std::vector<long> where(ours.bones.size());
  for (std::size_t b = 0; b < ours.bones.size(); ++b) {
    const std::string& name = ours.bones[b];
    const auto bone = std::find(source.bones.begin(), source.bones.end(), name);
    const auto object = std::find(source.objects.begin(), source.objects.end(), name);
    if (bone != source.bones.end()) {
      where[b] = bone - source.bones.begin();
    } else if (object != source.objects.end()) {
      where[b] = -1 - (object - source.objects.begin());
    } else {
      d.problem += "no " + name + " in the source; ";
    }
  }
  for (const std::string& name : source.bones)
    if (std::find(ours.bones.begin(), ours.bones.end(), name) == ours.bones.end()) d.problem += "no bone " + name + "; ";
  if (!d.problem.empty()) return d;
  for (std::size_t k = 0; k < ours.times.size(); ++k) {
    const double t = cut + ours.times[k];
    const auto near = std::min_element(source.times.begin(), source.times.end(),
                                       [t](double a, double b) { return std::abs(a - t) < std::abs(b - t); });
    if (std::abs(*near - t) > kSameKeyTime) {
      d.problem = "no source key at " + std::to_string(t) + " s";
      return d;
    }
    const std::size_t s = static_cast<std::size_t>(near - source.times.begin());
    for (std::size_t b = 0; b < ours.bones.size(); ++b) {
      const Vec3& truth = where[b] >= 0 ? source.heads[s][static_cast<std::size_t>(where[b])]
                                        : source.origins[s][static_cast<std::size_t>(-1 - where[b])];
      const double distance = (ours.heads[k][b] - truth).norm();
      if (distance > d.distance) d.distance = distance, d.joint = ours.bones[b], d.time = t;
    }
  }
  return d;
}

}  // namespace rotinterp::test
