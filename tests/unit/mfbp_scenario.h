// Small deterministic scenario for the MF-BP tests (not a core header):
// two CV targets plus uniform clutter in the seed-000 surveillance region,
// generated with a fixed LCG and Box-Muller on dmath, so every platform
// produces the same scans bit for bit (double generation, then cast).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "mptrack/math/detmath.h"
#include "mptrack/measurement.h"

namespace mfbp_test {

/// SmallBoard's target, measurement and component caps with the paper's
/// window 7 (SmallBoardCaps itself stops at window 4 to fit 64 KiB).
struct TestCaps {
  static constexpr std::size_t kMaxTargets = 16;
  static constexpr std::size_t kMaxMeasurements = 64;
  static constexpr std::size_t kMaxClutterComponents = 4;
  static constexpr std::size_t kMaxWindow = 7;
};

/// 64-bit LCG (Knuth MMIX constants), uniform in (0, 1) from the top 53 bits.
struct Lcg {
  std::uint64_t s = 0x853c49e6748fea9bULL;
  double uniform() {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (static_cast<double>(s >> 11) + 0.5) * (1.0 / 9007199254740992.0);
  }
  double normal() {  // Box-Muller, one value per call
    const double u1 = uniform();
    const double u2 = uniform();
    return std::sqrt(-2.0 * mptrack::dmath::dlog(u1)) * mptrack::dmath::dcos(6.283185307179586 * u2);
  }
  std::size_t below(std::size_t n) { return static_cast<std::size_t>(uniform() * static_cast<double>(n)); }
};

struct Truth {
  double x[4];     ///< [px, vx, py, vy] at scan 0
  double snr;      ///< linear
};

constexpr double kPeriod = 1.25;
constexpr double kD = 0.715;
constexpr double kSigmaR = 20.0;
constexpr double kSigmaAz = 0.010471975511965976;

/// Two targets 2 km apart moving in parallel at 40 m/s, SNR 10 and 50/3.
inline void truth_at(int k, std::size_t i, double* pos) {
  static const Truth kTruth[2] = {{{18000.0, 40.0, 14000.0, -10.0}, 10.0},
                                  {{20000.0, 40.0, 14000.0, -10.0}, 50.0 / 3.0}};
  const double t = kPeriod * k;
  pos[0] = kTruth[i].x[0] + kTruth[i].x[1] * t;
  pos[1] = kTruth[i].x[2] + kTruth[i].x[3] * t;
}

inline double truth_snr(std::size_t i) { return i == 0 ? 10.0 : 50.0 / 3.0; }

/// Scan k: detections of both targets (Swerling I: power ~ Exp(1 + SNR),
/// detected iff power > d^2) and `clutter` uniform points with CNR 1.
template <class T, std::size_t N>
void make_scan(Lcg& rng, int k, std::size_t clutter, mptrack::Scan<T, N>& scan) {
  scan.time_us = static_cast<std::uint64_t>(static_cast<unsigned>(k)) * std::uint64_t{1250000} + std::uint64_t{1000000};
  scan.has_doppler = false;
  scan.measurements.clear();
  for (std::size_t i = 0; i < 2; ++i) {
    double p[2];
    truth_at(k, i, p);
    const double power = -(1.0 + truth_snr(i)) * mptrack::dmath::dlog(rng.uniform());
    const double nr = rng.normal();
    const double na = rng.normal();
    if (!(power > kD * kD)) continue;
    mptrack::Measurement<T> m;
    m.range_m = static_cast<T>(std::sqrt(p[0] * p[0] + p[1] * p[1]) + kSigmaR * nr);
    m.azimuth_rad = static_cast<T>(mptrack::dmath::datan2(p[1], p[0]) + kSigmaAz * na);
    m.amplitude = static_cast<T>(std::sqrt(power));
    (void)scan.measurements.push_back(m);
  }
  for (std::size_t c = 0; c < clutter; ++c) {
    mptrack::Measurement<T> m;
    m.range_m = static_cast<T>(10000.0 + 40000.0 * rng.uniform());
    m.azimuth_rad = static_cast<T>(0.17453292519943295 + 0.8726646259971648 * rng.uniform());
    m.amplitude = static_cast<T>(std::sqrt(kD * kD - 2.0 * mptrack::dmath::dlog(rng.uniform())));
    (void)scan.measurements.push_back(m);
  }
}

}  // namespace mfbp_test
