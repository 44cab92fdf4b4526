// What the multipath tracker puts in its outputs: ground tracks as
// Cartesian reports (model/othr_cartesian.h), at once or after
// fixed-lag smoothing (fixed_lag_smoother.h).
#pragma once

#include <cstdint>

#include "mptrack/model/othr_cartesian.h"
#include "mptrack/multipath/fixed_lag_smoother.h"
#include "mptrack/multipath/path_track.h"
#include "mptrack/track_report.h"

namespace mptrack::multipath {

/// Appends an empty estimate of one scan to `outputs` (its capacity must
/// allow it: the tracker sizes it for the scans one step can finalise).
template <class Queue>
auto& open_estimate(Queue& outputs, std::uint64_t time_us, std::uint32_t scan_index) {
  static_cast<void>(outputs.resize(outputs.size() + 1));
  auto& e = outputs[outputs.size() - 1];
  e.time_us = time_us;
  e.scan_index = scan_index;
  e.tracks.clear();
  e.clutter.clear();
  return e;
}

/// Adds a ground track to an estimate as a Cartesian report.
template <class Estimate, class T>
void add_ground_report(Estimate& e, std::uint32_t id, const model::OthrState<T>& x, const Mat4<T>& P, T existence,
                       bool counted, std::int32_t measurement_index) {
  TrackReport<T> r;
  r.id = id;
  model::othr_ground_to_cartesian(x, P, r.state, r.covariance);
  r.existence = existence;
  r.confirmed = counted;
  r.measurement_index = measurement_index;
  static_cast<void>(e.tracks.push_back(r));  // at most one report per live track
}

/// What the smoother records of a track after its update at this scan.
template <class T, std::size_t MaxPaths>
LagEntry<T> lag_entry(const PathTrack<T, MaxPaths>& t, T dt_s) {
  LagEntry<T> e;
  e.id = t.id;
  e.x = t.x;
  e.P = t.P;
  e.x_pred = t.x_prior;
  e.P_pred = t.P_prior;
  e.q = t.existence;
  e.q_pred = t.existence_prior;
  e.dt_s = dt_s;
  e.confirmed = t.confirmed;
  e.measurement_index = t.measurement_index;
  return e;
}

/// A held-back scan counts a track if the track has been confirmed by now
/// and either its smoothed q(s = 1) holds the threshold or a newer scan's
/// filtered one does: the track was not over, so a run of scans missed on
/// every path is bridged and a confirmed track is reported from its birth
/// (docs/algorithms/multipath.md §Fixed-lag smoother).
template <class T>
bool counted_when_smoothed(const SmoothedEntry<T>& s, T hold_existence) {
  return s.confirmed && (s.q >= hold_existence || s.max_later_q >= hold_existence);
}

}  // namespace mptrack::multipath
