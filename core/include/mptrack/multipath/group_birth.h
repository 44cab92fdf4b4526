// Track births from multi-detection groups (seed 002 Sec. III-E;
// docs/algorithms/multipath.md §Births).
//
// Detections that the association leaves to clutter are grouped: two go in
// one group when they are within rho on every axis (slant range, range
// rate, azimuth). The candidates are sorted by slant range so that the
// search for a seed's partners stops at the first detection more than
// rho_r away (a sweep over range, O(n log n + n k) instead of O(n^2); the tracker
// sorts the detections once per scan and its gating uses the same order).
// A group of m >= min_group_size detections (at most kMaxGroup, the closest
// in range) is a track head if some assignment of its members to distinct
// paths maps them to ground points that agree: every member is inverted
// through its path (model/othr_measurement.h, othr_invert), and the
// assignment with the smallest normalised spread is kept if its spread per
// degree of freedom is at most birth_max_spread. Its mean is the new state.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "mptrack/model/othr_measurement.h"
#include "mptrack/multipath/multipath_params.h"
#include "mptrack/multipath/path_track.h"

namespace mptrack::multipath {

/// At most this many detections of a group are assigned to paths (the
/// assignment search is P(N_P, m) <= 8!/4! = 1680 for m = 4).
inline constexpr std::size_t kMaxGroup = 4;

template <class T>
struct GroupHypothesis {
  model::OthrState<T> x = model::OthrState<T>::Zero();  ///< mean ground point [km, km/s, rad, 0]
  T spread_per_dof = T(0);  ///< normalised spread / (3 (m - 1)); 0 for m = 1
  bool valid = false;
};

/// The best assignment of the m detections ys[0..m) to distinct paths.
/// sigma = [range km, range rate km/s, azimuth rad] scales the ground axes
/// (g ~ r, g_dot ~ r_dot, theta ~ zeta near the receiver's plane).
/// The runner-up (second) is the best assignment whose ground range differs
/// from the best one's by more than distinct_km: a group that fits two path
/// assignments (e.g. two detections 33 km apart fit EE+EF and EF+FF) is
/// ambiguous, and the caller may start both (docs/algorithms/multipath.md §Births).
template <class T, std::size_t MaxPaths>
GroupHypothesis<T> best_path_assignment(const model::OthrMeas<T>* ys, std::size_t m,
                                        const model::OthrPath<T>* paths, std::size_t num_paths,
                                        T baseline_km, const model::OthrMeas<T>& sigma,
                                        GroupHypothesis<T>* second = nullptr, T distinct_km = T(0)) {
  GroupHypothesis<T> best;
  GroupHypothesis<T> runner;
  T runner_spread = T(0);
  if (m == 0 || m > kMaxGroup || m > num_paths) return best;
  std::array<std::array<model::OthrState<T>, MaxPaths>, kMaxGroup> ground{};
  std::array<std::array<bool, MaxPaths>, kMaxGroup> ok{};
  for (std::size_t k = 0; k < m; ++k) {
    for (std::size_t p = 0; p < num_paths; ++p) ok[k][p] = model::othr_invert(ys[k], paths[p], baseline_km, ground[k][p]);
  }
  std::array<std::size_t, kMaxGroup> pick{};  // odometer over path indices
  T best_spread = T(0);
  for (;;) {
    bool injective = true;
    for (std::size_t a = 0; a < m && injective; ++a) {
      injective = ok[a][pick[a]];
      for (std::size_t b = 0; b < a && injective; ++b) injective = pick[a] != pick[b];
    }
    if (injective) {
      model::OthrState<T> mean = model::OthrState<T>::Zero();
      for (std::size_t k = 0; k < m; ++k) mean += ground[k][pick[k]];
      mean /= static_cast<T>(m);
      T spread = T(0);
      for (std::size_t k = 0; k < m; ++k) {
        const model::OthrState<T>& z = ground[k][pick[k]];
        const T e0 = (z(0) - mean(0)) / sigma(0);
        const T e1 = (z(1) - mean(1)) / sigma(1);
        const T e2 = (z(2) - mean(2)) / sigma(2);
        spread += e0 * e0 + e1 * e1 + e2 * e2;
      }
      GroupHypothesis<T> h;
      h.valid = true;
      h.x = mean;
      h.x(3) = T(0);
      if (!best.valid || spread < best_spread) {
        const T dg = best.x(0) - mean(0);
        if (best.valid && (dg > distinct_km || -dg > distinct_km)) {
          runner = best;  // the old best is the runner-up now
          runner_spread = best_spread;
        }
        best = h;
        best_spread = spread;
      } else {
        const T dg = best.x(0) - mean(0);
        if ((dg > distinct_km || -dg > distinct_km) && (!runner.valid || spread < runner_spread)) {
          runner = h;
          runner_spread = spread;
        }
      }
    }
    std::size_t d = 0;  // advance the odometer
    while (d < m && ++pick[d] == num_paths) pick[d++] = 0;
    if (d == m) break;
  }
  const T dof = m > 1 ? static_cast<T>(3 * (m - 1)) : T(1);
  best.spread_per_dof = m > 1 ? best_spread / dof : T(0);
  if (second != nullptr) {
    const T dg = runner.x(0) - best.x(0);
    *second = runner;
    second->valid = runner.valid && (dg > distinct_km || -dg > distinct_km);
    second->spread_per_dof = m > 1 ? runner_spread / dof : T(0);
  }
  return best;
}

/// The track started from hypothesis h of a group of m detections
/// (docs/algorithms/multipath.md §Births): mean h.x, covariance
/// diag(sigma_r^2/m, sigma_rdot^2/m, sigma_zeta^2/m, init bearing-rate var),
/// existence birth_existence_scale min(1, (m/N_P)^2). r_var is the scan's
/// noise [km^2, (km/s)^2, rad^2]; without Doppler the range-rate variance is
/// r_var(1) (the span squared).
template <class T, std::size_t MaxPaths>
PathTrack<T, MaxPaths> new_track(const GroupHypothesis<T>& h, std::size_t m, const MultipathParams<T>& p,
                                 const model::OthrMeas<T>& r_var, bool has_doppler, std::uint32_t id,
                                 std::int32_t scan_index) {
  PathTrack<T, MaxPaths> t;
  t.id = id;
  t.x = h.x;
  const T inv_m = T(1) / static_cast<T>(m);
  const T rate_std = p.init_range_rate_std_mps * T(1e-3);
  t.P.setZero();
  t.P(0, 0) = r_var(0) * inv_m;
  t.P(1, 1) = has_doppler ? rate_std * rate_std * inv_m : r_var(1);
  t.P(2, 2) = r_var(2) * inv_m;
  t.P(3, 3) = p.init_bearing_rate_std_radps * p.init_bearing_rate_std_radps;
  t.x_prior = t.x;
  t.P_prior = t.P;
  const T frac = static_cast<T>(m) / static_cast<T>(p.num_paths);
  t.existence = p.birth_existence_scale * (frac < T(1) ? frac * frac : T(1));
  t.existence_prior = t.existence;
  t.record_existence();
  t.measurement_index = scan_index;
  return t;
}

}  // namespace mptrack::multipath
