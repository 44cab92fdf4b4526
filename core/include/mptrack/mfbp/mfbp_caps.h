// The MF-BP capacities read from a caps type (caps.h), with defaults
// (MfbpTracker::validate() checks the run-time params against them).
//
// MF-BP has four scratch capacities beyond the four every tracker shares:
// the gated pairs kept per track and scan and the pool of gated pairs per
// scan that every track draws from (the sparse association of seed 000
// eqs. (99)-(102) runs on them; docs/algorithms/mfbp.md §Evidence and association), the
// clutter-seeding grid and the ranked two-point birth candidates
// (docs/algorithms/mfbp.md §Birth). A
// user caps type written before they existed still compiles: the accessors
// below (MPTRACK_OPTIONAL_CAP, caps.h) fall back to the values of the presets.
#pragma once

#include <cstddef>
#include <type_traits>

#include "mptrack/caps.h"

namespace mptrack::mfbp {

namespace detail {
MPTRACK_OPTIONAL_CAP(GatePairsOf, kMaxGatePairs, 8);
// MF-BP's own per-track list length; without it the shared kMaxGatePairs
// (which the multipath tracker also reads per pseudo-target).
MPTRACK_OPTIONAL_CAP(TrackGatePairsOf, kMaxTrackGatePairs, GatePairsOf<Caps>::value);
MPTRACK_OPTIONAL_CAP(ClutterGridCellsOf, kMaxClutterGridCells, 512);
MPTRACK_OPTIONAL_CAP(BirthCandidatesOf, kMaxBirthCandidates, 32);
// Without the member: room for every track's full list, so the pool never
// binds (the behaviour of a caps type written before it existed).
MPTRACK_OPTIONAL_CAP(GatePoolOf, kMaxGatePool, Caps::kMaxTargets * TrackGatePairsOf<Caps>::value);
}  // namespace detail

/// Gated measurements kept per track and scan (Caps::kMaxTrackGatePairs;
/// without it Caps::kMaxGatePairs, default 8). Only the stack list of one
/// track is sized by it; the stored pairs are the pool's.
template <class Caps>
inline constexpr std::size_t kMaxGatePairs = detail::TrackGatePairsOf<Caps>::value;
/// Gated pairs per scan shared by every track (Caps::kMaxGatePool, default
/// kMaxTargets * kMaxGatePairs<Caps>): the stored association beliefs and the
/// BP's edges are sized by it, not by kMaxTargets * kMaxGatePairs.
template <class Caps>
inline constexpr std::size_t kMaxGatePool = detail::GatePoolOf<Caps>::value;
/// Cells of the clutter-seeding grid (Caps::kMaxClutterGridCells, default 512).
template <class Caps>
inline constexpr std::size_t kMaxClutterGridCells = detail::ClutterGridCellsOf<Caps>::value;
/// Ranked two-point birth candidates per window (Caps::kMaxBirthCandidates, default 32).
template <class Caps>
inline constexpr std::size_t kMaxBirthCandidates = detail::BirthCandidatesOf<Caps>::value;

/// Compile-time checks of the MF-BP capacities (index widths of the slots).
template <class Caps>
constexpr bool mfbp_caps_are_valid() {
  static_assert(kMaxGatePairs<Caps> >= 1 && kMaxGatePairs<Caps> <= 255,
                "Caps::kMaxTrackGatePairs (or kMaxGatePairs) must be in [1, 255] (8-bit edge count)");
  static_assert(kMaxGatePool<Caps> >= kMaxGatePairs<Caps> && kMaxGatePool<Caps> < 65536,
                "Caps::kMaxGatePool must be in [kMaxGatePairs, 65535] (16-bit pool offsets)");
  static_assert(kMaxClutterGridCells<Caps> >= 1 && kMaxClutterGridCells<Caps> <= 65535,
                "Caps::kMaxClutterGridCells must be in [1, 65535] (16-bit cell index)");
  static_assert(kMaxBirthCandidates<Caps> >= 1, "Caps::kMaxBirthCandidates must be >= 1");
  return true;
}

}  // namespace mptrack::mfbp
