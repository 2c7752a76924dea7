// Files that crash or stall readers, built in tests (never copied into the
// project): shared by the io and eval suites.
#pragma once

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>

namespace rotinterp::test {

// A one-bone ASCII FBX whose X translation has one curve with `count` key times
// (KeyTime and KeyValueFloat blocks) in a take from 0 to 1 s. count 0 makes
// assimp 5.2.5's FBX converter segfault; a key at 1000 s trips its assertion
// '!keys.empty()', which aborts.
inline std::string fbx_one_curve(const std::string& key_times, const std::string& key_values, int count) {
  const std::string n = std::to_string(count);
  return "; FBX 7.4.0 project file\n"
         "FBXHeaderExtension:  {\n\tFBXHeaderVersion: 1003\n\tFBXVersion: 7400\n}\n"
         "GlobalSettings:  {\n\tVersion: 1000\n\tProperties70:  {\n"
         "\t\tP: \"UnitScaleFactor\", \"double\", \"Number\", \"\",1\n\t}\n}\n"
         "Objects:  {\n"
         "\tModel: 1000, \"Model::Bone\", \"LimbNode\" {\n\t\tVersion: 232\n\t}\n"
         "\tAnimationStack: 2000, \"AnimStack::Take\", \"\" {\n\t\tProperties70:  {\n"
         "\t\t\tP: \"LocalStart\", \"KTime\", \"Time\", \"\",0\n"
         "\t\t\tP: \"LocalStop\", \"KTime\", \"Time\", \"\",46186158000\n\t\t}\n\t}\n"
         "\tAnimationLayer: 3000, \"AnimLayer::Base\", \"\" {\n\t}\n"
         "\tAnimationCurveNode: 4000, \"AnimCurveNode::T\", \"\" {\n\t\tProperties70:  {\n"
         "\t\t\tP: \"d|X\", \"Number\", \"\", \"A\",0\n\t\t}\n\t}\n"
         "\tAnimationCurve: 5000, \"AnimCurve::\", \"\" {\n\t\tDefault: 0\n\t\tKeyVer: 4009\n"
         "\t\tKeyTime: *" + n + " {\n\t\t\ta: " + key_times + "\n\t\t}\n"
         "\t\tKeyValueFloat: *" + n + " {\n\t\t\ta: " + key_values + "\n\t\t}\n\t}\n}\n"
         "Connections:  {\n\tC: \"OO\",1000,0\n\tC: \"OO\",3000,2000\n\tC: \"OO\",4000,3000\n"
         "\tC: \"OP\",4000,1000, \"Lcl Translation\"\n\tC: \"OP\",5000,4000, \"d|X\"\n}\n";
}

// fuzz_read_any crash-79f25736: `shared_huesitos` (../shared/data's
// fbx/assimp_huesitos.fbx, 111 564 bytes) with 6 bytes changed, which makes
// assimp 5.2.5 free memory twice in ~aiScene. Empty when the source differs.
// GCC 12 with a precompiled header inlines the returned string's move and warns that
// a short string's buffer is overrun or overread (-Warray-bounds, -Wstringop-*), which a
// 111 564-byte one is not.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Warray-bounds"
#pragma GCC diagnostic ignored "-Wstringop-overread"
#pragma GCC diagnostic ignored "-Wstringop-overflow"
inline std::string double_free_fbx(const std::filesystem::path& shared_huesitos) {
  std::ifstream in(shared_huesitos, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() != 111564u) return {};
  const std::pair<std::size_t, unsigned char> patch[] = {{34883, 0x32}, {36139, 0x30}, {72784, 0x38},
                                                         {99599, 0x20}, {99651, 0xe3}, {108177, 0x34}};
  for (const auto& [at, value] : patch) bytes[at] = static_cast<char>(value);
  return bytes;
}
#pragma GCC diagnostic pop

// A BVH chain of `depth` joints, each the child of the one before, two frames.
inline std::string nested_bvh(std::size_t depth) {
  std::string s = "HIERARCHY\nROOT J0\n{\nOFFSET 0 0 0\nCHANNELS 3 Zrotation Xrotation Yrotation\n";
  for (std::size_t i = 1; i < depth; ++i)
    s += "JOINT J" + std::to_string(i) + "\n{\nOFFSET 0 1 0\nCHANNELS 3 Zrotation Xrotation Yrotation\n";
  s += "End Site\n{\nOFFSET 0 1 0\n}\n";
  for (std::size_t i = 0; i < depth; ++i) s += "}\n";
  s += "MOTION\nFrames: 2\nFrame Time: 0.01\n";
  std::string row;
  for (std::size_t i = 0; i < 3 * depth; ++i) row += "0 ";
  return s + row + "\n" + row + "\n";
}

}  // namespace rotinterp::test
