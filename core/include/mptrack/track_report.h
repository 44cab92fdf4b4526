// What every tracker in core reports: per finalised scan, the tracks (and,
// where estimated, the clutter map) plus counters. The host harness, the
// metrics and the golden tests only see these types, so trackers are
// interchangeable (MF-BP, its ablations, GM-PHD/CPHD, GNN).
//
// The members every tracker provides and the rules it obeys are in
// tracker_contract.h (checked at compile time and by
// tests/unit/tracker_contract_test.cpp). An online filter finalises one
// scan per step; a sliding-window smoother finalises scans in batches with
// a lag (seed 000: window 7, slide 3).
#pragma once

#include <cstddef>
#include <cstdint>

#include <Eigen/Core>

#include "mptrack/static_vector.h"

namespace mptrack {

/// One track at one finalised scan. State order [px, vx, py, vy]
/// (docs/algorithms/README.md §Notation and units).
template <class T>
struct TrackReport {
  std::uint32_t id = 0;                   ///< stable across scans; never reused within a run
  Eigen::Matrix<T, 4, 1> state = Eigen::Matrix<T, 4, 1>::Zero();       ///< [m, m/s, m, m/s]
  Eigen::Matrix<T, 4, 4> covariance = Eigen::Matrix<T, 4, 4>::Zero();  ///< of state
  T existence = T(0);                     ///< P(target present/visible) at this scan [-]
  T snr = T(0);                           ///< estimated mean SNR, linear [-] (0 if not estimated)
  bool confirmed = false;                 ///< passed the confirmation rule
  std::int32_t measurement_index = -1;    ///< most likely measurement at this scan, -1 = missed
};

/// One clutter component of the estimated clutter map (measurement space).
template <class T>
struct ClutterReport {
  std::uint32_t id = 0;
  bool uniform = false;                   ///< the uniform component (tau = 0 in seed 000)
  Eigen::Matrix<T, 2, 1> mean = Eigen::Matrix<T, 2, 1>::Zero();        ///< [range m, azimuth rad]
  Eigen::Matrix<T, 2, 2> covariance = Eigen::Matrix<T, 2, 2>::Zero();  ///< spread [m^2, m rad; ., rad^2]
  T expected_count = T(0);                ///< expected clutter measurements per scan [-]
  T cnr = T(0);                           ///< estimated mean clutter-to-noise ratio, linear [-]
};

/// Everything a tracker says about one finalised scan.
template <class T, std::size_t MaxTargets, std::size_t MaxClutter>
struct ScanEstimate {
  std::uint64_t time_us = 0;              ///< time of the scan this estimate is for
  std::uint32_t scan_index = 0;           ///< 0-based index of that scan in the tracker's input
  StaticVector<TrackReport<T>, MaxTargets> tracks;
  StaticVector<ClutterReport<T>, MaxClutter + 1> clutter;  ///< + 1: the uniform component
};

/// Counters every tracker keeps; nothing is dropped without being counted.
struct TrackerCounters {
  std::uint64_t scans = 0;                    ///< scans accepted by step()
  std::uint64_t scans_rejected = 0;           ///< scans refused whole (bad time, not initialised)
  std::uint64_t measurements_in = 0;          ///< measurements offered
  std::uint64_t measurements_invalid = 0;     ///< rejected: NaN/Inf, out of region, amplitude <= threshold
  std::uint64_t measurements_over_cap = 0;    ///< dropped by an internal cap (policy documented per tracker)
  std::uint64_t tracks_born = 0;
  std::uint64_t tracks_confirmed = 0;
  std::uint64_t tracks_deleted = 0;
  std::uint64_t track_cap_hits = 0;           ///< births refused because kMaxTargets tracks were alive
  std::uint64_t clutter_born = 0;
  std::uint64_t clutter_deleted = 0;
  std::uint64_t clutter_cap_hits = 0;
  std::uint64_t bp_not_converged = 0;         ///< BP runs that hit the iteration cap
  std::uint64_t numerical_repairs = 0;        ///< covariances re-symmetrised / regularised
  std::uint64_t gap_resets = 0;               ///< scans after a gap > Params::max_gap_s: all tracks dropped (scan_clock.h)
  std::uint64_t measurements_duplicate = 0;   ///< exact duplicates of an earlier measurement of the scan, dropped (measurement.h)
  std::uint64_t association_cap_hits = 0;     ///< gated (track, measurement) pairs dropped by an association cap
  std::uint64_t tentative_evicted = 0;        ///< tentative tracks deleted to make room for a more likely
                                              ///< birth when the track table was full (never a confirmed one)
  std::uint64_t mixture_truncated = 0;        ///< left out by a cap but never reportable: GM-PHD/CPHD components beyond J_max, CBMeMBer components beyond the raw cap and Bernoullis with r <= existence_extract beyond the track list
                                              ///< (GM-PHD/CPHD, CBMeMBer; rfs/mixture.h): counted, not a cap error
};

/// Calls f(name, member pointer) for every TrackerCounters field, in
/// declaration order: the one list that summaries and report writers walk,
/// so a counter added above cannot be left out of them.
template <class F>
void for_each_counter(F&& f) {
  f("scans", &TrackerCounters::scans);
  f("scans_rejected", &TrackerCounters::scans_rejected);
  f("measurements_in", &TrackerCounters::measurements_in);
  f("measurements_invalid", &TrackerCounters::measurements_invalid);
  f("measurements_over_cap", &TrackerCounters::measurements_over_cap);
  f("tracks_born", &TrackerCounters::tracks_born);
  f("tracks_confirmed", &TrackerCounters::tracks_confirmed);
  f("tracks_deleted", &TrackerCounters::tracks_deleted);
  f("track_cap_hits", &TrackerCounters::track_cap_hits);
  f("clutter_born", &TrackerCounters::clutter_born);
  f("clutter_deleted", &TrackerCounters::clutter_deleted);
  f("clutter_cap_hits", &TrackerCounters::clutter_cap_hits);
  f("bp_not_converged", &TrackerCounters::bp_not_converged);
  f("numerical_repairs", &TrackerCounters::numerical_repairs);
  f("gap_resets", &TrackerCounters::gap_resets);
  f("measurements_duplicate", &TrackerCounters::measurements_duplicate);
  f("association_cap_hits", &TrackerCounters::association_cap_hits);
  f("tentative_evicted", &TrackerCounters::tentative_evicted);
  f("mixture_truncated", &TrackerCounters::mixture_truncated);
}
/// Number of fields for_each_counter() visits.
inline constexpr std::size_t kTrackerCounterFields = 19;
static_assert(sizeof(TrackerCounters) == kTrackerCounterFields * sizeof(std::uint64_t),
              "every TrackerCounters field must be listed in for_each_counter()");

}  // namespace mptrack
