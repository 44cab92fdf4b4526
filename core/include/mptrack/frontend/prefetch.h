// Software prefetch of the next block a front-end stage will read.
//
// The range stage streams the 3 MB cube and the Doppler stage the range
// output, each in runs of a few KiB with FFTs in between, during which no
// load asks the hardware prefetchers for the next run (and they stop at
// 4 KiB page boundaries). A hint for a run well ahead, issued before the
// current run's FFTs, overlaps its memory latency with them; it matters most
// when other cores share the memory bandwidth (bench/README.md, session 15).
// A hint only: it changes no value, so no bits.
#pragma once

#include <cstddef>

namespace mptrack::frontend {

/// Cache line size the hints step by [bytes] (64 on every supported target's
/// L1; a larger line only makes some hints redundant).
inline constexpr std::size_t kPrefetchLineBytes = 64;

/// Hints that [p, p + bytes) will be read soon. No-op where the compiler has
/// no prefetch builtin. Always inlined: GCC 12 finds an out-of-line copy
/// "looping const" (no side effects) and deletes every call to it.
#if defined(__GNUC__)
__attribute__((always_inline)) inline void prefetch_read(const void* p, std::size_t bytes) {
  const char* c = static_cast<const char*>(p);
  for (std::size_t off = 0; off < bytes; off += kPrefetchLineBytes) __builtin_prefetch(c + off, 0, 3);
}
#else
inline void prefetch_read(const void* p, std::size_t bytes) {
  static_cast<void>(p);
  static_cast<void>(bytes);
}
#endif

}  // namespace mptrack::frontend
