// The FBX writer's document (private to src/io): the encoder with the Properties70,
// leaf-node and connection helpers that fbx_write.cpp (skeleton, settings) and
// fbx_write_takes.cpp (stacks, layers, curves) both write with.
#pragma once

#include "fbx_encode.h"
#include "rotinterp/io/fbx/fbx_write.h"

#include <cstdint>
#include <string_view>

namespace rotinterp {

class FbxWriteDocument {
 public:
  explicit FbxWriteDocument(FbxEncoding e)
      : enc_(e == FbxEncoding::binary ? FbxEncoder::Format::binary : FbxEncoder::Format::ascii) {}
  FbxEncoder& enc() { return enc_; }

  // A Properties70 entry: P: name, type, label, flags, values… (values follow; then end()).
  FbxEncoder& p(std::string_view name, std::string_view type, std::string_view label, std::string_view flags) {
    enc_.begin("P");
    return enc_.str(name).str(type).str(label).str(flags);
  }
  void p_int(std::string_view name, std::string_view type, std::string_view label, std::int32_t v) {
    p(name, type, label, "").i32(v);
    enc_.end();
  }
  void p_double(std::string_view name, double v) {
    p(name, "double", "Number", "").f64(v);
    enc_.end();
  }
  void p_time(std::string_view name, std::int64_t ticks) {
    p(name, "KTime", "Time", "").i64(ticks);
    enc_.end();
  }
  void p_vec(std::string_view name, const Vec3& v) {
    p(name, name, "", "A").f64(v.x()).f64(v.y()).f64(v.z());
    enc_.end();
  }
  void leaf_i32(std::string_view name, std::int32_t v) {
    enc_.begin(name);
    enc_.i32(v);
    enc_.end();
  }
  void leaf_str(std::string_view name, std::string_view v) {
    enc_.begin(name);
    enc_.str(v);
    enc_.end();
  }
  // Binary files: the FileId and CreationTime top-level nodes, fixed (the FileId the
  // format notes give for this creation time, which the encoder's footer matches),
  // so that the same command writes the same bytes.
  void file_id() {
    static constexpr unsigned char kFileId[16] = {0x28, 0xb3, 0x2a, 0xeb, 0xb6, 0x24, 0xcc, 0xc2,
                                                  0xbf, 0xc8, 0xb0, 0x2a, 0xa9, 0x2b, 0xfc, 0xf1};
    enc_.begin("FileId");
    enc_.raw(std::string_view(reinterpret_cast<const char*>(kFileId), sizeof kFileId));
    enc_.end();
    leaf_str("CreationTime", "1970-01-01 10:00:00:000");
  }
  void connect(std::int64_t child, std::int64_t parent, std::string_view property = {}) {
    enc_.begin("C");
    enc_.str(property.empty() ? "OO" : "OP").i64(child).i64(parent);
    if (!property.empty()) enc_.str(property);
    enc_.end();
  }

 private:
  FbxEncoder enc_;
};

}  // namespace rotinterp
