// OSPA with a Mahalanobis base distance in (range, range rate), the MOSPA of
// seed 003 Sec. IV-A: base covariance diag(sigma_r^2, sigma_rdot^2) (the
// paper's measurement noise, diag((15 m)^2, (0.1 Hz)^2)), order p = 2,
// cut-off c = 9.4 (dimensionless: a distance in standard deviations).
// docs/algorithms/metrics.md §MOSPA with a Mahalanobis base distance.
#pragma once

#include <memory>
#include <vector>

#include "mptrack/metrics/ospa.h"
#include "mptrack/scenario/generator.h"
#include "mptrack/scenario/scenario_spec.h"
#include "tracker_adapter.h"

namespace mptrack::sim {

struct MahalanobisOspaParams {
  double sigma_range_m = 15.0;           ///< base standard deviation of range [m]
  double sigma_range_rate_mps = 1.0;     ///< base standard deviation of range rate [m/s]
  double cutoff = 9.4;                   ///< c, in standard deviations (seed 003 Sec. IV-A)
  double order = 2.0;                    ///< p (seed 003 Sec. IV-A)
};

/// The scenario's base covariance: its measurement noise in range
/// (sigma_range_m; Cartesian scenarios: sigma_xy_m) and range rate
/// (othr.sigma_range_rate_mps, the one range-rate noise a ScenarioSpec
/// carries); c = 9.4, p = 2.
MahalanobisOspaParams mahalanobis_ospa_params(const scenario::ScenarioSpec& spec);

/// Range [m] and range rate [m/s] about the sensor at the origin of a
/// Cartesian state [px, vx, py, vy]; range rate 0 at the origin.
void range_and_rate(double px, double vx, double py, double vy, double& range_m, double& range_rate_mps);

class MahalanobisOspa {
 public:
  /// Throws std::runtime_error unless both sigmas are positive and finite
  /// and OSPA accepts (p, c).
  explicit MahalanobisOspa(const MahalanobisOspaParams& params = MahalanobisOspaParams{});
  /// OSPA between the truths of `scan` and the confirmed tracks of `est`.
  /// With a diagonal covariance the Mahalanobis distance is the Euclidean
  /// distance of (range / sigma_r, range rate / sigma_rdot), so the core
  /// OSPA runs on those whitened points. Throws std::runtime_error on more
  /// than 256 points or a non-finite state.
  double evaluate(const scenario::SimScan& scan, const EstimateOut& est);
  const MahalanobisOspaParams& params() const { return params_; }

 private:
  MahalanobisOspaParams params_;
  std::unique_ptr<OspaMetric<double, 256>> ospa_;  // a 256^2 cost matrix: heap
};

}  // namespace mptrack::sim
