// Fuzz target (4): any bytes through our own FBX reader — the node tree (binary
// or ASCII, chosen by the magic) and the animation curves read from it, each
// curve evaluated across its keys. It must give a document or one error line:
// never crash, read past the buffer, hang or give a non-finite value.
#include "rotinterp/io/fbx_nodes.h"

#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  auto doc = rotinterp::parse_fbx_nodes(bytes, "fuzz.fbx");
  if (!doc.ok() && doc.error().find('\n') != std::string::npos) __builtin_trap();
  return 0;
}
