// ScenarioSpec: a measurement-level radar scenario as data (seed 000 spec
// section 4). The same structure is what host-sim/scenarios/*.json hold;
// fields are in the JSON's units (degrees for angles, linear SNR/CNR) so a
// JSON file loads to exactly these values and saves back unchanged. The
// generator converts degrees to radians when it draws measurements.
//
// Scan k (1-based) is at time t_k = (k - 1) * scan_period_s.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace mptrack::scenario {

/// Amplitude fluctuation model (spec 2.4/2.5): the received power
/// u ~ Gamma(shape n, scale (1 + snr) / n), n = 1 for Swerling I, 2 for III.
enum class Swerling : std::uint8_t { kOne = 1, kThree = 3 };

/// Gamma shape n of a Swerling case (spec 2.4: n = 1 for I, n = 2 for III).
constexpr int swerling_shape(Swerling s) { return s == Swerling::kThree ? 2 : 1; }

/// Search region in measurement (polar) space, spec 4.1 / A20.
struct Region {
  double range_min_m = 10000.0;
  double range_max_m = 50000.0;
  double azimuth_min_deg = 10.0;   ///< counter-clockwise from +x
  double azimuth_max_deg = 60.0;
};

/// What a target does from start_s on (until the next segment starts).
enum class MotionKind : std::uint8_t {
  kConstantVelocity,      ///< "cv": keep the current velocity
  kConstantAcceleration,  ///< "ca": accel_mps2 = (ax, ay)
  kCoordinatedTurn,       ///< "ct": turn_rate_deg_s (positive = counter-clockwise), constant speed
  kSetVelocity,           ///< "set_velocity": velocity jumps to velocity_mps at start_s, then CV
};

struct MotionSegment {
  double start_s = 0.0;                      ///< absolute time [s] (scan k is at (k-1)*T)
  MotionKind kind = MotionKind::kConstantVelocity;
  std::array<double, 2> accel_mps2{};        ///< (ax, ay) [m/s^2], kConstantAcceleration
  double turn_rate_deg_s = 0.0;              ///< [deg/s], kCoordinatedTurn
  std::array<double, 2> velocity_mps{};      ///< (vx, vy) [m/s], kSetVelocity
};

/// One target (spec 4.1 Table II). Before its first segment a target moves
/// at constant velocity.
struct TargetSpec {
  std::uint32_t id = 1;                      ///< >= 1, unique
  std::array<double, 4> initial_state{};     ///< [px m, vx m/s, py m, vy m/s] at the birth scan
  std::uint32_t birth_scan = 1;              ///< first scan it exists (inclusive)
  std::uint32_t death_scan = 1;              ///< last scan it exists (inclusive)
  double snr = 1.0;                          ///< mean SNR, linear (sigma in spec 2.5; power mean 1 + snr)
  Swerling swerling = Swerling::kOne;
  std::vector<MotionSegment> motion;         ///< sorted by start_s
};

/// Time variation of a clutter component over its lifetime (spec 4.4, P104):
/// with f = (k - birth) / (death - birth) in [0, 1],
///   mean count  lambda_k = (1 + count_sin_amplitude * sin(pi f)) * mean_count
///   covariance  Cov_k    = (cov_scale_start + (cov_scale_end - cov_scale_start) f) * Cov_0
///   mean        mu_k     = mu_0 + drift * (t_k - t_birth)
/// Scenario 3: count_sin_amplitude 0.5, cov_scale 1/3 -> 4/3, no drift.
struct TimeVariation {
  double count_sin_amplitude = 0.0;          ///< [-]
  double cov_scale_start = 1.0;              ///< [-]
  double cov_scale_end = 1.0;                ///< [-]
  double drift_range_mps = 0.0;              ///< [m/s]
  double drift_azimuth_deg_s = 0.0;          ///< [deg/s]
};

/// One clutter component (spec 4.3 Table III). The uniform one covers the
/// region; a Gaussian one is N(mean, cov) in (range, azimuth) space with
/// cov = [[sr^2, rho sr saz], [rho sr saz, saz^2]]. Per-scan counts are Poisson.
struct ClutterSpec {
  std::uint32_t id = 0;                      ///< unique (0 = the uniform one by convention)
  bool uniform = false;
  double mean_count = 0.0;                   ///< Poisson mean per scan [-]
  double mean_range_m = 0.0;                 ///< Gaussian only
  double mean_azimuth_deg = 0.0;             ///< Gaussian only
  double sigma_range_m = 0.0;                ///< Gaussian only
  double sigma_azimuth_deg = 0.0;            ///< Gaussian only
  double correlation = 0.0;                  ///< Gaussian only, in (-1, 1)
  double cnr = 1.0;                          ///< mean clutter-to-noise ratio, linear
  Swerling swerling = Swerling::kOne;
  std::uint32_t birth_scan = 1;
  std::uint32_t death_scan = 1;
  TimeVariation variation;
};

struct ScenarioSpec {
  std::string name;
  std::string description;
  std::uint32_t num_scans = 1;               ///< scans 1..num_scans
  double scan_period_s = 1.25;               ///< T [s]
  Region region;
  double sigma_range_m = 20.0;               ///< measurement noise std (spec 2.6)
  double sigma_azimuth_deg = 0.6;
  double threshold = 0.715;                  ///< amplitude detection threshold d (spec 4.2)
  std::uint32_t eval_first_scan = 1;         ///< evaluation interval [first, last] (inclusive)
  std::uint32_t eval_last_scan = 1;
  std::vector<TargetSpec> targets;
  std::vector<ClutterSpec> clutter;
};

/// Semantic checks (ranges, lifetimes, unique ids). Returns "" when valid,
/// otherwise "<field path>: <what is wrong>", e.g. "targets[1].snr: expected a
/// positive number" (the JSON loader uses the same paths).
std::string validate(const ScenarioSpec& spec);

/// Field-by-field equality (exact, bitwise on doubles' values).
bool operator==(const MotionSegment& a, const MotionSegment& b);
bool operator==(const TargetSpec& a, const TargetSpec& b);
bool operator==(const TimeVariation& a, const TimeVariation& b);
bool operator==(const ClutterSpec& a, const ClutterSpec& b);
bool operator==(const Region& a, const Region& b);
bool operator==(const ScenarioSpec& a, const ScenarioSpec& b);
inline bool operator!=(const ScenarioSpec& a, const ScenarioSpec& b) { return !(a == b); }

}  // namespace mptrack::scenario
