// The readers' size checks (io/files/limits.h).
#include "rotinterp/io/files/limits.h"
#include "rotinterp/io/files/file_errors.h"

#include <limits>

namespace rotinterp {

Status check_declared_count(std::uint64_t count, std::uint64_t element_bytes, std::uint64_t bytes_left,
                            std::uint64_t max_count, const std::string& where) {
  if (element_bytes == 0) element_bytes = 1;
  if (count > max_count)
    return make_error(where + ": " + std::to_string(count) + " elements, more than the " + std::to_string(max_count) +
                          " rotinterp reads",
                      file_error::unreadable);
  if (count > bytes_left / element_bytes)
    return make_error(where + ": " + std::to_string(count) + " elements of " + std::to_string(element_bytes) +
                          " bytes cannot fit in the " + std::to_string(bytes_left) + " bytes left",
                      file_error::unreadable);
  return Ok{};
}

InflationBudget::InflationBudget(std::uint64_t file_bytes) {
  const std::uint64_t most = std::numeric_limits<std::uint64_t>::max();
  const std::uint64_t scaled =
      file_bytes > (most - kInflationFloorBytes) / kInflationPerFileByte ? most : file_bytes * kInflationPerFileByte;
  limit_ = left_ = scaled > most - kInflationFloorBytes ? most : scaled + kInflationFloorBytes;
}

Status InflationBudget::take(std::uint64_t bytes, const std::string& where) {
  if (bytes > left_)
    return make_error(where + ": the file's compressed arrays would inflate past " + std::to_string(limit_ >> 20) +
                          " MiB, more than a file of its size holds (a zlib bomb?)",
                      file_error::unreadable);
  left_ -= bytes;
  return Ok{};
}

}  // namespace rotinterp
