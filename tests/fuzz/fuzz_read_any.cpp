// Fuzz target (2): any bytes through assimp and our reader, the file extension
// chosen by the first byte so that every importer we rely on is reached.
#include "read_bytes.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const char* const kExtensions[] = {".bvh", ".fbx", ".gltf", ".glb", ".dae", ".obj", ".x", ".ply"};
  if (size < 1) return 0;
  read_bytes_as(data + 1, size - 1, kExtensions[data[0] % 8]);
  return 0;
}
