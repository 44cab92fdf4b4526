// Scenario generator: truth states and measurements per scan (docs/algorithms/scenarios.md
// §Measurement generation), reproducible from (seed, run): scan k of run r is drawn from
// its own RNG stream derive_seed(seed, r, k), so scans can be generated in
// any order, alone, with identical bits on every target.
//
// Per scan, in this fixed order (the order is part of the golden record):
//   1. every target alive at k (spec order): power u ~ Gamma(n, (1+snr)/n);
//      detected iff u > d^2; then y = h(x) + N(0, diag(sr, saz)^2), m = sqrt(u);
//   2. every clutter component alive at k (spec order): Poisson count, then
//      per point a position (uniform in the region, or N(mean, cov) in polar
//      space) and m = sqrt(u) with u ~ Gamma(n, (1+cnr)/n) given u > d^2;
//   3. points outside the region are dropped (counted);
//   4. a Fisher-Yates shuffle, so measurement order carries no information.
// Cartesian scenarios (seed 001) draw the same way with y = (px, py) +
// N(0, sigma_xy^2 I), clutter uniform over the x/y box or N(mean, cov) in
// x/y, and deliver each point as (range, azimuth) = (|y|, atan2). Clutter
// with a Weibull amplitude (docs/algorithms/models.md §Amplitude likelihoods) draws
// a^(2b) = d^(2b) + sigma0 E, E ~ Exp(1): the exact law given a > d (memorylessness).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "mptrack/measurement.h"
#include "mptrack/scenario/rng.h"
#include "mptrack/scenario/scenario_spec.h"
#include "mptrack/status.h"

namespace mptrack::scenario {

constexpr double kPi = 3.14159265358979323846264338327950288;
/// Degrees to radians; the one conversion every user of a spec must use.
constexpr double deg_to_rad(double deg) { return deg * (kPi / 180.0); }

/// Time of scan k (1-based) [s].
inline double scan_time_s(const ScenarioSpec& spec, std::uint32_t k) {
  return static_cast<double>(k - 1) * spec.scan_period_s;
}
/// Time of scan k [us], rounded to the nearest microsecond.
std::uint64_t scan_time_us(const ScenarioSpec& spec, std::uint32_t k);

/// Cartesian truth of one target [px m, vx m/s, py m, vy m/s] at time t_s,
/// by exact propagation through its motion segments from the birth scan.
struct KinematicState {
  double px = 0.0, vx = 0.0, py = 0.0, vy = 0.0;
};
KinematicState target_state_at(const ScenarioSpec& spec, const TargetSpec& target, double t_s);

inline bool alive(std::uint32_t birth, std::uint32_t death, std::uint32_t k) {
  return k >= birth && k <= death;
}

/// Clutter component parameters in effect at scan k (time variation and
/// drift applied), angles in radians.
struct ClutterAtScan {
  double mean_count = 0.0;
  double mean_range_m = 0.0;
  double mean_azimuth_rad = 0.0;
  double cov_rr = 0.0;        ///< [m^2]
  double cov_ra = 0.0;        ///< [m rad]
  double cov_aa = 0.0;        ///< [rad^2]
  double cnr = 0.0;
  // Cartesian scenarios (seed 001), Gaussian components only:
  double mean_x_m = 0.0;
  double mean_y_m = 0.0;
  double cov_xx = 0.0;        ///< [m^2]
  double cov_xy = 0.0;        ///< [m^2]
  double cov_yy = 0.0;        ///< [m^2]
};
ClutterAtScan clutter_at_scan(const ScenarioSpec& spec, const ClutterSpec& c, std::uint32_t k);

enum class OriginKind : std::uint8_t { kTarget, kClutter };

/// Where a measurement came from (for evaluation only; never shown to a tracker).
struct Origin {
  OriginKind kind = OriginKind::kClutter;
  std::uint32_t id = 0;   ///< target id or clutter component id
};

struct SimMeasurement {
  double range_m = 0.0;
  double azimuth_rad = 0.0;
  double amplitude = 0.0;  ///< sqrt(power / N0)
  Origin origin;
  double x_m = 0.0;        ///< Cartesian scenarios: the drawn position (range/azimuth are its polar form) [m]
  double y_m = 0.0;
  double doppler_mps = 0.0;  ///< OTHR scenarios: slant range rate [m/s] (range_m is the slant range)
  std::int32_t path = -1;    ///< OTHR scenarios: index of the path of a target detection, -1 otherwise
};

struct TruthState {
  std::uint32_t target_id = 0;
  KinematicState x;
  double snr = 0.0;
  bool detected = false;             ///< power above threshold at this scan
  bool in_region = false;            ///< its measurement (if detected) fell inside the region
  std::int32_t measurement_index = -1;  ///< index of its measurement in the shuffled scan, -1 if none
};

struct SimScan {
  std::uint32_t scan = 0;            ///< 1-based
  std::uint64_t time_us = 0;
  std::vector<TruthState> truth;     ///< targets alive at this scan, spec order
  std::vector<SimMeasurement> measurements;
  std::uint32_t dropped_outside_region = 0;
  bool has_doppler = false;          ///< doppler_mps is filled in (OTHR scenarios)
  // Seed 003 sea scenes (host-sim/src/run/sea_source.h), empty otherwise: per
  // measurement j, its range-Doppler patch (patch_size codes 0..255 from
  // patches[j * patch_size]) and the classifier features computed once per
  // detection and scan (feature_size floats from features[j * feature_size]),
  // shared by every tracker of the run.
  std::size_t patch_size = 0;
  std::vector<std::uint8_t> patches;
  std::size_t feature_size = 0;
  std::vector<float> features;
};

/// Options applied on top of a spec (Table V rows, clutter sweeps).
struct GeneratorOptions {
  double clutter_scale = 1.0;        ///< multiplies every mean clutter count (the sweep of
                                     ///< docs/algorithms/scenarios.md §Seed 000)
};

class Generator {
 public:
  /// Validates the spec (kInvalidArgument, message in error()) and stores a copy.
  Status init(const ScenarioSpec& spec, std::uint64_t seed, std::uint32_t run,
              const GeneratorOptions& options = {});

  /// Draws scan k (1..num_scans). kInvalidArgument if k is out of range or
  /// init() has not succeeded. Allocates (host-side std::vector).
  Status generate(std::uint32_t k, SimScan& out) const;

  const ScenarioSpec& spec() const { return spec_; }
  const std::string& error() const { return error_; }

 private:
  ScenarioSpec spec_;
  GeneratorOptions options_;
  std::uint64_t seed_ = 0;
  std::uint32_t run_ = 0;
  bool ready_ = false;
  std::string error_;
};

/// Copies a generated scan into a tracker input. Measurements past the cap
/// are not copied: returns kCapacityExceeded then (the first N are kept).
template <class T, std::size_t N>
Status to_scan(const SimScan& in, Scan<T, N>& out) {
  out.time_us = in.time_us;
  out.has_doppler = in.has_doppler;
  out.measurements.clear();
  Status st = Status::kOk;
  for (const SimMeasurement& m : in.measurements) {
    Measurement<T> y;
    y.range_m = static_cast<T>(m.range_m);
    y.azimuth_rad = static_cast<T>(m.azimuth_rad);
    y.amplitude = static_cast<T>(m.amplitude);
    y.doppler_mps = static_cast<T>(m.doppler_mps);
    if (out.measurements.push_back(y) != Status::kOk) st = Status::kCapacityExceeded;
  }
  return st;
}

}  // namespace mptrack::scenario
