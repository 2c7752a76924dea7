// Atomic writes: temporary file, checked writes, fsync, rename.
#include "rotinterp/io/files/atomic_file.h"

#include "cleanup_list.h"
#include "temp_names.h"
#include "rotinterp/io/files/output_dirs.h"
#include "rotinterp/io/files/file_errors.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ostream>
#include <streambuf>
#include <string>
#include <utility>

namespace rotinterp {

namespace {

namespace fs = std::filesystem;

// Every error here is about an output (its folder, its file, its lock): a caller names
// the output, not its input, in front of it.
Error write_error(std::string message) { return make_error(std::move(message), file_error::cannot_write); }

// The test seam (see the header): the Nth checked operation fails with ENOSPC.
bool injected_fault() {
  static const long fault_at = [] {
    const char* v = std::getenv("ROTINTERP_TEST_FAULT_AT");
    return v ? std::atol(v) : 0L;
  }();
  static std::atomic<long> count{0};
  if (fault_at <= 0) return false;
  if (count.fetch_add(1) + 1 != fault_at) return false;
  errno = ENOSPC;
  return true;
}

std::string reason(int err) { return std::strerror(err); }

}  // namespace

Status checked_write(int fd, const void* data, std::size_t size, const std::string& label) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    if (injected_fault()) return write_error(label + ": cannot write: " + reason(errno));
    const ssize_t n = ::write(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    // 0 bytes written for a non-empty request: no progress is possible.
    if (n <= 0) return write_error(label + ": cannot write: " + reason(n == 0 ? ENOSPC : errno));
    p += n;
    size -= static_cast<std::size_t>(n);
  }
  return Ok{};
}

Status checked_close(int fd, bool sync, const std::string& label) {
  std::string error;
  if (sync && (injected_fault() || ::fsync(fd) != 0)) error = label + ": cannot write (sync failed): " + reason(errno);
  // close() reports deferred write errors (NFS); EINTR still closes on Linux.
  const bool fault = injected_fault();
  if ((::close(fd) != 0 && errno != EINTR) || fault)
    if (error.empty()) error = label + ": cannot write (close failed): " + reason(fault ? ENOSPC : errno);
  if (!error.empty()) return write_error(error);
  return Ok{};
}

AtomicOutput::AtomicOutput(fs::path target, TempKind kind) : target_(std::move(target)) {
  if (Status s = check_not_an_input(target_); !s) {
    error_ = s.error();
    return;
  }
  if (Status made = create_output_directories(target_.parent_path()); !made) {
    error_ = made.error();
    return;
  }
  remove_stale_temporaries(target_.parent_path());
  const std::string dir = target_.parent_path().empty() ? std::string(".") : target_.parent_path().string();
  int err = 0;
  if (kind == TempKind::unnamed) {
    fd_ = ::open(dir.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0666);
    // Filesystems without O_TMPFILE say EOPNOTSUPP (or EISDIR/EINVAL on old kernels).
    if (fd_ < 0 && errno != EOPNOTSUPP && errno != EISDIR && errno != EINVAL) err = errno;
  }
  if (fd_ < 0 && err == 0) {  // new files get 0666 & ~umask, like any new file
    temp_ = claim_temp_name(target_, slot_, err, [&](const fs::path& name) {
      fd_ = ::open(name.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
      return fd_ >= 0;
    });
  }
  if (fd_ < 0) error_ = target_.string() + ": cannot write: " + reason(err);
}

AtomicOutput::~AtomicOutput() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_ && !temp_.empty()) ::unlink(temp_.c_str());
  cleanup::drop(slot_);
}

Status AtomicOutput::status() const {
  if (!error_.empty()) return write_error(error_);
  return Ok{};
}

Status AtomicOutput::write(const void* data, std::size_t size) {
  if (!error_.empty()) return write_error(error_);
  if (finished_) return write_error(target_.string() + ": written after it was finished");
  Status s = checked_write(fd_, data, size, target_.string());
  if (!s) error_ = s.error();
  return s;
}

