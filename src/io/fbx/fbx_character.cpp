// The tree edit of an FBX character: the source's nodes written back, its animation objects replaced by ours
// (io/fbx/fbx_character.h).
#include "rotinterp/io/fbx/fbx_character.h"

#include "fbx_objects.h"
#include "fbx_write_document.h"
#include "fbx_write_takes.h"
#include "rotinterp/io/files/kept_text.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace rotinterp {

namespace {

constexpr std::string_view kAnimationObjects[] = {"AnimationStack", "AnimationLayer", "AnimationCurveNode",
                                                  "AnimationCurve"};
// New object ids start here, skipping any the source uses.
constexpr std::int64_t kFirstNewId = 1000000;
// Curve values within this (relative to max(1, |value|)) are the same: float round-off.
constexpr double kStill = 1e-5;

bool is_animation(const FbxNode& object) {
  return std::find(std::begin(kAnimationObjects), std::end(kAnimationObjects), object.name) != std::end(kAnimationObjects);
}

// A Properties70 entry of `node` (P: name, type, label, flags, value…), or nullptr.
FbxNode* entry(FbxNode& node, std::string_view name) {
  for (FbxNode& block : node.children)
    if (block.name == "Properties70")
      for (FbxNode& p : block.children)
        if (!p.properties.empty() && p.properties[0].text == name) return &p;
  return nullptr;
}

FbxProperty scalar(char type, std::int64_t integer, double number = 0.0) {
  FbxProperty p;
  p.type = type;
  p.integer = integer;
  p.number = number;
  return p;
}
FbxProperty text(std::string s) {
  FbxProperty p;
  p.type = 'S';
  p.text = std::move(s);
  return p;
}

// Sets entry `name`'s value (the fifth field), adding the entry where it is missing,
// labelled as FBX SDK files label its type: Blender's importer asserts a double's
// label is "Number" (a CustomFrameRate labelled "" made it refuse the file).
void set_entry(FbxNode& node, std::string_view name, std::string_view type, const FbxProperty& value) {
  FbxNode* p = entry(node, name);
  if (!p) {
    auto block = std::find_if(node.children.begin(), node.children.end(), [](const FbxNode& c) { return c.name == "Properties70"; });
    if (block == node.children.end()) block = node.children.insert(node.children.end(), FbxNode{"Properties70", {}, {}});
    const std::string label = type == "double" ? "Number" : type == "KTime" ? "Time" : "";
    block->children.push_back(FbxNode{"P", {text(std::string(name)), text(std::string(type)), text(label), text("")}, {}});
    p = &block->children.back();
  }
  p->properties.resize(5);
  p->properties[4] = value;
}

// What the source's objects are, and which of them go.
struct Survey {
  std::set<std::int64_t> ids, removed;
  std::size_t dropped_clusters = 0, dropped_properties = 0, unnormalized_vertices = 0;
};

// Control points whose clusters' weights (per skin) sum to more than 0 but not to 1.
std::size_t unnormalized_vertices(const fbx::Objects& objects, const std::set<std::int64_t>& removed) {
  std::map<std::int64_t, std::map<std::int64_t, double>> sums;  // skin → control point → weight
  for (const FbxNode* o : objects.in_order) {
    const std::int64_t id = fbx::object_id(*o);
    if (o->name != "Deformer" || fbx::object_subclass(*o) != "Cluster" || removed.count(id)) continue;
    const FbxNode *indexes = o->child("Indexes"), *weights = o->child("Weights");
    if (!indexes || !weights || indexes->properties.empty() || weights->properties.empty()) continue;
    const std::vector<double> i = indexes->properties[0].as_doubles(), w = weights->properties[0].as_doubles();
    for (auto [it, end] = objects.by_child.equal_range(id); it != end; ++it)
      for (std::size_t k = 0; k < std::min(i.size(), w.size()); ++k)
        sums[objects.connections[it->second].parent][static_cast<std::int64_t>(i[k])] += w[k];
  }
  std::size_t n = 0;
  for (const auto& [skin, points] : sums)
    for (const auto& [point, sum] : points) n += sum > 0.0 && std::abs(sum - 1.0) > kSkinWeightSumTolerance;
  return n;
}

// Whether some curve of the curve node `id` takes more than one value (beyond float round-off).
bool moves(const fbx::Objects& objects, std::int64_t id) {
  for (auto [it, end] = objects.by_parent.equal_range(id); it != end; ++it) {
    const auto curve = objects.by_id.find(objects.connections[it->second].child);
    if (curve == objects.by_id.end() || curve->second->name != "AnimationCurve") continue;
    const FbxNode* values = curve->second->child("KeyValueFloat");
    if (!values || values->properties.empty()) continue;
    const std::vector<double> v = values->properties[0].as_doubles();
    if (std::any_of(v.begin(), v.end(), [&](double x) { return std::abs(x - v.front()) > kStill * std::max(1.0, std::abs(x)); }))
      return true;
  }
  return false;
}

Survey survey(const fbx::Objects& objects) {
  Survey s;
  for (const FbxNode* o : objects.in_order) {
    const std::int64_t id = fbx::object_id(*o);
    s.ids.insert(id);
    if (is_animation(*o)) s.removed.insert(id);
  }
  for (const FbxNode* o : objects.in_order) {
    const std::int64_t id = fbx::object_id(*o);
    if (o->name == "AnimationCurveNode") {
      bool lcl = false, other = false;
      for (auto [it, end] = objects.by_child.equal_range(id); it != end; ++it) {
        const std::string& property = objects.connections[it->second].property;
        if (property.empty()) continue;
        (property == "Lcl Translation" || property == "Lcl Rotation" || property == "Lcl Scaling" ? lcl : other) = true;
      }
      if (other && !lcl && moves(objects, id)) ++s.dropped_properties;
    }
    if (o->name == "Deformer" && fbx::object_subclass(*o) == "Cluster") {
      // A cluster deforms by its bone: one linked to no model is dropped (a repair).
      bool linked = false;
      for (auto [it, end] = objects.by_parent.equal_range(id); it != end; ++it) {
        const auto child = objects.by_id.find(objects.connections[it->second].child);
        linked = linked || (child != objects.by_id.end() && child->second->name == "Model");
      }
      if (!linked) s.removed.insert(id), ++s.dropped_clusters;
    }
  }
  s.unnormalized_vertices = unnormalized_vertices(objects, s.removed);
  return s;
}

FbxKept count_kept(const fbx::Objects& objects, const Survey& s) {
  FbxKept k;
  k.dropped_clusters = s.dropped_clusters;
  k.dropped_properties = s.dropped_properties;
  k.unnormalized_vertices = s.unnormalized_vertices;
  for (const FbxNode* o : objects.in_order) {
    if (s.removed.count(fbx::object_id(*o))) continue;
    const std::string subclass = fbx::object_subclass(*o);
    if (o->name == "Geometry" && subclass == "Mesh") ++k.meshes;
    if (o->name == "Deformer") k.skins += subclass == "Skin", k.bones += subclass == "Cluster", k.blend_shapes += subclass == "BlendShape";
    if (o->name == "Material") ++k.materials;
    if (o->name == "Texture") ++k.textures;
    if (o->name == "Pose" && subclass == "BindPose") ++k.bind_poses;
    if (const FbxNode* content = o->name == "Video" ? o->child("Content") : nullptr)
      if (!content->properties.empty() && !content->properties[0].text.empty()) ++k.embedded_media;
  }
  return k;
}

// Definitions with each type's count as written (GlobalSettings as the source has it).
FbxNode definitions(FbxNode defs, const std::map<std::string, std::size_t>& counts) {
  std::set<std::string> listed;
  std::int64_t total = 0;
  auto set_count = [](FbxNode& node, std::int64_t n) {
    auto c = std::find_if(node.children.begin(), node.children.end(), [](const FbxNode& x) { return x.name == "Count"; });
    if (c == node.children.end()) c = node.children.insert(node.children.end(), FbxNode{"Count", {scalar('I', 0)}, {}});
    if (c->properties.empty()) c->properties.push_back(scalar('I', 0));
    c->properties[0].integer = n;
  };
  for (FbxNode& type : defs.children) {
    if (type.name != "ObjectType" || type.properties.empty()) continue;
    const std::string& name = type.properties[0].text;
    listed.insert(name);
    if (name != "GlobalSettings") {
      const auto n = counts.find(name);
      set_count(type, n == counts.end() ? 0 : static_cast<std::int64_t>(n->second));
    }
    if (const FbxNode* c = type.child("Count"); c && !c->properties.empty()) total += c->properties[0].integer;
  }
  for (std::string_view name : kAnimationObjects)
    if (!listed.count(std::string(name)) && counts.count(std::string(name))) {
      FbxNode type{"ObjectType", {text(std::string(name))}, {}};
      set_count(type, static_cast<std::int64_t>(counts.at(std::string(name))));
      total += static_cast<std::int64_t>(counts.at(std::string(name)));
      defs.children.push_back(std::move(type));
    }
  set_count(defs, total);
  return defs;
}

}  // namespace

