// A character's body as a reader finds it (ReadOptions::read_body): its meshes,
// their skins and materials, and the images those use, for a writer that keeps the
// body in another format (an FBX character written as GLB). Plain data in the
// source's numbers: positions in its units, matrices row-major; what a target
// format cannot hold (a fifth weight on a vertex) is the writer's to drop and say.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace rotinterp {

using RowMajor4 = std::array<double, 16>;

// One bone of a mesh's skin: the joint (by the clip's name for it) and the mesh's
// world transform at bind time as that bone sees it (its node's world transform at
// rest times assimp's offset matrix), so the writer can place the bone's inverse
// bind matrix against its own joints. Weights are (vertex, weight) pairs as the
// source has them, unnormalized.
struct BodyBone {
  std::string joint;
  RowMajor4 mesh_to_world{};
  std::vector<std::uint32_t> vertices;
  std::vector<float> weights;
};

// One material's part of a mesh: triangles over its own vertices. A mesh node with
// several materials is one BodyMesh of several parts (as Blender shows it: one
// object, several materials).
struct BodyPart {
  std::vector<float> positions, normals, uvs, colours;  // xyz, xyz, uv (v up, as assimp), rgba; per vertex
  std::vector<std::uint32_t> triangles;                 // three indices per triangle
  int material = -1;                                    // index in CharacterBody::materials
  std::vector<BodyBone> bones;                          // empty: rigid (see BodyMesh::world)
};

struct BodyMesh {
  std::string name;
  RowMajor4 world{};  // the mesh node's world transform at rest
  // The nearest ancestor of the mesh node that is a joint ("": none), which moves a
  // rigid part; a rigid mesh with none stays where `world` puts it.
  std::string parent_joint;
  std::vector<BodyPart> parts;
};

struct BodyImage {
  std::string name;       // the source's file name or embedded texture name
  std::string mime_type;  // "image/png" or "image/jpeg"
  std::string bytes;
};

struct BodyMaterial {
  std::string name;
  std::array<double, 4> base_colour{1.0, 1.0, 1.0, 1.0};  // linear RGBA (diffuse × opacity)
  int image = -1;                                          // base-colour image, index in CharacterBody::images
};

struct CharacterBody {
  std::vector<BodyMesh> meshes;
  std::vector<BodyMaterial> materials;
  std::vector<BodyImage> images;
  // What the reader could not bring along ("texture 'x.png' not found beside the
  // file"), one line each, for the writer's summary.
  std::vector<std::string> notes;
};

}  // namespace rotinterp
