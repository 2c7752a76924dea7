// read_models: each FBX Model's transform properties (rotation order, pre/post
// rotation, pivots and offsets, inherit type, local TRS) over its template.
#include "fbx_objects.h"

#include <cmath>

namespace rotinterp::fbx {

namespace {

// Definitions/ObjectType "Model"/PropertyTemplate "FbxNode": the defaults a file
// leaves out of each Model.
const FbxNode* model_template(const FbxDocument& doc) {
  const FbxNode* defs = doc.node("Definitions");
  if (!defs) return nullptr;
  for (const FbxNode& type : defs->children) {
    if (type.name != "ObjectType" || type.properties.empty() || type.properties[0].text != "Model") continue;
    for (const FbxNode& t : type.children)
      if (t.name == "PropertyTemplate") return &t;
  }
  return nullptr;
}

const FbxNode* either(const FbxNode& model, const FbxNode* templ, std::string_view name) {
  if (const FbxNode* p = find_property(model, name)) return p;
  return templ ? find_property(*templ, name) : nullptr;
}

}  // namespace

void read_model_properties(const FbxNode& node, const FbxNode* templ, FbxModel& m) {
  // A non-finite component (a hostile file) takes the default: no NaN leaves the library.
  auto vec = [&](std::string_view name, const FbxVec3& fallback) {
    FbxVec3 v = property_vec3(either(node, templ, name), fallback);
    for (std::size_t c = 0; c < 3; ++c)
      if (!std::isfinite(v[c])) v[c] = fallback[c];
    return v;
  };
  auto num = [&](std::string_view name, double fallback) { return property_number(either(node, templ, name), 0, fallback); };
  m.name = object_name(node);
  m.type = object_subclass(node);
  m.rotation_order = static_cast<int>(num("RotationOrder", 0));
  if (m.rotation_order < 0 || m.rotation_order > 5) m.rotation_order = 0;  // 6 "spheric" is evaluated as XYZ
  m.inherit_type = static_cast<int>(num("InheritType", 0));
  m.rotation_active = num("RotationActive", 0) != 0.0;
  m.translation = vec("Lcl Translation", {0, 0, 0});
  m.rotation = vec("Lcl Rotation", {0, 0, 0});
  m.scaling = vec("Lcl Scaling", {1, 1, 1});
  m.pre_rotation = vec("PreRotation", {0, 0, 0});
  m.post_rotation = vec("PostRotation", {0, 0, 0});
  m.rotation_offset = vec("RotationOffset", {0, 0, 0});
  m.rotation_pivot = vec("RotationPivot", {0, 0, 0});
  m.scaling_offset = vec("ScalingOffset", {0, 0, 0});
  m.scaling_pivot = vec("ScalingPivot", {0, 0, 0});
}

std::vector<FbxModel> read_models(const FbxDocument& doc, const Objects& objects) {
  const FbxNode* templ = model_template(doc);
  std::vector<FbxModel> out;
  for (const FbxNode* node : objects.in_order) {
    if (node->name != "Model") continue;
    FbxModel m;
    m.id = object_id(*node);
    read_model_properties(*node, templ, m);
    for (auto [it, end] = objects.by_child.equal_range(m.id); it != end; ++it) {
      const Connection& c = objects.connections[it->second];
      const auto parent = objects.by_id.find(c.parent);
      if (c.property.empty() && parent != objects.by_id.end() && parent->second->name == "Model") m.parent = c.parent;
    }
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace rotinterp::fbx
