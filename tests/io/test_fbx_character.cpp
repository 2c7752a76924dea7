// The tree edit of an FBX character (io/fbx/fbx_character.h): parsed, edited and
// encoded, the source's non-animation nodes come back equal (every property in its
// own type), its animation objects and their connections are gone, and every new
// connection names objects that exist.
#include "io/io_test_util.h"
#include "rotinterp/io/fbx/fbx_character.h"
#include "rotinterp/io/read.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

namespace rotinterp {
namespace {

bool same(const FbxProperty& a, const FbxProperty& b) {
  return a.type == b.type && a.integer == b.integer && a.text == b.text && a.integers == b.integers &&
         (a.number == b.number || (a.number != a.number && b.number != b.number)) && a.numbers == b.numbers;
}
bool same(const FbxNode& a, const FbxNode& b) {
  if (a.name != b.name || a.properties.size() != b.properties.size() || a.children.size() != b.children.size()) return false;
  for (std::size_t i = 0; i < a.properties.size(); ++i)
    if (!same(a.properties[i], b.properties[i])) return false;
  for (std::size_t i = 0; i < a.children.size(); ++i)
    if (!same(a.children[i], b.children[i])) return false;
  return true;
}

bool is_animation(const FbxNode& n) { return n.name.rfind("Animation", 0) == 0; }

TEST(FbxCharacter, NonAnimationNodesComeBackEqualAndOnlyTheAnimationIsReplaced) {
  for (const char* name : {"digitalrune_Dude.fbx", "ufbx_maya_kenney_character_7700_binary.fbx"}) {
    const std::filesystem::path path = test::kData / "fbx" / name;
    const Result<Clip> clip = read_clip(path);
    ASSERT_TRUE(clip) << clip.error();
    const Result<FbxCharacter> source = read_fbx_character(path);
    ASSERT_TRUE(source) << source.error();
    const Result<FbxCharacterFile> file = fbx_character_file({*clip}, path, false);
    ASSERT_TRUE(file) << file.error();
    const Result<FbxDocument> out = parse_fbx_nodes(file->bytes, "out.fbx");
    ASSERT_TRUE(out) << out.error();
    EXPECT_TRUE(out->binary);
    EXPECT_EQ(file->kept.meshes, 1u) << name;
    EXPECT_EQ(file->kept.skins, 1u) << name;

    // Top-level nodes other than those the edit states (rate, span, active take,
    // counts, version, file id) are equal.
    const std::set<std::string> edited = {"FBXHeaderExtension", "FileId", "CreationTime", "GlobalSettings", "Documents",
                                          "Definitions", "Objects", "Connections", "Takes"};
    for (const FbxNode& top : source->doc.nodes) {
      if (edited.count(top.name)) continue;
      const FbxNode* written = out->node(top.name);
      ASSERT_NE(written, nullptr) << name << ": " << top.name;
      EXPECT_TRUE(same(top, *written)) << name << ": " << top.name;
    }
    // Objects: the source's non-animation objects, in order and equal, then ours.
    std::vector<const FbxNode*> kept, ours;
    std::set<std::int64_t> old_animation, ids = {0};
    for (const FbxNode& o : source->doc.node("Objects")->children)
      if (is_animation(o)) old_animation.insert(o.properties.at(0).integer);
      else kept.push_back(&o);
    for (const FbxNode& o : out->node("Objects")->children) {
      ids.insert(o.properties.at(0).integer);
      if (!is_animation(o)) ours.push_back(&o);
      else EXPECT_EQ(old_animation.count(o.properties.at(0).integer), 0u) << name << ": an old animation object is kept";
    }
    ASSERT_EQ(ours.size(), kept.size()) << name;
    for (std::size_t i = 0; i < kept.size(); ++i) EXPECT_TRUE(same(*kept[i], *ours[i])) << name << ": " << kept[i]->name;
    // Connections: the source's that name no animation object, equal and in order,
    // then ours; every one names objects that exist.
    std::vector<const FbxNode*> source_links;
    for (const FbxNode& c : source->doc.node("Connections")->children)
      if (!old_animation.count(c.properties.at(1).integer) && !old_animation.count(c.properties.at(2).integer))
        source_links.push_back(&c);
    const auto& links = out->node("Connections")->children;
    ASSERT_GT(links.size(), source_links.size()) << name;
    for (std::size_t i = 0; i < source_links.size(); ++i) EXPECT_TRUE(same(*source_links[i], links[i])) << name;
    for (const FbxNode& c : links) {
      EXPECT_EQ(ids.count(c.properties.at(1).integer), 1u) << name << ": a connection from a missing object";
      EXPECT_EQ(ids.count(c.properties.at(2).integer), 1u) << name << ": a connection to a missing object";
    }
    // The edited file reads back as a clip of the same joints.
    const Result<FbxAnimation> animation = read_fbx_animation(*out, "out.fbx");
    ASSERT_TRUE(animation) << animation.error();
    EXPECT_EQ(animation->takes.size(), 1u) << name;
  }
}

// An inconsistent source: a connection to an object that is not there, and a
// cluster whose bone link is gone. Both are dropped, and the summary says so.
TEST(FbxCharacter, ConnectionsToMissingObjectsAndClustersWithoutABoneAreDroppedAndSaid) {
  const std::filesystem::path path = test::kData / "fbx" / "digitalrune_Marine_Run.fbx";
  const Result<Clip> clip = read_clip(path);
  ASSERT_TRUE(clip) << clip.error();
  Result<FbxCharacter> source = read_fbx_character(path);
  ASSERT_TRUE(source) << source.error();
  std::set<std::int64_t> clusters, models;
  for (const FbxNode& o : source->doc.node("Objects")->children) {
    if (o.name == "Deformer" && o.properties.at(2).text == "Cluster") clusters.insert(o.properties[0].integer);
    if (o.name == "Model") models.insert(o.properties[0].integer);
  }
  auto& nodes = source->doc.nodes;
  auto& links = std::find_if(nodes.begin(), nodes.end(), [](const FbxNode& n) { return n.name == "Connections"; })->children;
  // The first model → cluster link goes; a link to id 42 (no object) comes.
  const auto bone_link = std::find_if(links.begin(), links.end(), [&](const FbxNode& c) {
    return models.count(c.properties.at(1).integer) && clusters.count(c.properties.at(2).integer);
  });
  ASSERT_NE(bone_link, links.end());
  const std::int64_t orphan = bone_link->properties[2].integer;
  links.erase(bone_link);
  FbxNode missing = links.front();
  missing.properties[2].integer = 42;
  links.push_back(missing);

  const Result<FbxCharacterTake> take = fbx_character_take(*clip, *source, &source->animation.takes.front());
  ASSERT_TRUE(take) << take.error();
  const Result<FbxCharacterFile> file = encode_fbx_character(*source, {*take}, std::nullopt, FbxEncoding::binary);
  ASSERT_TRUE(file) << file.error();
  EXPECT_EQ(file->kept.dropped_connections, 1u);
  EXPECT_EQ(file->kept.dropped_clusters, 1u);
  EXPECT_NE(file->kept.text().find("1 connection to missing objects dropped"), std::string::npos) << file->kept.text();
  EXPECT_NE(file->kept.text().find("1 cluster linked to no bone dropped"), std::string::npos) << file->kept.text();
  const Result<FbxDocument> out = parse_fbx_nodes(file->bytes, "out.fbx");
  ASSERT_TRUE(out) << out.error();
  for (const FbxNode& o : out->node("Objects")->children) EXPECT_NE(o.properties.at(0).integer, orphan);
  for (const FbxNode& c : out->node("Connections")->children) {
    EXPECT_NE(c.properties.at(1).integer, orphan);
    EXPECT_NE(c.properties.at(2).integer, orphan);
    EXPECT_NE(c.properties.at(2).integer, 42);
  }
}

}  // namespace
}  // namespace rotinterp
