// One take in our FBX writer (private to src/io): its AnimationStack and
// AnimationLayer, its curve nodes and curves, their connections and its Takes entry.
// fbx_write.cpp writes the skeleton once and these once per take, in take order.
#pragma once

#include "fbx_write_document.h"

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace rotinterp {

// The object ids of one take, drawn from the writer's counter in file order: stack,
// layer, then per joint its "R" node and curves, its "T" and "S" nodes and curves (0: none).
struct FbxTakeIds {
  std::int64_t stack = 0, layer = 0;
  std::vector<std::int64_t> rotation_node, translation_node, scaling_node;
  std::vector<std::array<std::int64_t, 3>> rotation_curve, translation_curve, scaling_curve;
  std::size_t curve_nodes = 0, curves = 0;
};
FbxTakeIds new_take_ids(const std::vector<FbxOutJoint>& curves, const std::function<std::int64_t()>& new_id);

// The first to last key tick over all of a take's curves ({0, 0} without keys).
FbxTickSpan fbx_curves_span(const std::vector<FbxOutJoint>& curves);

// Objects: the stack (LocalStart/Stop and ReferenceStart/Stop = `span`), its layer,
// the curve nodes, the curves.
void write_take_objects(FbxWriteDocument& doc, const FbxOutTake& take, const FbxTakeIds& ids, FbxTickSpan span);
// Connections: layer → stack, curve nodes → layer and to their model's property,
// curves → their curve node.
void write_take_connections(FbxWriteDocument& doc, const FbxOutTake& take, const FbxTakeIds& ids,
                            const std::vector<std::int64_t>& model_id);
// The take's entry under Takes (LocalTime and ReferenceTime = `span`).
void write_take_entry(FbxWriteDocument& doc, const std::string& name, FbxTickSpan span);

}  // namespace rotinterp
