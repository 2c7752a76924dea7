// Shared by the reader fuzz targets: write the bytes to a temporary file with the
// given extension and read it through rotinterp::read_clip. The reader must give
// a valid clip or an error — never crash, leak or hang.
#pragma once

#include "rotinterp/io/read.h"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

inline void read_bytes_as(const std::uint8_t* data, std::size_t size, const char* extension) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("rotinterp_fuzz_" + std::to_string(::getpid()) + extension);
  if (FILE* f = std::fopen(path.c_str(), "wb")) {
    std::fwrite(data, 1, size, f);
    std::fclose(f);
  }
  auto clip = rotinterp::read_clip(path);
  if (clip.ok() && !clip->validate().ok()) __builtin_trap();  // the reader promises a valid clip
  std::filesystem::remove(path);
}
