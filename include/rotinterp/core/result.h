// Result<T>: a value or a one-line error message. Library functions return it;
// only the CLI turns an error into a message on stderr and an exit code.
#pragma once

#include <cassert>
#include <string>
#include <utility>
#include <variant>

namespace rotinterp {

struct Error {
  std::string message;  // one line, no trailing newline; names the file/joint/frame where known
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

 private:
  std::variant<T, Error> v_;
};

// Status: a Result with no value.
struct Ok {};
using Status = Result<Ok>;

inline Error make_error(std::string message) { return Error{std::move(message)}; }

}  // namespace rotinterp

// Internal bugs (never bad input) use this one assert macro.
#define ROTINTERP_ASSERT(cond) assert(cond)
