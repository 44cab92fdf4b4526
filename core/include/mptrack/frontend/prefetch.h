// Software prefetch of the next block a front-end stage will read.
//
// The range stage reads its input profiles, and the Doppler stage its
// chirp runs, in an order the hardware prefetcher does not follow (jumps of
// kilobytes between consecutive runs, each run a few cache lines): a hint
// for the next run, issued before the current run's FFTs, overlaps its
// memory latency with them. A hint only: it changes no value, so no bits.
#pragma once

#include <cstddef>

namespace mptrack::frontend {

/// Cache line size the hints step by [bytes] (64 on every supported target's
/// L1; a larger line only makes some hints redundant).
inline constexpr std::size_t kPrefetchLineBytes = 64;

/// Hints that [p, p + bytes) will be read soon. No-op where the compiler has
/// no prefetch builtin.
inline void prefetch_read(const void* p, std::size_t bytes) {
#if defined(__GNUC__)
  const char* c = static_cast<const char*>(p);
  for (std::size_t off = 0; off < bytes; off += kPrefetchLineBytes) __builtin_prefetch(c + off, 0, 3);
#else
  static_cast<void>(p);
  static_cast<void>(bytes);
#endif
}

}  // namespace mptrack::frontend
