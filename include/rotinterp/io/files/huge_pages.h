// Large buffers that are filled once, front to back, asking for 2 MB pages (private to src/io).
#pragma once

#include <cstddef>
#include <cstdint>

#include <sys/mman.h>

namespace rotinterp {

// A file's text, its parsed table and a clip's key arrays are tens of MB touched
// once each. On the project's VM every first touch of a 4 KB page costs about 8 µs
// in the kernel: a third of the CPU time of resampling a 90 MB BVH went to page
// faults (perf). With transparent huge pages in "madvise" mode (Debian's default),
// this asks for 2 MB pages over the buffer's aligned interior, before it is
// touched; elsewhere it changes nothing. Buffers under 2 MB are left alone.
inline void advise_huge_pages(const void* data, std::size_t bytes) {
#ifdef MADV_HUGEPAGE
  constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
  if (bytes < kHuge) return;
  const auto first = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t begin = (first + kHuge - 1) & ~(kHuge - 1);
  const std::uintptr_t end = (first + bytes) & ~(kHuge - 1);
  if (end > begin) (void)::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)data;
  (void)bytes;
#endif
}

}  // namespace rotinterp
