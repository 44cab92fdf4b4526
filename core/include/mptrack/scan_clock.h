// ScanClock: the scan-admission rule of the tracker contract (track_report.h),
// shared by every tracker so the rule is written once.
//
// A scan is refused whole, before any tracker state is touched, when the
// tracker is not initialised (kNotInitialized) or when its time does not
// increase strictly (kOutOfOrder); both count in
// TrackerCounters::scans_rejected. An admitted scan gets the time elapsed
// since the previous accepted scan; advance() records it as accepted.
//
// Max-gap rule (docs/reliability.md F1). A scan more than max_gap after
// the previous accepted one is accepted, but gap_exceeded() flags it: the
// tracker then drops every track (counted in TrackerCounters::gap_resets
// and tracks_deleted) and processes the scan as the first of a new run.
// Predicting a constant-velocity covariance over an unbounded gap is
// meaningless (after ~1000 s the float CV covariance, P_vv dt^2 ~ 1e20, is
// singular to working precision) and the old tracks would gate nothing.
// Each tracker's Params carries max_gap_s (default 60 s); set_max_gap_s()
// installs it at init(). No limit until it is set.
#pragma once

#include <cstddef>
#include <cstdint>

#include "mptrack/status.h"
#include "mptrack/track_report.h"

namespace mptrack {

class ScanClock {
 public:
  /// Forgets every scan: the next admitted scan is the first.
  void reset() {
    has_time_ = false;
    last_time_us_ = 0;
  }

  /// kOk if a scan at time_us may be processed; otherwise the refusal,
  /// counted in counters.scans_rejected. Does not advance the clock.
  Status admit(bool initialized, std::uint64_t time_us, TrackerCounters& counters) const {
    if (!initialized) {
      ++counters.scans_rejected;
      return Status::kNotInitialized;
    }
    if (has_time_ && !(time_us > last_time_us_)) {
      ++counters.scans_rejected;
      return Status::kOutOfOrder;
    }
    return Status::kOk;
  }

  /// Installs the max-gap rule: a gap longer than max_gap_s [s] is flagged
  /// by gap_exceeded(). max_gap_s must be validated (finite, > 0, <= 1e6 s)
  /// by the caller's Params; reset() keeps it.
  template <class T>
  void set_max_gap_s(T max_gap_s) {
    max_gap_us_ = static_cast<std::uint64_t>(max_gap_s * T(1e6));
  }

  /// True if a previous scan was accepted and time_us is more than the max
  /// gap after it (never true before set_max_gap_s()). Call after admit().
  bool gap_exceeded(std::uint64_t time_us) const {
    return has_time_ && max_gap_us_ > 0 && time_us > last_time_us_ &&
           time_us - last_time_us_ > max_gap_us_;
  }

  /// Forgets the previous scan time only (after gap_exceeded()): the next
  /// elapsed_s() returns its first_dt_s. Admission is unaffected: the
  /// caller has admitted the current scan already.
  void restart() { has_time_ = false; }

  /// The gap rule of a tracker whose whole state is one track table: if
  /// time_us is a gap (gap_exceeded()), counts it (gap_resets, and the
  /// live_tracks dropped in tracks_deleted), restarts the clock and returns
  /// true; the caller then clears its table.
  bool restart_on_gap(std::uint64_t time_us, std::size_t live_tracks, TrackerCounters& c) {
    if (!gap_exceeded(time_us)) return false;
    ++c.gap_resets;
    c.tracks_deleted += live_tracks;
    restart();
    return true;
  }

  /// Time since the previous accepted scan [s]; first_dt_s for the first scan.
  template <class T>
  T elapsed_s(std::uint64_t time_us, T first_dt_s) const {
    return has_time_ ? static_cast<T>(time_us - last_time_us_) * T(1e-6) : first_dt_s;
  }

  /// What init() of every tracker does: forget every scan and install the
  /// max-gap rule from its validated Params::max_gap_s [s].
  template <class T>
  void start(T max_gap_s) {
    reset();
    set_max_gap_s(max_gap_s);
  }

  /// Records the scan at time_us as accepted.
  void advance(std::uint64_t time_us) {
    last_time_us_ = time_us;
    has_time_ = true;
  }

  bool has_time() const { return has_time_; }
  std::uint64_t last_time_us() const { return last_time_us_; }

 private:
  std::uint64_t last_time_us_ = 0;  ///< time of the last accepted scan [us]
  std::uint64_t max_gap_us_ = 0;    ///< max-gap rule [us], 0 = none
  bool has_time_ = false;
};

}  // namespace mptrack
