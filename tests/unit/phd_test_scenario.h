// Small deterministic Cartesian scenario for the IGGM baseline tests
// (seed 001 geometry): targets on straight lines in [-1000, 1000]^2 m,
// sigma = 10 m, SNR 100 (20 dB), threshold d = sqrt(ln 10) (P_FA 0.1),
// uniform Rayleigh clutter of unit power. Own 64-bit LCG so the tests do
// not depend on the scenario library; dmath keeps the data bit-identical
// on every target (the golden tests replay it).
#pragma once

#include <cmath>
#include <cstdint>

#include "mptrack/caps.h"
#include "mptrack/math/detmath.h"
#include "mptrack/measurement.h"
#include "mptrack/rfs/rfs_params.h"

namespace phdtest {

struct Lcg {
  std::uint64_t s;
  explicit Lcg(std::uint64_t seed) : s(seed * kMul + kInc) {}
  static constexpr std::uint64_t kMul = 6364136223846793005u;
  static constexpr std::uint64_t kInc = 1442695040888963407u;
  double uniform() {
    s = s * kMul + kInc;
    return (static_cast<double>(s >> 11) + 0.5) * (1.0 / 9007199254740992.0);
  }
  double normal() {  // Box-Muller, one output
    const double u1 = uniform();
    const double u2 = uniform();
    return std::sqrt(-2.0 * mptrack::dmath::dlog(u1)) * mptrack::dmath::dcos(6.283185307179586 * u2);
  }
};

constexpr double kThreshold = 1.5174271293851465;  // sqrt(ln 10)

struct Truth {
  double px, vx, py, vy;
};

/// Adds a Cartesian detection (x, y) with amplitude a as its polar form.
template <std::size_t N>
void add_xy(mptrack::Scan<double, N>& scan, double x, double y, double a) {
  mptrack::Measurement<double> m;
  m.range_m = std::sqrt(x * x + y * y);
  m.azimuth_rad = mptrack::dmath::datan2(y, x);
  m.amplitude = a;
  (void)scan.measurements.push_back(m);
}

/// Scan k (0-based) of a scenario with the given targets and clutter count
/// (Poisson-free: exactly `clutter` points, deterministic per seed).
template <std::size_t N>
void make_scan(mptrack::Scan<double, N>& scan, int k, const Truth* truths, int n_truths, int clutter,
               std::uint64_t seed) {
  Lcg rng(seed * 1000003u + static_cast<std::uint64_t>(k));
  scan.time_us = static_cast<std::uint64_t>(k) * 1000000u;
  scan.measurements.clear();
  const double d2 = kThreshold * kThreshold;
  for (int t = 0; t < n_truths; ++t) {
    const Truth& tr = truths[t];
    const double x = tr.px + tr.vx * k + 10.0 * rng.normal();
    const double y = tr.py + tr.vy * k + 10.0 * rng.normal();
    // Swerling I at SNR 100: power ~ Exp(101), detected iff > d^2.
    const double u = -101.0 * mptrack::dmath::dlog(rng.uniform());
    if (u > d2) add_xy(scan, x, y, std::sqrt(u));
  }
  for (int c = 0; c < clutter; ++c) {
    const double x = -1000.0 + 2000.0 * rng.uniform();
    const double y = -1000.0 + 2000.0 * rng.uniform();
    const double u = d2 - mptrack::dmath::dlog(rng.uniform());  // truncated Exp(1)
    add_xy(scan, x, y, std::sqrt(u));
  }
}

/// Seed 001 filter parameters for this scenario.
inline mptrack::RfsFilterParams<double> seed001_params() {
  mptrack::RfsFilterParams<double> p;
  p.amplitude.threshold = kThreshold;
  p.clutter_rate = 40.0;
  p.clutter_scale = 1.0;
  return p;
}

}  // namespace phdtest
