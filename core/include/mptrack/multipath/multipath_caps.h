// The multipath MF-BP capacities read from a caps type (caps.h), with
// defaults (docs/algorithms/multipath.md §Capacities).
//
//  - kMaxPaths: propagation paths per target (N_P; 4 for the OTHR E/F
//    layers). A track is N_P pseudo-targets in the association, so the BP
//    is sized kMaxTargets x kMaxPaths pseudo-targets.
//  - kMaxGatePairs: gated detections kept per pseudo-target and scan (the
//    same name and default as MF-BP's: the closest ones are kept).
//  - kMaxSmoothingLag: scans the fixed-lag smoother may hold back.
// A caps type without them compiles with the defaults (MPTRACK_OPTIONAL_CAP).
#pragma once

#include <cstddef>
#include <type_traits>

#include "mptrack/caps.h"

namespace mptrack::multipath {

namespace detail {
MPTRACK_OPTIONAL_CAP(PathsOf, kMaxPaths, 4);
MPTRACK_OPTIONAL_CAP(PathGatePairsOf, kMaxGatePairs, 8);
MPTRACK_OPTIONAL_CAP(SmoothingLagOf, kMaxSmoothingLag, 3);
}  // namespace detail

/// Propagation paths per target (Caps::kMaxPaths, default 4).
template <class Caps>
inline constexpr std::size_t kMaxPaths = detail::PathsOf<Caps>::value;
/// Gated detections kept per (target, path) and scan (Caps::kMaxGatePairs, default 8).
template <class Caps>
inline constexpr std::size_t kMaxPathGatePairs = detail::PathGatePairsOf<Caps>::value;

/// Scans the fixed-lag smoother can hold back (Caps::kMaxSmoothingLag,
/// default 3; multipath/fixed_lag_smoother.h).
template <class Caps>
inline constexpr std::size_t kMaxSmoothingLag = detail::SmoothingLagOf<Caps>::value;

/// The largest number of paths a Params can describe (its path table).
inline constexpr std::size_t kParamPaths = 8;

/// Compile-time checks (index widths of the shared loopy BP, assoc/association_bp.h).
template <class Caps>
constexpr bool multipath_caps_are_valid() {
  static_assert(kMaxPaths<Caps> >= 1 && kMaxPaths<Caps> <= kParamPaths,
                "Caps::kMaxPaths must be in [1, 8]");
  static_assert(kMaxPathGatePairs<Caps> >= 1 && kMaxPathGatePairs<Caps> <= 255,
                "Caps::kMaxGatePairs must be in [1, 255]");
  static_assert(kMaxSmoothingLag<Caps> >= 1 && kMaxSmoothingLag<Caps> <= 16,
                "Caps::kMaxSmoothingLag must be in [1, 16]");
  static_assert(Caps::kMaxTargets * kMaxPaths<Caps> * kMaxPathGatePairs<Caps> < 65536,
                "kMaxTargets x kMaxPaths x kMaxGatePairs must stay below 65536 (16-bit BP edges)");
  return true;
}

}  // namespace mptrack::multipath
