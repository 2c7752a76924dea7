// The DCC reference values of ../shared/data/curves/dcc_reference.tsv (MANIFEST.md,
// "Curves as the DCCs evaluate them"), for the curve tests and the info CLI test.
#pragma once

#include "io_test_util.h"

#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace rotinterp::test {

struct DccCase {
  std::string name, node, property, file;
  char channel = 'X';
  std::size_t layer = 0;
  double time_offset_s = 0.0;
  std::vector<double> values;  // at i/24 s + time_offset_s
  // 1e-4 of the reference's range: the tolerance the issue sets.
  double tolerance() const {
    double lo = values.at(0), hi = values.at(0);
    for (double v : values) lo = std::min(lo, v), hi = std::max(hi, v);
    return 1e-4 * (hi - lo);
  }
};

// Each case with its file as MANIFEST maps it; the FBX 6.1 twin of the
// interpolation-modes file is listed as its own case.
inline std::vector<DccCase> dcc_cases() {
  const std::map<std::string, std::vector<std::string>> files = {
      {"maya_interpolation_modes",
       {"fbx/ufbx_maya_interpolation_modes_7500_ascii.fbx", "curves/ufbx_maya_interpolation_modes_6100_binary.fbx"}},
      {"maya_auto_clamp", {"curves/ufbx_maya_auto_clamp_7100_binary.fbx"}},
      {"maya_tangent_spline", {"curves/ufbx_maya_tangent_spline_7700_binary.fbx"}},
      {"motionbuilder_tangent_spline", {"fbx/ufbx_motionbuilder_tangent_spline_7700_ascii.fbx"}},
      {"motionbuilder_tangent_weight", {"curves/ufbx_motionbuilder_tangent_weight_7700_ascii.fbx"}}};
  std::vector<DccCase> out;
  std::ifstream in(kData / "curves/dcc_reference.tsv");
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, '\t');) f.push_back(cell);
    if (f.size() < 7) continue;
    DccCase c;
    c.name = f[0], c.node = f[1], c.property = f[2], c.channel = f[3].at(0);
    c.layer = std::stoul(f[4]);
    c.time_offset_s = std::stod(f[5]);
    std::istringstream vs(f[6]);
    for (double v; vs >> v;) c.values.push_back(v);
    for (const std::string& file : files.at(c.name)) {
      c.file = (kData / file).string();
      out.push_back(c);
    }
  }
  return out;
}

}  // namespace rotinterp::test
