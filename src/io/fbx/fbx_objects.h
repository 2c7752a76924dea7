// FBX 7.x objects and their connections (private to src/io): the id → object map,
// the connection lists, object names as either encoding spells them, and
// Properties70 look-ups — what fbx_curves.cpp and fbx_models.cpp share.
#pragma once

#include "rotinterp/io/fbx/fbx_curves.h"
#include "rotinterp/io/fbx/fbx_nodes.h"

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rotinterp::fbx {

struct Connection {
  std::int64_t child = 0, parent = 0;
  std::string property;  // "" for object–object
};

struct Objects {
  std::map<std::int64_t, const FbxNode*> by_id;
  std::vector<const FbxNode*> in_order;  // as the file lists them
  std::vector<Connection> connections;   // as the file lists them
  std::multimap<std::int64_t, std::size_t> by_parent, by_child;  // → index in connections
};

// The objects and connections of a 7.x document (empty for a 6.1 one).
Objects index_objects(const FbxDocument& doc);

// An object node's id (its first property), 0 without one.
std::int64_t object_id(const FbxNode& node);
// "pCube1" from "Model::pCube1" (ASCII) or "pCube1\0\1Model" (binary).
std::string object_name(const FbxNode& node);
// "Mesh" from Model: …, "Model::pCube1", "Mesh": the string after the name, or "".
std::string object_subclass(const FbxNode& node);

// A Properties70 (or Properties60) entry's values, or nullptr: P: "name", "type",
// "label", "flags", values… (Property: "name", "type", "flags", values… in 6.1).
const FbxNode* find_property(const FbxNode& object, std::string_view name);
// Its value i as a number (properties after the header fields), or `fallback`.
double property_number(const FbxNode* p, std::size_t i, double fallback);
FbxVec3 property_vec3(const FbxNode* p, const FbxVec3& fallback);

// A Model node's name, subclass and transform properties (`templ`: the defaults
// of its type, or nullptr); id and parent are the caller's.
void read_model_properties(const FbxNode& node, const FbxNode* templ, FbxModel& m);
// Every Model object with its transform properties over the FbxNode template's
// defaults (Definitions), and its parent model.
std::vector<FbxModel> read_models(const FbxDocument& doc, const Objects& objects);

// A 6.1 document's models (Properties60, parents from Connect "OO" by name) and
// takes (fbx_takes.cpp).
Result<FbxAnimation> read_fbx_takes(const FbxDocument& doc, const std::string& label);

}  // namespace rotinterp::fbx
