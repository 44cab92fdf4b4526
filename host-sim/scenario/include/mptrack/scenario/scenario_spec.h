// ScenarioSpec: a measurement-level radar scenario as data (seed 000 Sec. IV-A;
// docs/algorithms/scenarios.md §Seed 000). The same structure is what
// host-sim/scenarios/*.json hold; fields are in the JSON's units (degrees for angles,
// linear SNR/CNR) so a JSON file loads to exactly these values and saves back unchanged.
// The generator converts degrees to radians when it draws measurements.
//
// Scan k (1-based) is at time t_k = (k - 1) * scan_period_s.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace mptrack::scenario {

/// Amplitude fluctuation model (docs/algorithms/models.md §Detection probability): the
/// received power u ~ Gamma(shape n, scale (1 + snr) / n), n = 1 for Swerling I, 2 for III.
enum class Swerling : std::uint8_t { kOne = 1, kThree = 3 };

/// Gamma shape n of a Swerling case (n = 1 for I, n = 2 for III; docs/algorithms/models.md
/// §Detection probability).
constexpr int swerling_shape(Swerling s) { return s == Swerling::kThree ? 2 : 1; }

/// Where measurements live. Seed 000 is polar (range, azimuth); seed 001
/// (seed 001 eq. (87)) is a Cartesian position sensor: z = (x, y) + N(0, sigma^2 I).
/// A Cartesian measurement is still delivered in the polar fields of
/// mptrack::Measurement (range = |z|, azimuth = atan2(y, x)); the trackers
/// that model a Cartesian sensor convert it back (phd/measurement_model.h).
/// kOthr (seed 002 Sec. IV): over-the-horizon radar, one detection per
/// target and ionospheric path in slant coordinates (range, range rate,
/// azimuth); targets move in ground coordinates (TargetSpec::ground_state).
enum class MeasurementSpace : std::uint8_t { kPolar, kCartesian, kOthr };

/// One ionospheric propagation path of an OTHR scenario (seed 002 Sec.
/// IV-A): virtual reflection heights of the transmit and receive legs, and
/// the probability that a target is detected through it in a scan.
struct OthrPathSpec {
  std::string name;            ///< e.g. "EE", "EF", "FE", "FF"
  double tx_height_km = 100.0;
  double rx_height_km = 100.0;
  double pd = 0.75;            ///< in (0, 1]
};

/// The OTHR geometry, the range-rate axis of the region and its noise.
/// The slant range and azimuth axes use Region and sigma_range_m /
/// sigma_azimuth_deg (slant range, azimuth zeta).
struct OthrSpec {
  double baseline_km = 100.0;                ///< receiver-transmitter distance d
  double range_rate_max_mps = 524.0;         ///< region: |slant range rate| <= this
  double sigma_range_rate_mps = 1.0;         ///< slant range-rate noise std
  std::vector<OthrPathSpec> paths;           ///< 1..8 paths
};

/// Surveillance region of a Cartesian scenario [m] (seed 001 Sec. 5:
/// [-1000, 1000]^2).
struct CartesianRegion {
  double x_min_m = -1000.0;
  double x_max_m = 1000.0;
  double y_min_m = -1000.0;
  double y_max_m = 1000.0;
};

/// Clutter amplitude law. kSwerling: power u ~ Gamma(n, (1 + cnr) / n) given u > d^2
/// (docs/algorithms/scenarios.md §Measurement generation). kWeibull: seed 001 eqs.
/// (41)-(44), p(a) = (2b / sigma0) a^(2b-1) exp(-a^(2b) / sigma0), given a > d; b = 1,
/// sigma0 = 1 is Rayleigh noise of unit power (normalised amplitudes).
enum class ClutterAmplitude : std::uint8_t { kSwerling, kWeibull };

/// Search region in measurement (polar) space, docs/algorithms/scenarios.md §Seed 000.
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

/// One target (seed 000 Table II). Before its first segment a target moves
/// at constant velocity.
struct TargetSpec {
  std::uint32_t id = 1;                      ///< >= 1, unique
  std::array<double, 4> initial_state{};     ///< [px m, vx m/s, py m, vy m/s] at the birth scan
  std::uint32_t birth_scan = 1;              ///< first scan it exists (inclusive)
  std::uint32_t death_scan = 1;              ///< last scan it exists (inclusive)
  double snr = 1.0;                          ///< mean SNR, linear (power mean 1 + snr; sigma in
                                             ///< docs/algorithms/models.md §Inverse-gamma power belief)
  Swerling swerling = Swerling::kOne;
  std::vector<MotionSegment> motion;         ///< sorted by start_s
  /// OTHR scenarios only: [g km, g_dot km/s, theta rad, theta_dot rad/s] at
  /// the birth scan, constant rates in ground range and bearing (seed 002
  /// Sec. IV); initial_state and motion are then unused.
  std::array<double, 4> ground_state{};
};

