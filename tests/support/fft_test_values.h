// Inputs for the FFT bit-equality tests (fft_reorder_test, fft_dispatch_test,
// fft_batch_test): a linear congruential sequence mapped to the value kinds
// where two schedules could round differently if they were not the same
// operations, and the comparison those tests use.
#pragma once

#include <cstdint>
#include <cstring>
#include <limits>

namespace mptrack::test {

/// Next value of kind `kind % 6`: 0 ordinary in [-1, 1], 1 subnormal, 2 signed
/// zero, 3 large (sums overflow to inf), 4 sometimes inf, 5 sometimes NaN.
/// Kinds 0..3 are finite (pass kind % 4 for inputs without inf or NaN).
inline float fft_test_value(std::uint32_t& x, int kind) {
  x = x * 1664525u + 1013904223u;
  const float u = static_cast<float>(static_cast<int>(x >> 9) % 20001 - 10000) * 1e-4f;
  switch (kind % 6) {
    case 0: return u;
    case 1: return u * 1e-39f;                                  // subnormal range
    case 2: return (x & 0x100u) != 0u ? -0.0f : 0.0f;           // signed zeros
    case 3: return u * 1e30f;                                   // large (overflows to inf)
    case 4: return (x & 0x7000u) == 0u ? std::numeric_limits<float>::infinity() : u;
    default: return (x & 0x7000u) == 0u ? std::numeric_limits<float>::quiet_NaN() : u;
  }
}

/// Bit-identical, or both NaN. NaN payloads are not compared: which operand's
/// payload an x86 operation returns depends on operand order, which the
/// compiler may commute in + and *; no golden vector holds a NaN.
inline bool same_bits_or_nan(float a, float b) {
  if (a != a && b != b) return true;
  return std::memcmp(&a, &b, sizeof(float)) == 0;
}

}  // namespace mptrack::test