std::string FbxKept::text() const {
  std::vector<std::string> parts;
  if (meshes) parts.push_back(count_text(meshes, "mesh", "meshes"));
  if (skins) parts.push_back(count_text(skins, "skin", "skins") + " (" + count_text(bones, "bone", "bones") + ")");
  if (blend_shapes) parts.push_back(count_text(blend_shapes, "blend shape", "blend shapes"));
  if (materials) parts.push_back(count_text(materials, "material", "materials"));
  if (textures) parts.push_back(count_text(textures, "texture", "textures"));
  if (embedded_media) parts.push_back(count_text(embedded_media, "embedded image", "embedded images"));
  if (bind_poses) parts.push_back(count_text(bind_poses, "bind pose", "bind poses"));
  std::string s = kept_text(parts);
  if (skins && !bind_poses) s += "; no bind pose (readers take the clusters' matrices)";
  if (ascii) s += "; written as ASCII FBX, as the source";
  if (dropped_properties) s += "; dropped: " + count_text(dropped_properties, "animated property", "animated properties") + " other than rotation and translation";
  if (dropped_connections) s += "; repaired: " + count_text(dropped_connections, "connection", "connections") + " to missing objects dropped";
  if (dropped_clusters) s += "; repaired: " + count_text(dropped_clusters, "cluster", "clusters") + " linked to no bone dropped";
  if (unnormalized_vertices)
    s += "; " + unnormalized_weights_text(unnormalized_vertices) + " (kept as the source has them; Blender normalizes them)";
  return s;
}

