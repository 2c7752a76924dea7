// An Assimp::IOSystem whose streams check every write, the flush, the fsync and
// the close: assimp's exporters ignore what a write returns, so a full disk would
// otherwise give a truncated file and success. The first failure is kept and read
// back with error() once the export is done.
#pragma once

#include <assimp/IOSystem.hpp>

#include <memory>
#include <mutex>
#include <string>

namespace rotinterp {

class CheckedIOSystem : public Assimp::IOSystem {
 public:
  // Errors name `label` (the file the user asked for, not a temporary).
  explicit CheckedIOSystem(std::string label);
  bool Exists(const char* file) const override;
  char getOsSeparator() const override { return '/'; }
  Assimp::IOStream* Open(const char* file, const char* mode) override;
  void Close(Assimp::IOStream* stream) override;

  // The first failed operation on any stream opened here ("LABEL: cannot write: …"),
  // empty when all succeeded. Streams report when they are closed (or deleted).
  std::string error() const;

  // Shared with the streams, which may outlive a call into this object.
  struct Errors {
    std::mutex mutex;
    std::string first;
    void add(const std::string& message);
  };

 private:
  std::string label_;
  std::shared_ptr<Errors> errors_;
};

}  // namespace rotinterp