/// Time variation of a clutter component over its lifetime (seed 000 eq. (104);
/// docs/algorithms/scenarios.md §Seed 000):
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

/// One clutter component (seed 000 Table III). The uniform one covers the
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
  // --- additions for Cartesian scenarios and Weibull clutter (seed 001) ---
  double mean_x_m = 0.0;                     ///< Cartesian Gaussian only: mean x [m]
  double mean_y_m = 0.0;                     ///< Cartesian Gaussian only: mean y [m]
  double sigma_x_m = 0.0;                    ///< Cartesian Gaussian only: std along x [m] (correlation shared)
  double sigma_y_m = 0.0;                    ///< Cartesian Gaussian only: std along y [m]
  ClutterAmplitude amplitude = ClutterAmplitude::kSwerling;
  double weibull_shape = 1.0;                ///< kWeibull: b [-] (seed 001: 0.8; 1 = Rayleigh)
  double weibull_scale = 1.0;                ///< kWeibull: sigma0, normalised amplitude units [-]
};

struct ScenarioSpec {
  std::string name;
  std::string description;
  std::uint32_t num_scans = 1;               ///< scans 1..num_scans
  double scan_period_s = 1.25;               ///< T [s]
  Region region;
  double sigma_range_m = 20.0;               ///< measurement noise std (seed 000 Sec. IV-A)
  double sigma_azimuth_deg = 0.6;
  double threshold = 0.715;                  ///< amplitude detection threshold d (seed 000 Sec. IV-A)
  std::uint32_t eval_first_scan = 1;         ///< evaluation interval [first, last] (inclusive)
  std::uint32_t eval_last_scan = 1;
  std::vector<TargetSpec> targets;
  std::vector<ClutterSpec> clutter;
  // --- additions for Cartesian scenarios (seed 001); unused when polar ---
  MeasurementSpace space = MeasurementSpace::kPolar;
  CartesianRegion xy_region;                 ///< Cartesian: surveillance region [m]
  double sigma_xy_m = 10.0;                  ///< Cartesian: position noise std per axis [m] (seed 001: 10)
  // --- additions for OTHR scenarios (seed 002); unused otherwise ---
  OthrSpec othr;
};

/// Semantic checks (ranges, lifetimes, unique ids). Returns "" when valid,
/// otherwise "<field path>: <what is wrong>", e.g. "targets[1].snr: expected a
/// positive number" (the JSON loader uses the same paths).
std::string validate(const ScenarioSpec& spec);

/// Largest clutter Poisson mean per scan a scenario may ask for (times
/// --clutter-scale: GeneratorOptions): above it a scan's draw alone is
/// unbounded work, and no tracker's caps come near it.
inline constexpr double kMaxClutterMeanCount = 1e6;

/// Expected measurements per scan at the largest clutter mean: every clutter
/// component's mean_count x (1 + |count_sin_amplitude|) x clutter_scale plus
/// one per target (per propagation path for OTHR). The harness refuses a
/// scenario whose figure exceeds the trackers' caps by far.
double expected_measurements_per_scan(const ScenarioSpec& spec, double clutter_scale);

/// Field-by-field equality (exact, bitwise on doubles' values).
bool operator==(const MotionSegment& a, const MotionSegment& b);
bool operator==(const TargetSpec& a, const TargetSpec& b);
bool operator==(const TimeVariation& a, const TimeVariation& b);
bool operator==(const ClutterSpec& a, const ClutterSpec& b);
bool operator==(const Region& a, const Region& b);
bool operator==(const CartesianRegion& a, const CartesianRegion& b);
bool operator==(const OthrPathSpec& a, const OthrPathSpec& b);
bool operator==(const OthrSpec& a, const OthrSpec& b);
bool operator==(const ScenarioSpec& a, const ScenarioSpec& b);
inline bool operator!=(const ScenarioSpec& a, const ScenarioSpec& b) { return !(a == b); }

}  // namespace mptrack::scenario
