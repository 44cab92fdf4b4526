// Tapering windows for the range, Doppler and angle stages.
//
// Computed once in init() in double with mptrack::dmath (no libm), rounded
// to float, so window tables are bit-identical on every target. Symmetric
// (not periodic) definitions, n = 0..L-1, as used for sidelobe control of a
// finite aperture (Harris 1978, eqs. 27a, 30b, 32).
#pragma once

#include <cstddef>
#include <cstdint>

#include "mptrack/math/constants.h"
#include "mptrack/math/detmath.h"

namespace mptrack::frontend {

enum class WindowType : std::uint8_t {
  kRectangular = 0,  ///< no taper: best SNR (processing gain L), -13 dB sidelobes
  kHann,             ///< -31 dB sidelobes, 1.76 dB SNR loss
  kHamming,          ///< -43 dB sidelobes, 1.34 dB SNR loss
  kBlackman,         ///< -58 dB sidelobes, 2.37 dB SNR loss
};

/// Window value w[n] of length len (len >= 1; len == 1 gives 1).
inline double window_value(WindowType type, std::size_t n, std::size_t len) {
  if (len <= 1 || type == WindowType::kRectangular) return 1.0;
  const double x = mptrack::dmath::kTwoPi<double> * static_cast<double>(n) /
                   static_cast<double>(len - 1);
  const double c1 = mptrack::dmath::dcos(x);
  switch (type) {
    case WindowType::kHann: return 0.5 - 0.5 * c1;
    case WindowType::kHamming: return 0.54 - 0.46 * c1;
    case WindowType::kBlackman: return 0.42 - 0.5 * c1 + 0.08 * mptrack::dmath::dcos(2.0 * x);
    case WindowType::kRectangular: break;
  }
  return 1.0;
}

/// Fills w[0..len) with the window rounded to float.
inline void fill_window(WindowType type, float* w, std::size_t len) {
  for (std::size_t n = 0; n < len; ++n) w[n] = static_cast<float>(window_value(type, n, len));
}

/// True for a defined enumerator (params validation).
inline bool is_valid_window(WindowType t) {
  return t == WindowType::kRectangular || t == WindowType::kHann || t == WindowType::kHamming ||
         t == WindowType::kBlackman;
}

}  // namespace mptrack::frontend
