// The importer process's failure kinds (import_process.cpp gives them): what
// happens to a reading because it runs in another process. The file kinds it also
// passes on are io/files/file_errors.h's; a code here is none of theirs (checked
// below, when this compiles), so that a kind sent and decoded is the kind given.
#pragma once

#include "rotinterp/core/result.h"
#include "rotinterp/io/files/file_errors.h"

#include <cstddef>
#include <cstdint>
#include <iterator>

namespace rotinterp::process_error {

inline constexpr ErrorKind crashed{16};    // the importer died on the input (a signal, a bad exit)
inline constexpr ErrorKind too_large{17};  // its reply passed ReadOptions::max_import_bytes
inline constexpr ErrorKind timed_out{18};  // it ran past ReadOptions::import_timeout_seconds

inline constexpr ErrorKind all[] = {crashed, too_large, timed_out};

namespace detail {
constexpr bool codes_distinct() {
  std::uint8_t codes[1 + std::size(file_error::all) + std::size(all)] = {};
  std::size_t n = 1;  // codes[0]: ErrorKind::other
  for (ErrorKind k : file_error::all) codes[n++] = static_cast<std::uint8_t>(k);
  for (ErrorKind k : all) codes[n++] = static_cast<std::uint8_t>(k);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if (codes[i] == codes[j]) return false;
  return true;
}
static_assert(codes_distinct(), "two error kinds share a code (here and io/files/file_errors.h)");
}  // namespace detail

}  // namespace rotinterp::process_error
