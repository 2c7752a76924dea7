// Our FBX node reader: every shared FBX file (binary 6.1–7.7, ASCII) reads; what
// our writer encodes reads back node for node in both encodings; hostile sizes,
// counts, depth and truncation are refused with one line naming the file and node.
#include "fbx_encode.h"
#include "io_test_util.h"
#include "rotinterp/io/fbx/fbx_nodes.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace rotinterp {
namespace {

using test::kData;

std::string file_bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A small document: one array big enough to be zlib-compressed in binary.
std::string encoded(FbxEncoder::Format format) {
  FbxEncoder e(format);
  e.begin("Objects");
  e.begin("AnimationCurve");
  e.i64(42).str(e.object_name("", "AnimCurve")).str("");
  e.begin("KeyTime");
  std::vector<std::int64_t> times;
  for (std::int64_t k = 0; k < 100; ++k) times.push_back(k * 1924423250);
  e.i64_array(times);
  e.end();
  e.begin("KeyValueFloat");
  e.f32_array({1.5f, -2.25f, 3.0f});
  e.end();
  e.begin("Default");
  e.f64(0.125);
  e.end();
  e.end();
  e.end();
  return *e.finish();
}

TEST(FbxNodes, EveryEncodingOfOurWriterReadsBackNodeForNode) {
  for (auto format : {FbxEncoder::Format::binary, FbxEncoder::Format::ascii}) {
    auto doc = parse_fbx_nodes(encoded(format), "x.fbx");
    ASSERT_TRUE(doc.ok()) << doc.error();
    EXPECT_EQ(doc->binary, format == FbxEncoder::Format::binary);
    EXPECT_EQ(doc->version, 7400u);
    const FbxNode* objects = doc->node("Objects");
    ASSERT_NE(objects, nullptr);
    const FbxNode* curve = objects->child("AnimationCurve");
    ASSERT_NE(curve, nullptr);
    ASSERT_EQ(curve->properties.size(), 3u);
    EXPECT_EQ(curve->properties[0].integer, 42);
    const std::vector<double> times = curve->child("KeyTime")->properties.at(0).as_doubles();
    ASSERT_EQ(times.size(), 100u);
    EXPECT_EQ(times[99], 99.0 * 1924423250);
    EXPECT_EQ(curve->child("KeyValueFloat")->properties.at(0).as_doubles(), (std::vector<double>{1.5, -2.25, 3.0}));
    EXPECT_EQ(curve->child("Default")->properties.at(0).as_double(), 0.125);
  }
}

TEST(FbxNodes, EverySharedFbxFileReadsWithItsObjects) {
  std::size_t files = 0;
  for (const char* dir : {"fbx", "curves"})
    for (const auto& entry : std::filesystem::directory_iterator(kData / dir)) {
      if (entry.path().extension() != ".fbx") continue;
      ++files;
      auto doc = parse_fbx_nodes(file_bytes(entry.path()), entry.path().string());
      ASSERT_TRUE(doc.ok()) << doc.error();
      EXPECT_NE(doc->node("Objects"), nullptr) << entry.path();
      EXPECT_GE(doc->version, 6100u) << entry.path();
      EXPECT_LE(doc->version, 7700u) << entry.path();
    }
  EXPECT_GE(files, 16u);
}

TEST(FbxNodes, EveryTruncationIsRefusedOrReadWithoutReadingPastTheEnd) {
  const std::string whole = encoded(FbxEncoder::Format::binary);
  std::size_t refused = 0;
  for (std::size_t n = 0; n < whole.size(); ++n) {
    // A copy of exactly n bytes, so that a read past it is caught by the sanitizers.
    const std::string cut = whole.substr(0, n);
    auto doc = parse_fbx_binary(cut, "cut.fbx");
    if (!doc.ok()) {
      ++refused;
      EXPECT_EQ(doc.error().rfind("cut.fbx: ", 0), 0u) << doc.error();
    }
  }
  EXPECT_GT(refused, whole.size() / 2);
}

TEST(FbxNodes, AHostileArrayCountIsRefusedNamingTheNode) {
  std::string bytes = encoded(FbxEncoder::Format::binary);
  // KeyValueFloat's 'f' array: count 3, raw (encoding 0), 12 bytes.
  const std::string header = std::string("f\x03\0\0\0\0\0\0\0\x0c\0\0\0", 13);
  const std::size_t at = bytes.find(header);
  ASSERT_NE(at, std::string::npos);
  bytes[at + 4] = '\x7f';  // count 0x7f000003
  auto doc = parse_fbx_binary(bytes, "hostile.fbx");
  ASSERT_FALSE(doc.ok());
  EXPECT_EQ(doc.error().rfind("hostile.fbx: FBX node Objects/AnimationCurve/KeyValueFloat: ", 0), 0u) << doc.error();
  EXPECT_EQ(doc.error().find('\n'), std::string::npos);

  const std::string ascii = "; FBX 7.4.0 project file\nKeyTime: *4000000000 {\n a: 1\n}\n";
  auto text = parse_fbx_ascii(ascii, "hostile.fbx");
  ASSERT_FALSE(text.ok());
  EXPECT_EQ(text.error().rfind("hostile.fbx: FBX node KeyTime: ", 0), 0u) << text.error();
}

TEST(FbxNodes, AnErrorNamingANodeWithControlCharactersStaysOneLine) {
  FbxEncoder e(FbxEncoder::Format::binary);
  e.begin("Bad\nName");
  e.begin("Values");
  e.f32_array({1.0f});
  e.end();
  e.end();
  std::string bytes = *e.finish();
  const std::size_t at = bytes.find(std::string("f\x01\0\0\0\0\0\0\0\x04\0\0\0", 13));
  ASSERT_NE(at, std::string::npos);
  bytes[at + 4] = '\x7f';
  auto doc = parse_fbx_binary(bytes, "ctrl.fbx");
  ASSERT_FALSE(doc.ok());
  EXPECT_EQ(doc.error().find('\n'), std::string::npos) << doc.error();
  EXPECT_NE(doc.error().find("Bad?Name/Values"), std::string::npos) << doc.error();
}

TEST(FbxNodes, AZlibArrayThatLiesAboutItsSizeIsRefused) {
  std::string bytes = encoded(FbxEncoder::Format::binary);
  // KeyTime's 'l' array of 100 is zlib-compressed (encoding 1): claim 101 elements.
  const std::string header = std::string("l\x64\0\0\0\x01\0\0\0", 9);
  const std::size_t at = bytes.find(header);
  ASSERT_NE(at, std::string::npos);
  bytes[at + 1] = '\x65';
  auto doc = parse_fbx_binary(bytes, "liar.fbx");
  ASSERT_FALSE(doc.ok());
  EXPECT_NE(doc.error().find("KeyTime: zlib array"), std::string::npos) << doc.error();
}

TEST(FbxNodes, NestingPastTheDepthLimitIsRefused) {
  std::string deep;
  for (std::size_t d = 0; d <= kFbxMaxDepth + 1; ++d) deep += "N: {\n";
  for (std::size_t d = 0; d <= kFbxMaxDepth + 1; ++d) deep += "}\n";
  auto doc = parse_fbx_ascii(deep, "deep.fbx");
  ASSERT_FALSE(doc.ok());
  EXPECT_NE(doc.error().find("nested deeper than"), std::string::npos) << doc.error();

  std::string shallow;
  for (std::size_t d = 0; d < 10; ++d) shallow += "N: {\n";
  for (std::size_t d = 0; d < 10; ++d) shallow += "}\n";
  EXPECT_TRUE(parse_fbx_ascii(shallow, "ok.fbx").ok());
}

TEST(FbxNodes, AsciiPropertiesContinueAfterACommaAcrossLines) {
  const std::string text = "Key: 0,1.5,U,\n   s,0 ; a comment\nNext: \"a, b\"\n";
  auto doc = parse_fbx_ascii(text, "keys.fbx");
  ASSERT_TRUE(doc.ok()) << doc.error();
  ASSERT_EQ(doc->nodes.size(), 2u);
  const auto& p = doc->nodes[0].properties;
  ASSERT_EQ(p.size(), 5u);
  EXPECT_EQ(p[1].as_double(), 1.5);
  EXPECT_EQ(p[2].text, "U");
  EXPECT_EQ(p[3].text, "s");
  EXPECT_EQ(doc->nodes[1].properties.at(0).text, "a, b");
}

}  // namespace
}  // namespace rotinterp
