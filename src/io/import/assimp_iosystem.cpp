// The assimp IOSystem whose streams check every write, flush, fsync and close.
#include "assimp_iosystem.h"

#include "rotinterp/io/files/atomic_file.h"

#include <assimp/IOStream.hpp>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <vector>

namespace rotinterp {

namespace {

// A file read or written through a file descriptor. Writes are buffered (the
// exporters write many small pieces) and every one of them checked.
class CheckedStream : public Assimp::IOStream {
 public:
  CheckedStream(int fd, bool writing, std::string label, std::shared_ptr<CheckedIOSystem::Errors> errors)
      : fd_(fd), writing_(writing), path_(std::move(label)), errors_(std::move(errors)) {}

  ~CheckedStream() override {
    drain();
    if (Status s = checked_close(fd_, writing_ && failed_.empty(), path_); !s && writing_) fail(s.error());
  }

  size_t Read(void* buffer, size_t size, size_t count) override {
    if (writing_ || size == 0) return 0;
    std::size_t done = 0, want = size * count;
    auto* p = static_cast<char*>(buffer);
    while (done < want) {
      const ssize_t n = ::read(fd_, p + done, want - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      done += static_cast<std::size_t>(n);
    }
    pos_ += done;
    return done / size;
  }

  size_t Write(const void* data, size_t size, size_t count) override {
    if (!writing_ || !failed_.empty()) return 0;
    const std::size_t bytes = size * count;
    const auto* p = static_cast<const char*>(data);
    if (buffer_.size() + bytes > kBufferSize && !drain()) return 0;
    if (bytes >= kBufferSize) {
      if (Status s = checked_write(fd_, p, bytes, path_); !s) return fail(s.error()), 0;
    } else {
      buffer_.insert(buffer_.end(), p, p + bytes);
    }
    pos_ += bytes;
    return count;
  }

  aiReturn Seek(size_t offset, aiOrigin origin) override {
    if (!drain()) return aiReturn_FAILURE;
    const int whence = origin == aiOrigin_SET ? SEEK_SET : origin == aiOrigin_CUR ? SEEK_CUR : SEEK_END;
    // aiOrigin_END takes a negative offset passed as size_t.
    const off_t at = ::lseek(fd_, static_cast<off_t>(offset), whence);
    if (at < 0) return aiReturn_FAILURE;
    pos_ = static_cast<std::size_t>(at);
    return aiReturn_SUCCESS;
  }

  size_t Tell() const override { return pos_; }

  size_t FileSize() const override {
    struct stat st {};
    const std::size_t on_disk = ::fstat(fd_, &st) == 0 ? static_cast<std::size_t>(st.st_size) : 0;
    return std::max(on_disk, pos_);
  }

  void Flush() override { drain(); }

 private:
  static constexpr std::size_t kBufferSize = 1 << 16;

  bool drain() {
    if (!failed_.empty()) return false;
    if (buffer_.empty()) return true;
    Status s = checked_write(fd_, buffer_.data(), buffer_.size(), path_);
    buffer_.clear();
    if (!s) fail(s.error());
    return s.ok();
  }
  void fail(const std::string& message) {
    if (failed_.empty()) failed_ = message;
    errors_->add(message);
  }

  int fd_;
  bool writing_;
  std::string path_;  // the label errors name
  std::shared_ptr<CheckedIOSystem::Errors> errors_;
  std::vector<char> buffer_;
  std::size_t pos_ = 0;
  std::string failed_;
};

}  // namespace

void CheckedIOSystem::Errors::add(const std::string& message) {
  std::lock_guard<std::mutex> lock(mutex);
  if (first.empty()) first = message;
}

CheckedIOSystem::CheckedIOSystem(std::string label) : label_(std::move(label)), errors_(std::make_shared<Errors>()) {}

bool CheckedIOSystem::Exists(const char* file) const { return ::access(file, F_OK) == 0; }

Assimp::IOStream* CheckedIOSystem::Open(const char* file, const char* mode) {
  const bool writing = std::strchr(mode, 'w') != nullptr || std::strchr(mode, 'a') != nullptr;
  const int flags = writing ? O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC : O_RDONLY | O_CLOEXEC;
  const int fd = ::open(file, flags, 0666);
  if (fd < 0) {
    if (writing) errors_->add(label_ + ": cannot write: " + std::strerror(errno));
    return nullptr;
  }
  return new CheckedStream(fd, writing, label_, errors_);
}

void CheckedIOSystem::Close(Assimp::IOStream* stream) { delete stream; }

std::string CheckedIOSystem::error() const {
  std::lock_guard<std::mutex> lock(errors_->mutex);
  return errors_->first;
}

}  // namespace rotinterp
