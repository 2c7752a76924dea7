// glibc's allocator told to keep freed memory for reuse.
#include "allocator.h"

#include <malloc.h>

namespace rotinterp::cli {

void keep_freed_memory_for_reuse() {
  mallopt(M_MMAP_THRESHOLD, 32 << 20);  // glibc's largest allowed value on 64-bit
  mallopt(M_TRIM_THRESHOLD, 512 << 20);
  mallopt(M_TOP_PAD, 16 << 20);
}

}  // namespace rotinterp::cli
