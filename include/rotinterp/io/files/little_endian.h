// Little-endian bytes for our binary writers (FBX, GLB); private to src/io.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>

namespace rotinterp {

// An unsigned integer, least significant byte first.
template <class U>
void put_le(std::string& out, U v) {
  for (std::size_t i = 0; i < sizeof(U); ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
}

// A float's or double's IEEE bits as an unsigned integer (for put_le).
template <class T>
auto bits(T v) {
  if constexpr (sizeof(T) == 8) {
    std::uint64_t u;
    std::memcpy(&u, &v, 8);
    return u;
  } else {
    std::uint32_t u;
    std::memcpy(&u, &v, 4);
    return u;
  }
}

}  // namespace rotinterp
