// Compile-time capacity traits ("caps"). Every buffer in core is sized from
// one of these types; nothing is sized at run time.
//
// A caps type is any struct with the static members below. Pass it as the
// Caps template parameter of a core component, e.g.
//   mptrack::MfbpTracker<float, mptrack::SmallBoardCaps> tracker;  // placed in .bss
// The four capacities every component shares (kMaxTargets, kMaxMeasurements,
// kMaxClutterComponents, kMaxWindow) are required. The capacities of one
// tracker only (MF-BP: kMaxGatePairs, kMaxTrackGatePairs, kMaxGatePool,
// kMaxClutterGridCells, kMaxBirthCandidates; GM-PHD/CPHD: kMaxMixtureComponents; CBMeMBer:
// kMaxComponentsPerBernoulli, kMaxRawComponentsPerBernoulli) are optional:
// a caps type without them gets the values of the presets below (read
// through MPTRACK_OPTIONAL_CAP traits: mfbp/mfbp_caps.h, rfs/rfs_caps.h).
// Run-time tunables never live here: they are in each component's Params
// struct (units and defaults there), validated once by init().
#pragma once

#include <cstddef>
#include <type_traits>

namespace mptrack {

/// Default caps: a mid-range Cortex-M7 / Cortex-A board.
struct DefaultCaps {
  static constexpr std::size_t kMaxTargets = 64;            ///< tracks alive at once
  static constexpr std::size_t kMaxMeasurements = 256;      ///< detections per scan
  static constexpr std::size_t kMaxClutterComponents = 8;   ///< non-uniform clutter components
  static constexpr std::size_t kMaxWindow = 7;              ///< smoothing window length K (scans)
  /// Multipath MF-BP: gated measurements kept per pseudo-target and scan
  /// (the most likely ones; the rest are dropped and counted in
  /// TrackerCounters::association_cap_hits). MF-BP used it per track before
  /// kMaxTrackGatePairs / kMaxGatePool below. 16: tentative tracks in seed000-s2/-s3's chaff (20-30 per scan) hold
  /// many gated measurements; one run dropped 1 803 / 5 962 pairs at 8 (38 /
  /// 46 of 341 steps), 222 / 1 838 at 16 (19 / 39 steps) and 4 / 165 at 32
  /// (1 / 9 steps), with the same OSPA at 16 and 32. 32 would cost MF-BP
  /// another ~76 KB here and push the Cortex-M7 image past its 512 KiB
  /// (bench/README.md); LargeCaps has 32.
  static constexpr std::size_t kMaxGatePairs = 16;
  /// MF-BP reads these two instead of kMaxGatePairs (which the multipath
  /// tracker keeps per pseudo-target): up to 128 gated pairs per track,
  /// drawn from a pool of 1024 per scan shared by every track
  /// (docs/algorithms/mfbp.md §Evidence and association). Measured with no cap, 10 runs
  /// each: the longest list was 47 / 56 on seed000-s2 / -s3 and the most
  /// pairs in one scan 300 / 535; the pool costs what 16 per track did.
  /// 64 per track still dropped 3 pairs of one young track (67 gated) in
  /// one of 34 000 steps of seed000-s3 (100 runs); the list is stack only
  /// (GateList, ~0.4 KB more in float), not stored state.
  static constexpr std::size_t kMaxTrackGatePairs = 128;
  static constexpr std::size_t kMaxGatePool = 1024;
  /// MF-BP: cells of the clutter-seeding grid (the grid is coarsened until
  /// the region fits).
  static constexpr std::size_t kMaxClutterGridCells = 512;
  /// MF-BP: two-point birth candidates ranked per window; the params field
  /// birth_max_per_window must not exceed it (init() refuses).
  static constexpr std::size_t kMaxBirthCandidates = 32;
  /// GM-PHD/CPHD: Gaussian components kept after pruning and merging
  /// (2 per target; the lightest beyond it are dropped, track_cap_hits).
  static constexpr std::size_t kMaxMixtureComponents = 128;
  /// CBMeMBer: Gaussian components per Bernoulli after reduction, and the
  /// heaviest collected before it (mixture_truncated counts what is dropped).
  static constexpr std::size_t kMaxComponentsPerBernoulli = 4;
  /// 64: seed000-s2 needs up to 64 above prune_threshold per updated
  /// Bernoulli (p99.9 52; docs/algorithms/cbmember.md §Caps).
  static constexpr std::size_t kMaxRawComponentsPerBernoulli = 64;
};

/// Small board: fits a 64 KiB RAM budget (see README, footprint report).
/// Fits 64 KiB: MfbpTracker<float, SmallBoardCaps> state + step() stack
/// (docs/results/bench/footprint.json). The MF-BP window stops at 4 scans (run it with
/// window_length 4, slide 2, or as the online filter): every window scan
/// costs ~7.9 KB here, and window 4 loses little (20/10 runs: S1 36.8 m vs
/// 34.1 m at window 7, S2 87.0 m vs 89.9 m; docs/results/seed000-s1.md).
struct SmallBoardCaps {
  static constexpr std::size_t kMaxTargets = 16;
  static constexpr std::size_t kMaxMeasurements = 64;
  static constexpr std::size_t kMaxClutterComponents = 4;
  static constexpr std::size_t kMaxWindow = 4;
  static constexpr std::size_t kMaxGatePairs = 8;
  static constexpr std::size_t kMaxClutterGridCells = 512;
  static constexpr std::size_t kMaxBirthCandidates = 32;
  static constexpr std::size_t kMaxMixtureComponents = 32;
  static constexpr std::size_t kMaxComponentsPerBernoulli = 4;
  static constexpr std::size_t kMaxRawComponentsPerBernoulli = 16;
};

/// Large: Cortex-A class cores with MiBs of RAM.
struct LargeCaps {
  static constexpr std::size_t kMaxTargets = 256;
  static constexpr std::size_t kMaxMeasurements = 1024;
  static constexpr std::size_t kMaxClutterComponents = 8;
  static constexpr std::size_t kMaxWindow = 7;
  static constexpr std::size_t kMaxGatePairs = 32;
  static constexpr std::size_t kMaxTrackGatePairs = 128;
  static constexpr std::size_t kMaxGatePool = 8192;
  static constexpr std::size_t kMaxClutterGridCells = 512;
  static constexpr std::size_t kMaxBirthCandidates = 32;
  static constexpr std::size_t kMaxMixtureComponents = 512;
  static constexpr std::size_t kMaxComponentsPerBernoulli = 4;
  /// As DefaultCaps: the measured per-Bernoulli budget does not shrink with
  /// more RAM (docs/algorithms/cbmember.md §Caps).
  static constexpr std::size_t kMaxRawComponentsPerBernoulli = 64;
};

/// Declares the trait Trait<Caps>: Caps::Member if the caps type declares
/// it, otherwise Default (C++17 detection idiom). Capacities that only one
/// component needs (MF-BP's gate pairs, CBMeMBer's components per
/// Bernoulli, ...) are read through such a trait, so a caps type written
/// before they existed still compiles, with the presets' values.
#define MPTRACK_OPTIONAL_CAP(Trait, Member, Default)                                          \
  template <class Caps, class = void>                                                        \
  struct Trait : std::integral_constant<std::size_t, (Default)> {};                          \
  template <class Caps>                                                                      \
  struct Trait<Caps, std::void_t<decltype(Caps::Member)>>                                    \
      : std::integral_constant<std::size_t, Caps::Member> {}

/// Compile-time validation of a caps type; every component calls it in a
/// static_assert so a bad preset fails to build with a readable message.
template <class Caps>
constexpr bool caps_are_valid() {
  static_assert(Caps::kMaxTargets >= 1, "Caps::kMaxTargets must be >= 1");
  static_assert(Caps::kMaxMeasurements >= 1, "Caps::kMaxMeasurements must be >= 1");
  static_assert(Caps::kMaxWindow >= 1, "Caps::kMaxWindow must be >= 1");
  static_assert(Caps::kMaxTargets <= 4096 && Caps::kMaxMeasurements <= 65535,
                "caps beyond 4096 targets / 65535 measurements are not supported (16-bit indices)");
  return true;
}

}  // namespace mptrack
