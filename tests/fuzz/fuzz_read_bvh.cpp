// Fuzz target (1): bytes as a .bvh file through the full reader (assimp, our
// header and layout pass, validation).
#include "read_bytes.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  read_bytes_as(data, size, ".bvh");
  return 0;
}
