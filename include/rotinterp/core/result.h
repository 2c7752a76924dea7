// Result<T>: a value or a one-line error message. Library functions return it;
// only the CLI turns an error into a message on stderr and an exit code.
#pragma once

#include <cassert>
#include <cstdint>
#include <string>
#include <utility>
#include <variant>

namespace rotinterp {

// What kind of failure an error is, for callers that act on it (a batch skips a
// file without an animation and goes on after a crash). Open, like std::byte: core
// names only `other`, what most errors are; the layers that produce failures name
// their own kinds as constants of this type (io/files/file_errors.h,
// io/process/process_errors.h), so core knows no file or process.
enum class ErrorKind : std::uint8_t { other = 0 };

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