Result<FbxCharacterFile> encode_fbx_character(const FbxCharacter& source, const std::vector<FbxCharacterTake>& takes,
                                              const std::optional<Rate>& rate, FbxEncoding encoding) {
  if (takes.empty()) return make_error(source.label + ": no takes to write");
  if (!source.doc.node("Objects") || !source.doc.node("Connections"))
    return make_error(source.label + ": no Objects or Connections to keep");
  const fbx::Objects objects = fbx::index_objects(source.doc);
  const Survey s = survey(objects);
  FbxCharacterFile out;
  out.kept = count_kept(objects, s);
  out.kept.ascii = encoding == FbxEncoding::ascii;

  std::int64_t next_id = kFirstNewId;
  auto new_id = [&] {
    while (s.ids.count(next_id)) ++next_id;
    return next_id++;
  };
  std::vector<FbxTakeIds> ids;
  std::vector<FbxTickSpan> spans;
  FbxTickSpan whole{};
  std::map<std::string, std::size_t> counts;
  for (const FbxNode* o : objects.in_order)
    if (!s.removed.count(fbx::object_id(*o))) ++counts[o->name];
  for (const FbxCharacterTake& t : takes) {
    ids.push_back(new_take_ids(t.take.curves, new_id));
    spans.push_back(fbx_curves_span(t.take.curves));
    whole = ids.size() == 1 ? spans.back() : FbxTickSpan{std::min(whole.start, spans.back().start), std::max(whole.stop, spans.back().stop)};
    ++counts["AnimationStack"], ++counts["AnimationLayer"];
    counts["AnimationCurveNode"] += ids.back().curve_nodes;
    counts["AnimationCurve"] += ids.back().curves;
  }
  const std::string& active = takes.front().take.name;

  FbxWriteDocument doc(encoding);
  FbxEncoder& e = doc.enc();
  bool wrote_takes = false;
  auto write_takes = [&] {
    e.begin("Takes");
    doc.leaf_str("Current", active);
    for (std::size_t t = 0; t < takes.size(); ++t) write_take_entry(doc, takes[t].take.name, spans[t]);
    e.end();
    wrote_takes = true;
  };
  for (const FbxNode& top : source.doc.nodes) {
    if (top.name == "FBXHeaderExtension") {
      FbxNode header = top;
      for (FbxNode& c : header.children)
        if (c.name == "FBXVersion") c.properties = {scalar('I', FbxEncoder::kVersion)};  // the encoding we write
      e.node(header);
    } else if (top.name == "FileId" && encoding == FbxEncoding::binary) {
      doc.file_id();  // with CreationTime: our footer matches them
    } else if (top.name == "CreationTime" && encoding == FbxEncoding::binary) {
      continue;
    } else if (top.name == "GlobalSettings") {
      FbxNode settings = top;
      if (rate) {
        set_entry(settings, "TimeMode", "enum", scalar('I', fbx_time_mode(rate->num, rate->den)));
        set_entry(settings, "CustomFrameRate", "double", scalar('D', 0, rate->hz()));
      }
      set_entry(settings, "TimeSpanStart", "KTime", scalar('L', whole.start));
      set_entry(settings, "TimeSpanStop", "KTime", scalar('L', whole.stop));
      e.node(settings);
    } else if (top.name == "Documents") {
      FbxNode documents = top;
      for (FbxNode& d : documents.children)
        if (d.name == "Document") set_entry(d, "ActiveAnimStackName", "KString", text(active));
      e.node(documents);
    } else if (top.name == "Definitions") {
      e.node(definitions(top, counts));
    } else if (top.name == "Objects") {
      e.begin("Objects");
      for (const FbxNode& o : top.children)
        if (!is_animation(o) && !s.removed.count(fbx::object_id(o))) e.node(o);
      for (std::size_t t = 0; t < takes.size(); ++t) write_take_objects(doc, takes[t].take, ids[t], spans[t]);
      e.end();
    } else if (top.name == "Connections") {
      e.begin("Connections");
      for (const FbxNode& c : top.children) {
        const auto& p = c.properties;
        const bool valid = c.name == "C" && p.size() >= 3 && p[1].is_integer() && p[2].is_integer();
        if (valid && (s.removed.count(p[1].integer) || s.removed.count(p[2].integer))) continue;
        if (!valid || !s.ids.count(p[1].integer) || (p[2].integer != 0 && !s.ids.count(p[2].integer))) {
          ++out.kept.dropped_connections;
          continue;
        }
        e.node(c);
      }
      for (std::size_t t = 0; t < takes.size(); ++t)
        write_take_connections(doc, takes[t].take, ids[t], takes[t].model_ids);
      e.end();
    } else if (top.name == "Takes") {
      write_takes();
    } else {
      e.node(top);  // References, unknown nodes: as they are
    }
  }
  if (!wrote_takes) write_takes();
  auto bytes = e.finish();
  if (!bytes) return bytes.failure(source.label + ": ");
  out.bytes = std::move(*bytes);
  return out;
}

}  // namespace rotinterp
