// Progress reporting for long work (batches, renders). Libraries call it; the CLI
// decides whether anything is shown (stderr a terminal, no --quiet).
#pragma once

#include <cstddef>
#include <functional>

namespace rotinterp {

// Called with (units done, units in all); may be called from worker threads, and
// must be cheap. An empty function reports nothing.
using ProgressFn = std::function<void(std::size_t done, std::size_t total)>;

}  // namespace rotinterp
