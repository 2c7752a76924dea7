// Fuzz target (5): any bytes through our own glTF/GLB reader — the GLB container, the
// JSON, buffers (data: URIs; files only beside a folder that does not exist), every
// accessor and sampler, and the key checks of io/files/key_checks.h — then each
// sampler evaluated across its keys and beyond. It must give animations or one error
// line: never crash, read past a buffer, hang or give a non-finite value.
#include "rotinterp/io/gltf/gltf_source.h"

#include <cmath>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  auto read = rotinterp::parse_gltf_animations(bytes, "/nonexistent-fuzz-folder", "fuzz.gltf");
  if (!read.ok()) {
    if (read.error().find('\n') != std::string::npos) __builtin_trap();
    return 0;
  }
  for (const rotinterp::GltfAnimation& a : read->animations)
    for (const rotinterp::GltfSampler& s : a.samplers) {
      const double first = s.times.front(), last = s.times.back();
      for (int k = -2; k <= 10; ++k) {
        const double t = first + (last - first) * k / 8.0;
        if (s.width == 4 && !rotinterp::gltf_rotation_at(s, t).coeffs().allFinite()) __builtin_trap();
        if (s.width == 3 && !rotinterp::gltf_vector_at(s, t).allFinite()) __builtin_trap();
      }
    }
  return 0;
}
