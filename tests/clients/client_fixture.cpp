#include "client_fixture.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <utility>

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

BlenderImport playing(const BlenderImport& b, const std::string& action) {
  BlenderImport out = b;
  out.times.clear(), out.heads.clear(), out.origins.clear();
  if (const auto it = b.action_keys.find(action); it != b.action_keys.end()) {
    out.times = it->second.times;
    out.heads = it->second.heads;
    out.origins = it->second.origins;
  }
  return out;
}

nlohmann::json run_blender(const std::string& script, const std::string& args, const std::vector<std::string>& files,
                           const std::filesystem::path& dir, const std::string& stem) {
  const auto json = dir / (stem + ".json"), log = dir / (stem + ".log");
  std::string cmd = "blender -b --factory-startup --python " + std::string(ROTINTERP_SOURCE_DIR) + "/tests/clients/" +
                    script + " -- " + json.string() + args;
  for (const std::string& f : files) cmd += " '" + f + "'";
  cmd += " >" + log.string() + " 2>&1";
  if (std::system(cmd.c_str()) != 0)
    throw std::runtime_error("Blender failed (is it installed? scripts/install-deps.sh adds it):\n" + read_text(log));
  std::ifstream in(json);
  return nlohmann::json::parse(in);
}

std::string make_blender_rig(const std::filesystem::path& dir, bool skinned) {
  const std::string stem = (dir / "rig").string(), log = (dir / "rig.log").string();
  const std::string make = "blender -b --factory-startup --python '" + std::string(ROTINTERP_SOURCE_DIR) +
                           "/tests/clients/blender_nla_rig.py' -- '" + stem + "'" + (skinned ? " skinned" : "") + " > '" +
                           log + "' 2>&1";
  if (std::system(make.c_str()) != 0) throw std::runtime_error("Blender could not make the rig:\n" + read_text(log));
  return stem;
}

std::vector<BlenderImport> blender_imports(const std::vector<std::string>& files, const std::filesystem::path& dir) {
  const nlohmann::json all = run_blender("blender_dump.py", "", files, dir, "blender");
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
    b.actions = strings(r, "actions");
    if (r.contains("action_keys"))
      for (const auto& [name, keys] : r["action_keys"].items())
        b.action_keys[name] = {keys.at("times").get<std::vector<double>>(), points(keys.at("positions")),
                               points(keys.at("object_positions"))};
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

Deviation worst_deviation(const BlenderImport& ours, const BlenderImport& source, double cut, CompareAt at) {
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
  if (ours.times.empty()) return d.problem = "no keys", d;
  // The index in `times` of the key at t, if there is one.
  const auto key_at = [](const std::vector<double>& times, double t) -> std::optional<std::size_t> {
    const auto near = std::min_element(times.begin(), times.end(),
                                       [t](double a, double b) { return std::abs(a - t) < std::abs(b - t); });
    if (near == times.end() || std::abs(*near - t) > kSameKeyTime) return std::nullopt;
    return static_cast<std::size_t>(near - times.begin());
  };
  std::vector<std::pair<std::size_t, std::size_t>> pairs;  // (key of ours, key of the source)
  if (at == CompareAt::every_key_of_ours) {
    for (std::size_t k = 0; k < ours.times.size(); ++k) {
      const std::optional<std::size_t> s = key_at(source.times, cut + ours.times[k]);
      if (!s) return d.problem = "no source key at " + std::to_string(cut + ours.times[k]) + " s", d;
      pairs.emplace_back(k, *s);
    }
  } else {
    for (std::size_t s = 0; s < source.times.size(); ++s) {
      const double t = source.times[s] - cut;
      if (t < ours.times.front() - kSameKeyTime || t > ours.times.back() + kSameKeyTime) continue;
      const std::optional<std::size_t> k = key_at(ours.times, t);
      if (!k) return d.problem = "no key of ours at the source's key " + std::to_string(source.times[s]) + " s", d;
      pairs.emplace_back(*k, s);
    }
  }
  d.keys = pairs.size();
  for (const auto& [k, s] : pairs)
    for (std::size_t b = 0; b < ours.bones.size(); ++b) {
      const Vec3& truth = where[b] >= 0 ? source.heads[s][static_cast<std::size_t>(where[b])]
                                        : source.origins[s][static_cast<std::size_t>(-1 - where[b])];
      const double distance = (ours.heads[k][b] - truth).norm();
      if (distance > d.distance) d.distance = distance, d.joint = ours.bones[b], d.time = source.times[s];
    }
  return d;
}

}  // namespace rotinterp::test
