// Result<T>: a value or a one-line error message. Library functions return it;
// only the CLI turns an error into a message on stderr and an exit code.
#pragma once

#include <cassert>
#include <string>
#include <utility>
#include <variant>

namespace rotinterp {

// What kind of failure an error is, for callers that act on it (a batch skips a
// file without an animation and goes on after a crash). Most errors are `other`.
enum class ErrorKind {
  other,
  unreadable,    // input that is not what it should be: empty, malformed, or refused
  no_animation,  // readable input that holds no animation (a mesh)
  crashed,       // a helper process died on the input
  too_large,     // a result passed the size limit its caller set
  timed_out,     // work ran past the deadline its caller set
  no_file,       // nothing at the path: missing, a link to nothing, a loop of links
  directory,     // the path is a directory
  cannot_open,   // the system refuses to read it: permissions, not a regular file, I/O
  out_of_memory, // the work needed more memory than the process may have
  cannot_write,  // an output could not be made (its folder, its file, its lock): the message names it
  last = cannot_write,
};

struct Error {
  std::string message;  // one line, no trailing newline; names the file/joint/frame where known
  ErrorKind kind = ErrorKind::other;
};

template <class T>
class [[nodiscard]] Result {
 public:
  Result(T value) : v_(std::move(value)) {}      // NOLINT: implicit on purpose
  Result(Error error) : v_(std::move(error)) {}  // NOLINT: implicit on purpose

  bool ok() const { return std::holds_alternative<T>(v_); }
  explicit operator bool() const { return ok(); }

  const T& value() const& { assert(ok()); return std::get<T>(v_); }
  T& value() & { assert(ok()); return std::get<T>(v_); }
  T&& value() && { assert(ok()); return std::get<T>(std::move(v_)); }
  const T& operator*() const& { return value(); }
  T& operator*() & { return value(); }
  const T* operator->() const { return &value(); }
  T* operator->() { return &value(); }

  const std::string& error() const { assert(!ok()); return std::get<Error>(v_).message; }
  ErrorKind error_kind() const { assert(!ok()); return std::get<Error>(v_).kind; }
  // The error itself (message and kind), to pass on as another Result's: the one way
  // an error is passed on, so that its kind survives (`return r.failure();`).
  const Error& failure() const { assert(!ok()); return std::get<Error>(v_); }
  // The same, with `context` before its message ("joint 'Hips': " + message).
  Error failure(const std::string& context) const { return Error{context + failure().message, failure().kind}; }

 private:
  std::variant<T, Error> v_;
};

// Status: a Result with no value.
struct Ok {};
using Status = Result<Ok>;

inline Error make_error(std::string message, ErrorKind kind = ErrorKind::other) { return Error{std::move(message), kind}; }

}  // namespace rotinterp

// Internal bugs (never bad input) use this one assert macro.
#define ROTINTERP_ASSERT(cond) assert(cond)
