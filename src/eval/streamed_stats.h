// Statistics over a stream of sample blocks with memory independent of their count
// (private to src/eval/): smoothness summed block by block, and two order statistics
// selected by radix on the values' bits.
#pragma once

#include "rotinterp/clip/metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

namespace rotinterp::detail {

// sampled_smoothness over a stream of blocks: each block's samples follow the
// two before it (kept in front of the next block), so every second difference is
// counted once. One block gives exactly sampled_smoothness of all samples.
struct SmoothnessSum {
  double sum_sq = 0.0, max = 0.0, first_rms = 0.0;
  std::size_t count = 0, blocks = 0;
  // q[0..n): the two carried samples first unless this is the first block.
  void add(const Quat* q, std::size_t n, double dt) {
    const Smoothness s = sampled_smoothness(q, n, dt);
    const std::size_t c = n >= 3 ? n - 2 : 0;
    sum_sq += s.acceleration_rms * s.acceleration_rms * static_cast<double>(c);
    max = std::max(max, s.acceleration_max);
    count += c;
    if (blocks++ == 0) first_rms = s.acceleration_rms;
  }
  double rms() const {
    if (blocks == 1) return first_rms;  // bit for bit what one call gives
    return count ? std::sqrt(sum_sq / static_cast<double>(count)) : 0.0;
  }
};

// The two order statistics of rank lo and lo + 1 (0-based) of the non-negative
// values `each_block` yields (it calls its argument with (values, n) per block, in
// any order, the same values on every call), with memory independent of their
// count: a radix selection on the values' bit patterns, which non-negative
// doubles order like the numbers; 16 bits per pass, then one pass collects the
// few values left with that prefix and the smallest value above them.
template <class EachBlock>
std::pair<double, double> select_two(const EachBlock& each_block, std::uint64_t lo) {
  constexpr std::size_t kCollect = 1 << 20;
  auto bits = [](double v) {
    std::uint64_t b = 0;
    v = std::isfinite(v) && v > 0.0 ? v : 0.0;  // as percentile() reads them
    std::memcpy(&b, &v, sizeof b);
    return b;
  };
  std::uint64_t prefix = 0, rank = lo, in_bucket = 0;
  int known = 0;  // leading bits fixed so far
  std::vector<std::uint64_t> count(1 << 16);
  while (known < 64) {
    std::fill(count.begin(), count.end(), 0);
    const int shift = 64 - known - 16;
    each_block([&](const double* v, std::size_t n) {
      for (std::size_t i = 0; i < n; ++i) {
        const std::uint64_t b = bits(v[i]);
        if (known == 0 || (b >> (64 - known)) == prefix) ++count[(b >> shift) & 0xFFFF];
      }
    });
    std::size_t d = 0;
    while (rank >= count[d]) rank -= count[d++];
    prefix = (prefix << 16) | d;
    known += 16;
    in_bucket = count[d];
    if (in_bucket <= kCollect) break;
  }
  std::vector<double> bucket;
  double above = INFINITY;
  each_block([&](const double* v, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint64_t b = bits(v[i]), top = b >> (64 - known);
      if (top == prefix && in_bucket <= kCollect) bucket.push_back(std::isfinite(v[i]) && v[i] > 0.0 ? v[i] : 0.0);
      else if (top > prefix) above = std::min(above, v[i]);
    }
  });
  if (in_bucket > kCollect) {  // all 64 bits fixed: every value in the bucket is the same
    double same = 0.0;
    std::memcpy(&same, &prefix, sizeof same);
    return {same, rank + 1 < in_bucket ? same : above};
  }
  std::nth_element(bucket.begin(), bucket.begin() + static_cast<std::ptrdiff_t>(rank), bucket.end());
  const double a = bucket[rank];
  const double b = rank + 1 < bucket.size()
                       ? *std::min_element(bucket.begin() + static_cast<std::ptrdiff_t>(rank) + 1, bucket.end())
                       : above;
  return {a, b};
}

}  // namespace rotinterp::detail
