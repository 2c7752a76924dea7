// The process-wide allocator setting of the programs that run batches (the CLI,
// bench_eval); a library call never changes it.
#pragma once

namespace rotinterp::cli {

// Tells glibc's allocator to keep freed memory for reuse (no trimming of the heap
// below 512 MB, no mmap for blocks under 32 MB): the batch allocates and frees
// per-clip buffers of megabytes over and over, and returning them to the kernel
// each time cost 13 % of `eval`'s CPU time in page faults (perf, three CMU/assimp
// BVH clips). Process-wide: for a program that runs batches (the CLI, bench_eval),
// not for a library user's process.
void keep_freed_memory_for_reuse();

}  // namespace rotinterp::cli
