// The wire format's bytes (clip_wire.cpp): a Writer that appends fixed-size
// integers, raw doubles and counted strings, and a Reader that reads them back with
// every read bounds-checked. Private to src/io.
#pragma once

#include "rotinterp/core/rotation.h"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace rotinterp::wire {

class Writer {
 public:
  void u8(std::uint8_t v) { bytes_.push_back(static_cast<char>(v)); }
  void u64(std::uint64_t v) { raw(&v, sizeof v); }
  void i64(std::int64_t v) { raw(&v, sizeof v); }
  void f64(double v) { raw(&v, sizeof v); }
  void str(std::string_view s) {
    u64(s.size());
    bytes_.append(s);
  }
  void vec3(const Vec3& v) {
    for (int i = 0; i < 3; ++i) f64(v[i]);
  }
  void quat(const Quat& q) {
    f64(q.w());
    f64(q.x());
    f64(q.y());
    f64(q.z());
  }
  void raw(const void* p, std::size_t n) { bytes_.append(static_cast<const char*>(p), n); }
  // A vector of plain values, bit for bit: its count, then its bytes.
  template <class T>
  void values(const std::vector<T>& v) {
    u64(v.size());
    raw(v.data(), v.size() * sizeof(T));
  }
  std::string take() { return std::move(bytes_); }

 private:
  std::string bytes_;
};

// Every read is bounds-checked. After the first failure nothing more is read and
// every value is 0, so the decoding loops end at once.
class Reader {
 public:
  explicit Reader(std::string_view bytes) : bytes_(bytes) {}
  bool failed() const { return failed_; }
  bool at_end() const { return at_ == bytes_.size(); }
  void fail() {
    failed_ = true;
    at_ = bytes_.size();
  }

  std::uint8_t u8() {
    std::uint8_t v = 0;
    raw(&v, sizeof v);
    return v;
  }
  std::uint64_t u64() {
    std::uint64_t v = 0;
    raw(&v, sizeof v);
    return v;
  }
  std::int64_t i64() {
    std::int64_t v = 0;
    raw(&v, sizeof v);
    return v;
  }
  // An enumerator of at most `last`.
  template <class E>
  E enumerator(E last) {
    const std::uint8_t v = u8();
    if (v > static_cast<std::uint8_t>(last)) fail();
    return failed_ ? E{} : static_cast<E>(v);
  }
  double f64() {
    double v = 0.0;
    raw(&v, sizeof v);
    return v;
  }
  bool flag() {
    const std::uint8_t v = u8();
    if (v > 1) fail();
    return v == 1;
  }
  std::size_t size() {
    const std::uint64_t v = u64();
    if constexpr (sizeof(std::size_t) < sizeof v)
      if (v > std::numeric_limits<std::size_t>::max()) fail();
    return failed_ ? 0 : static_cast<std::size_t>(v);
  }
  int index() {
    std::int64_t v = 0;
    raw(&v, sizeof v);
    if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max()) fail();
    return failed_ ? 0 : static_cast<int>(v);
  }
  // A count of items of at least `min_bytes` each. Never trusted: more items than
  // the bytes left can hold is garbage, not a reason to allocate.
  std::size_t count(std::size_t min_bytes) {
    const std::uint64_t n = u64();
    if (n > (bytes_.size() - at_) / min_bytes) fail();
    return failed_ ? 0 : static_cast<std::size_t>(n);
  }
  std::string str() {
    const std::size_t n = count(1);
    std::string s(bytes_.substr(at_, n));
    at_ += n;
    return s;
  }
  Vec3 vec3() {
    Vec3 v;
    for (int i = 0; i < 3; ++i) v[i] = f64();
    return v;
  }
  template <class T>
  void values(std::vector<T>& v) {
    v.resize(count(sizeof(T)));
    if (!v.empty()) raw(v.data(), v.size() * sizeof(T));
  }
  Quat quat() {
    const double w = f64();
    const double x = f64();
    const double y = f64();
    const double z = f64();
    return Quat(w, x, y, z);
  }

 private:
  void raw(void* p, std::size_t n) {
    if (failed_ || bytes_.size() - at_ < n) return fail();
    std::memcpy(p, bytes_.data() + at_, n);
    at_ += n;
  }

  std::string_view bytes_;
  std::size_t at_ = 0;
  bool failed_ = false;
};

}  // namespace rotinterp::wire
