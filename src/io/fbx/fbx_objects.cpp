// FBX 7.x objects, connections, names and Properties70 look-ups (fbx_objects.h).
#include "fbx_objects.h"

namespace rotinterp::fbx {

std::int64_t object_id(const FbxNode& node) {
  if (node.properties.empty() || !node.properties[0].is_integer()) return 0;
  return node.properties[0].integer;
}

std::string object_name(const FbxNode& node) {
  for (const FbxProperty& p : node.properties) {
    if (!p.is_string()) continue;
    const std::string& s = p.text;
    if (const std::size_t bin = s.find(std::string_view("\0\1", 2)); bin != std::string::npos) return s.substr(0, bin);
    if (const std::size_t ascii = s.find("::"); ascii != std::string::npos) return s.substr(ascii + 2);
    return s;
  }
  return "";
}

std::string object_subclass(const FbxNode& node) {
  bool named = false;
  for (const FbxProperty& p : node.properties) {
    if (!p.is_string()) continue;
    if (named) return p.text;
    named = true;
  }
  return "";
}

Objects index_objects(const FbxDocument& doc) {
  Objects out;
  if (const FbxNode* objects = doc.node("Objects"))
    for (const FbxNode& o : objects->children) {
      const std::int64_t id = object_id(o);
      if (id == 0) continue;
      out.by_id.emplace(id, &o);
      out.in_order.push_back(&o);
    }
  if (const FbxNode* conns = doc.node("Connections"))
    for (const FbxNode& c : conns->children) {
      const auto& p = c.properties;
      if (c.name != "C" || p.size() < 3 || !p[0].is_string() || !p[1].is_integer() || !p[2].is_integer()) continue;
      Connection k{p[1].integer, p[2].integer, p.size() > 3 && p[3].is_string() ? p[3].text : ""};
      out.by_parent.emplace(k.parent, out.connections.size());
      out.by_child.emplace(k.child, out.connections.size());
      out.connections.push_back(std::move(k));
    }
  return out;
}

const FbxNode* find_property(const FbxNode& object, std::string_view name) {
  for (const char* block : {"Properties70", "Properties60"})
    if (const FbxNode* props = object.child(block))
      for (const FbxNode& p : props->children)
        if (!p.properties.empty() && p.properties[0].is_string() && p.properties[0].text == name) return &p;
  return nullptr;
}

double property_number(const FbxNode* p, std::size_t i, double fallback) {
  if (!p) return fallback;
  const std::size_t first = p->name == "P" ? 4 : 3;  // Properties70 has a label field
  if (p->properties.size() <= first + i || !p->properties[first + i].is_number()) return fallback;
  return p->properties[first + i].as_double();
}

FbxVec3 property_vec3(const FbxNode* p, const FbxVec3& fallback) {
  return {property_number(p, 0, fallback[0]), property_number(p, 1, fallback[1]), property_number(p, 2, fallback[2])};
}

}  // namespace rotinterp::fbx
