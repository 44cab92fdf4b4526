// The multipath track fusion (MPTF) capacities read from a caps type
// (caps.h), with defaults (docs/algorithms/mptf.md §Capacities).
//
//  - kMaxPaths: propagation paths (N_P; 4 for the OTHR E/F layers), the
//    same caps member the multipath MF-BP tracker reads.
//  - kMaxPathTracks: slant-coordinate tracks alive at once, tentative ones
//    included (default kMaxMeasurements: every detection of a scan can start
//    one, which the birth rule does at high clutter).
//  - fused (reported) ground tracks: kMaxTargets; the path tracks fusion
//    considers per scan: kMaxTargets x kMaxPaths (a full fused table).
// A caps type without them compiles with the defaults (MPTRACK_OPTIONAL_CAP).
#pragma once

#include <cstddef>
#include <type_traits>

#include "mptrack/caps.h"

namespace mptrack::mptf {

namespace detail {
MPTRACK_OPTIONAL_CAP(PathsOf, kMaxPaths, 4);
MPTRACK_OPTIONAL_CAP(PathTracksOf, kMaxPathTracks, Caps::kMaxMeasurements);
}  // namespace detail

template <class Caps>
inline constexpr std::size_t kMaxPaths = detail::PathsOf<Caps>::value;
template <class Caps>
inline constexpr std::size_t kMaxPathTracks = detail::PathTracksOf<Caps>::value;
template <class Caps>
inline constexpr std::size_t kMaxFusionCandidates = Caps::kMaxTargets * kMaxPaths<Caps>;

/// The largest number of paths a Params can describe (its path table).
inline constexpr std::size_t kParamPaths = 8;

template <class Caps>
constexpr bool mptf_caps_are_valid() {
  static_assert(kMaxPaths<Caps> >= 1 && kMaxPaths<Caps> <= kParamPaths, "Caps::kMaxPaths must be in [1, 8]");
  static_assert(kMaxPathTracks<Caps> >= 1 && kMaxPathTracks<Caps> <= 65535,
                "Caps::kMaxPathTracks must be in [1, 65535]");
  return true;
}

}  // namespace mptrack::mptf
