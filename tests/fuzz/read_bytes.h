// Shared by the reader fuzz targets: write the bytes to a temporary file with the
// given extension and read it through rotinterp::read_clip (assimp in the
// importer process) and in this process. The reader must give a valid clip or an error, the same both
// ways — never crash, leak or hang.
#pragma once

#include "rotinterp/io/process/importer.h"  // src/io: the importer's in-process reading
#include "rotinterp/io/read.h"
#include "rotinterp/io/process/process_errors.h"

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
  // A non-BVH file is read in the importer process, out of the fuzzer's sight.
  // Unless assimp crashed there, read it again in this process, so that our own
  // clip building runs under the sanitizers too; both readings must agree.
  if (clip.ok() || clip.error_kind() != rotinterp::process_error::crashed) {
    const rotinterp::ReadOutcome again = rotinterp::detail::read_in_this_process(path, {});
    if (again.error.has_value() == clip.ok()) __builtin_trap();
    if (again.error && (*again.error != clip.error() || again.kind != clip.error_kind())) __builtin_trap();
    if (!again.error && (again.info.clip.rotations.size() != clip->rotations.size() || !again.info.clip.validate().ok()))
      __builtin_trap();
  }
  std::filesystem::remove(path);
}
