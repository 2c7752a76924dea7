// A character's body on the wire (body_wire.h).
#include "body_wire.h"

namespace rotinterp::wire {

namespace {

constexpr std::size_t kCount = 8, kMatrix = 16 * 8;

void put(Writer& w, const RowMajor4& m) {
  for (double x : m) w.f64(x);
}
void get(Reader& r, RowMajor4& m) {
  for (double& x : m) x = r.f64();
}

}  // namespace

void put(Writer& w, const CharacterBody& body) {
  w.u64(body.meshes.size());
  for (const BodyMesh& mesh : body.meshes) {
    w.str(mesh.name);
    put(w, mesh.world);
    w.str(mesh.parent_joint);
    w.u64(mesh.parts.size());
    for (const BodyPart& part : mesh.parts) {
      for (const auto* v : {&part.positions, &part.normals, &part.uvs, &part.colours}) w.values(*v);
      w.values(part.triangles);
      w.i64(part.material);
      w.u64(part.bones.size());
      for (const BodyBone& bone : part.bones) {
        w.str(bone.joint);
        put(w, bone.mesh_to_world);
        w.values(bone.vertices);
        w.values(bone.weights);
      }
    }
  }
  w.u64(body.materials.size());
  for (const BodyMaterial& m : body.materials) {
    w.str(m.name);
    for (double c : m.base_colour) w.f64(c);
    w.i64(m.image);
  }
  w.u64(body.images.size());
  for (const BodyImage& image : body.images) {
    w.str(image.name);
    w.str(image.mime_type);
    w.str(image.bytes);
  }
  w.u64(body.notes.size());
  for (const std::string& note : body.notes) w.str(note);
}

void get(Reader& r, CharacterBody& body) {
  body.meshes.resize(r.count(kCount + kMatrix + kCount + kCount));
  for (BodyMesh& mesh : body.meshes) {
    mesh.name = r.str();
    get(r, mesh.world);
    mesh.parent_joint = r.str();
    mesh.parts.resize(r.count(5 * kCount + 8 + kCount));
    for (BodyPart& part : mesh.parts) {
      for (auto* v : {&part.positions, &part.normals, &part.uvs, &part.colours}) r.values(*v);
      r.values(part.triangles);
      part.material = r.index();
      part.bones.resize(r.count(kCount + kMatrix + 2 * kCount));
      for (BodyBone& bone : part.bones) {
        bone.joint = r.str();
        get(r, bone.mesh_to_world);
        r.values(bone.vertices);
        r.values(bone.weights);
      }
    }
  }
  body.materials.resize(r.count(kCount + 4 * 8 + 8));
  for (BodyMaterial& m : body.materials) {
    m.name = r.str();
    for (double& c : m.base_colour) c = r.f64();
    m.image = r.index();
  }
  body.images.resize(r.count(3 * kCount));
  for (BodyImage& image : body.images) {
    image.name = r.str();
    image.mime_type = r.str();
    image.bytes = r.str();
  }
  body.notes.resize(r.count(kCount));
  for (std::string& note : body.notes) note = r.str();
}

}  // namespace rotinterp::wire
