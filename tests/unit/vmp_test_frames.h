// Tiny deterministic raw-frame generator for the VMP tests and golden: point
// echoes of the seed 004 chirp on the centred 3 x 3 virtual array (the same
// signal model as host-sim/adc's FrameSynthesizer, written again here so core
// tests need no host-sim) plus white complex Gaussian noise from an LCG and
// an Irwin-Hall sum. Only + - * /, sqrt and mptrack::dmath: the same bits on
// every target, so the golden's input is bit-identical under qemu.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "mptrack/frontend/radar_cube.h"
#include "mptrack/math/detmath.h"
#include "mptrack/vmp/vmp_params.h"

namespace vmp_test {

using Caps = mptrack::frontend::Seed004RadarCaps;
using Cube = mptrack::frontend::RadarCube<Caps>;

struct Lcg {
  std::uint32_t state;
  double uniform() {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) * (1.0 / 16777216.0);
  }
  /// Approximately N(0, 1): Irwin-Hall sum of 12 uniforms.
  double gaussian() {
    double s = 0.0;
    for (int k = 0; k < 12; ++k) s += uniform();
    return s - 6.0;
  }
};

/// sqrt(mean RCS) rho(r) [V] of VmpParams p at range r [m] (the radar equation).
inline double echo_amplitude(const mptrack::VmpParams& p, double r) {
  const double lambda = 299792458.0 / p.carrier_hz;
  const double four_pi = 4.0 * mptrack::dmath::kPi<double>;
  return std::sqrt(p.mean_rcs_m2) * p.tx_amplitude * p.antenna_gain * lambda / (four_pi * std::sqrt(four_pi) * r * r);
}

/// Adds the echo of a point at (x, y) [m] with complex amplitude gain g (times
/// echo_amplitude) to the cube.
inline void add_echo(const mptrack::VmpParams& p, double x, double y, double g_re, double g_im, Cube& cube) {
  constexpr double kPi = mptrack::dmath::kPi<double>;
  const double r = std::sqrt(x * x + y * y);
  const double u = x / r;
  const double tau = 2.0 * r / 299792458.0;
  const double fs = p.sample_rate_hz;
  const double kappa = p.bandwidth_hz / p.chirp_duration_s;
  const std::size_t len = static_cast<std::size_t>(p.chirp_duration_s * fs + 0.5);
  const double t_mid = 0.5 * static_cast<double>(len - 1) / fs;
  const double a = echo_amplitude(p, r);
  for (std::size_t v = 0; v < 9; ++v) {
    const double ph_v = 2.0 * kPi * p.element_spacing_wavelengths * (static_cast<double>(v) - 4.0) * u;
    for (std::size_t i = 0; i < Caps::kNumSamples; ++i) {
      const double t = static_cast<double>(i) / fs - tau;
      if (t < -0.5 / fs || !(t < (static_cast<double>(len) - 0.5) / fs)) continue;
      double s = 0.0;
      double c = 1.0;
      mptrack::dmath::dsincos(kPi * kappa * (t - t_mid) * (t - t_mid) + ph_v, s, c);
      const std::size_t o = Cube::offset(0, v / 3, v % 3, i);
      cube.iq[o] += static_cast<float>(a * (g_re * c - g_im * s));
      cube.iq[o + 1] += static_cast<float>(a * (g_re * s + g_im * c));
    }
  }
}

/// Adds CN(0, noise_variance_v2) to every sample.
inline void add_noise(const mptrack::VmpParams& p, Lcg& rng, Cube& cube) {
  const double sd = std::sqrt(0.5 * p.noise_variance_v2);
  for (float& x : cube.iq) x += static_cast<float>(sd * rng.gaussian());
}

inline void clear(Cube& cube, std::uint64_t time_us) {
  cube.time_us = time_us;
  for (float& x : cube.iq) x = 0.0f;
}

}  // namespace vmp_test
