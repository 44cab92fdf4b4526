// A small deterministic OTHR multipath scene for the multipath tracker's
// tests (seed 002 Sec. IV): targets move with constant ground-range rate and
// bearing rate, each is detected on each ionospheric path with probability
// pd, and uniform clutter fills the slant-coordinate box. Noise from an LCG
// with Irwin-Hall Gaussians; only + - * / sqrt and mptrack::dmath (through
// model/othr_measurement.h), so the scans are the same bits on every target.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "mptrack/measurement.h"
#include "mptrack/model/othr_measurement.h"
#include "mptrack/multipath/multipath_params.h"

namespace othr_scene {

struct Lcg {
  std::uint32_t state;
  double uniform() {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) * (1.0 / 16777216.0);
  }
  double gaussian() {
    double s = 0.0;
    for (int k = 0; k < 12; ++k) s += uniform();
    return s - 6.0;
  }
};

struct Target {
  mptrack::model::OthrState<double> x0;  ///< [g km, g_dot km/s, theta rad, theta_dot rad/s] at scan 0
  int first_scan = 0;                    ///< alive in [first_scan, last_scan]
  int last_scan = 1 << 30;
  mptrack::model::OthrState<double> at(int k, double dt_s) const {
    mptrack::model::OthrState<double> x = x0;
    const double t = dt_s * k;
    x(0) += x0(1) * t;
    x(2) += x0(3) * t;
    return x;
  }
};

/// Everything of a scene but its targets (no std::vector: the bare-metal
/// golden case builds one).
struct SceneConfig {
  mptrack::MultipathParams<double> geometry;  ///< paths, baseline, region, noise
  double pd = 0.75;
  double clutter_mean = 20.0;
  double dt_s = 16.0;
  std::uint32_t seed = 0x5eed0002u;
};

struct Scene : SceneConfig {
  std::vector<Target> targets;
};

/// The four targets of seed 002 Sec. IV (ground coordinates, scan 0 = k 1),
/// into a fixed table (the heap-free golden case uses it directly).
inline void seed002_target_table(Target (&t)[4]) {
  for (Target& x : t) {
    x.first_scan = 0;
    x.last_scan = 1 << 30;
  }
  t[0].x0 << 1700.0, 0.10, 0.48, 8.7e-5;
  t[1].x0 << 1750.0, 0.10, 0.48, 8.7e-5;
  t[2].x0 << 1850.0, 0.20, 0.54, 8.7e-5;
  t[3].x0 << 1915.0, -0.20, 0.54, 8.7e-5;
  t[0].last_scan = t[1].last_scan = 19;
  t[2].first_scan = t[3].first_scan = 9;
  t[2].last_scan = t[3].last_scan = 29;
}

/// The same four targets as a vector.
inline std::vector<Target> seed002_targets() {
  Target t[4];
  seed002_target_table(t);
  return std::vector<Target>(t, t + 4);
}

/// Poisson(mean) by inversion (mean up to a few hundred; exp by repeated products).
inline int poisson(double mean, Lcg& rng) {
  double l = 1.0;  // exp(-mean) computed as a product of exp(-1/16) steps
  const double step = 0.9394130628134758;  // exp(-1/16)
  for (double m = mean; m > 0.0; m -= 1.0 / 16.0) l *= (m >= 1.0 / 16.0) ? step : 1.0 - m;
  int k = 0;
  double p = rng.uniform();
  while (p > l && k < 10000) {
    p *= rng.uniform();
    ++k;
  }
  return k;
}

/// The scene's scans one at a time, without the heap (the bare-metal golden
/// case, tests/golden/cases/multipath.cpp): next() must be called for k = 0,
/// 1, 2, ... in order, since the noise comes from one running LCG.
class ScanMaker {
 public:
  ScanMaker(const Target* targets, std::size_t num_targets, const SceneConfig& s)
      : targets_(targets), num_targets_(num_targets), s_(s), rng_{s.seed} {}

  template <std::size_t N>
  void next(int k, mptrack::Scan<float, N>& scan) {
    const auto& g = s_.geometry;
    scan.measurements.clear();
    scan.time_us = 1000000ull + static_cast<std::uint64_t>(k) * static_cast<std::uint64_t>(s_.dt_s * 1e6);
    scan.has_doppler = true;
    auto push = [&](double r_km, double rd_kmps, double az) {
      if (r_km * 1e3 < g.region.range_min_m || r_km * 1e3 > g.region.range_max_m) return;
      if (az < g.region.azimuth_min_rad || az > g.region.azimuth_max_rad) return;
      if (rd_kmps * 1e3 > g.range_rate_span_mps || -rd_kmps * 1e3 > g.range_rate_span_mps) return;
      mptrack::Measurement<float> m;
      m.range_m = static_cast<float>(r_km * 1e3);
      m.doppler_mps = static_cast<float>(rd_kmps * 1e3);
      m.azimuth_rad = static_cast<float>(az);
      m.amplitude = 1.0f;
      static_cast<void>(scan.measurements.push_back(m));
    };
    for (std::size_t i = 0; i < num_targets_; ++i) {
      const Target& t = targets_[i];
      if (k < t.first_scan || k > t.last_scan) continue;
      const auto x = t.at(k, s_.dt_s);
      for (std::uint32_t p = 0; p < g.num_paths; ++p) {
        if (rng_.uniform() >= s_.pd) continue;
        const auto y = mptrack::model::othr_measure(x, g.paths[p], g.baseline_km);
        // Draws in a fixed order (azimuth, range rate, range): function
        // arguments are evaluated in an unspecified order, which differs
        // between compilers' targets (x86-64 and aarch64 gave different scenes).
        const double n_az = g.noise.azimuth_std_rad * rng_.gaussian();
        const double n_rd = g.noise.doppler_std_mps * 1e-3 * rng_.gaussian();
        const double n_r = g.noise.range_std_m * 1e-3 * rng_.gaussian();
        push(y(0) + n_r, y(1) + n_rd, y(2) + n_az);
      }
    }
    const int nc = poisson(s_.clutter_mean, rng_);
    for (int c = 0; c < nc; ++c) {
      const double r = g.region.range_min_m + (g.region.range_max_m - g.region.range_min_m) * rng_.uniform();
      const double rd = g.range_rate_span_mps * (2.0 * rng_.uniform() - 1.0);
      const double az = g.region.azimuth_min_rad + (g.region.azimuth_max_rad - g.region.azimuth_min_rad) * rng_.uniform();
      push(r * 1e-3, rd * 1e-3, az);
    }
  }

 private:
  const Target* targets_;
  std::size_t num_targets_;
  const SceneConfig& s_;
  Lcg rng_;
};

/// The scans of the scene, float, has_doppler set (range m, azimuth rad, doppler m/s).
template <std::size_t N>
std::vector<mptrack::Scan<float, N>> make_scans(const Scene& s, int num_scans) {
  std::vector<mptrack::Scan<float, N>> scans(static_cast<std::size_t>(num_scans));
  ScanMaker maker(s.targets.data(), s.targets.size(), s);
  for (int k = 0; k < num_scans; ++k) maker.next(k, scans[static_cast<std::size_t>(k)]);
  return scans;
}

}  // namespace othr_scene