Status AtomicOutput::finish() {
  if (!error_.empty()) return write_error(error_);
  if (finished_) return Ok{};
  const std::string label = target_.string();
  auto failed = [&](const std::string& message) -> Status {
    error_ = message;
    return write_error(message);
  };
  // The replaced file's owner and mode (owner first: chown clears set-id bits).
  struct stat old {};
  if (::stat(target_.c_str(), &old) == 0 && S_ISREG(old.st_mode)) {
    struct stat now {};
    // Not root: at least the group, if we are in it; else the mode alone is kept.
    if (::fstat(fd_, &now) == 0 && (now.st_uid != old.st_uid || now.st_gid != old.st_gid) &&
        ::fchown(fd_, old.st_uid, old.st_gid) != 0)
      (void)!::fchown(fd_, static_cast<uid_t>(-1), old.st_gid);
    if (::fchmod(fd_, old.st_mode & 07777) != 0) return failed(label + ": cannot keep its permissions: " + reason(errno));
  }
  if (injected_fault() || ::fsync(fd_) != 0) return failed(label + ": cannot write (sync failed): " + reason(errno));
  finished_ = true;
  return Ok{};
}

Status AtomicOutput::commit() {
  if (committed_) return Ok{};
  if (Status s = finish(); !s) return s;
  if (Status s = check_not_an_input(target_); !s) return s;
  const std::string label = target_.string();
  if (temp_.empty()) {
    // Unnamed: give it a short-lived name (a plain link cannot replace a file), then
    // rename that over the target.
    char proc[64];
    std::snprintf(proc, sizeof proc, "/proc/self/fd/%d", fd_);
    int err = 0;
    temp_ = claim_temp_name(target_, slot_, err, [&](const fs::path& name) {
      return ::linkat(AT_FDCWD, proc, AT_FDCWD, name.c_str(), AT_SYMLINK_FOLLOW) == 0;
    });
    if (temp_.empty()) return write_error(label + ": cannot write: " + reason(err));
  }
  if (::rename(temp_.c_str(), target_.c_str()) != 0) return write_error(label + ": cannot write: " + reason(errno));
  committed_ = true;
  cleanup::drop(slot_);  // the name is the target's now: not for the interrupt handler to remove
  slot_ = -1;
  // The rename itself reaches the disk with the directory.
  const std::string dir = target_.parent_path().empty() ? std::string(".") : target_.parent_path().string();
  const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
  return Ok{};
}

Status commit_together(const std::vector<AtomicOutput*>& outputs) {
  for (AtomicOutput* o : outputs)
    if (Status s = o->finish(); !s) return s;
  sigset_t block, old;
  sigemptyset(&block);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&block, sig);
  pthread_sigmask(SIG_BLOCK, &block, &old);
  Status result = Ok{};
  for (AtomicOutput* o : outputs)
    if (Status s = o->commit(); !s) {
      result = s;
      break;
    }
  pthread_sigmask(SIG_SETMASK, &old, nullptr);
  return result;
}

namespace {

// A stream buffer over AtomicOutput::write; a failed write makes the stream bad.
class AtomicStreamBuf : public std::streambuf {
 public:
  explicit AtomicStreamBuf(AtomicOutput& out) : out_(out), buffer_(kSize) { setp(buffer_.data(), buffer_.data() + kSize); }

 protected:
  int_type overflow(int_type ch) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(ch, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(ch);
      pbump(1);
    }
    return traits_type::not_eof(ch);
  }
  int sync() override { return drain() ? 0 : -1; }

 private:
  static constexpr std::size_t kSize = 1 << 16;
  bool drain() {
    const std::size_t n = static_cast<std::size_t>(pptr() - pbase());
    setp(buffer_.data(), buffer_.data() + kSize);
    return n == 0 || out_.write(buffer_.data(), n).ok();
  }
  AtomicOutput& out_;
  std::vector<char> buffer_;
};

}  // namespace

Status write_to(AtomicOutput& out, const std::function<Status(std::ostream&)>& write) {
  if (Status s = out.status(); !s) return s;
  AtomicStreamBuf buf(out);
  std::ostream os(&buf);
  if (Status s = write(os); !s) return s;
  os.flush();
  if (Status s = out.status(); !s) return s;
  if (!os) return write_error(out.target().string() + ": cannot write");
  return out.finish();
}

Status write_file_atomically(const fs::path& target, const std::function<Status(std::ostream&)>& write) {
  AtomicOutput out(target, TempKind::unnamed);
  if (Status s = write_to(out, write); !s) return s;
  return out.commit();
}

}  // namespace rotinterp
