// Compile-time capacities of the VMP tracker (docs/algorithms/vmp.md §Caps and memory).
#pragma once

#include <cstddef>

namespace mptrack {

/// Seed 004 defaults: 16 tracks, a 32-frame window, 4 births per frame, a birth
/// map of up to 96 range x 64 bearing cells (1.17 m x 1/32 in sin theta over 3..100 m).
struct VmpDefaultCaps {
  static constexpr std::size_t kMaxTargets = 16;        ///< live tracks (K_MAX)
  static constexpr std::size_t kWindow = 32;            ///< frames per track window (W)
  static constexpr std::size_t kMaxBirthsPerFrame = 4;  ///< B_MAX
  static constexpr std::size_t kMapRangeCells = 96;     ///< birth map range cells
  static constexpr std::size_t kMapAngleCells = 64;     ///< birth map bearing cells
};

/// Small caps for tests under qemu: 4 tracks, an 8-frame window.
struct VmpSmallCaps {
  static constexpr std::size_t kMaxTargets = 4;
  static constexpr std::size_t kWindow = 8;
  static constexpr std::size_t kMaxBirthsPerFrame = 4;
  static constexpr std::size_t kMapRangeCells = 96;
  static constexpr std::size_t kMapAngleCells = 64;
};

template <class Caps>
constexpr bool vmp_caps_are_valid() {
  static_assert(Caps::kMaxTargets >= 1 && Caps::kMaxTargets <= 64, "1 <= kMaxTargets <= 64");
  static_assert(Caps::kWindow >= 2, "kWindow >= 2 (a frozen tail needs one frame inside)");
  static_assert(Caps::kMaxBirthsPerFrame >= 1, "kMaxBirthsPerFrame >= 1");
  static_assert(Caps::kMapRangeCells >= 2 && Caps::kMapAngleCells >= 2, "birth map needs >= 2 x 2 cells");
  return true;
}

}  // namespace mptrack
