// Test-side scenes for the SBL detector tests (not part of core): seed 004
// echoes at the radar-equation amplitude, synthesised sample by sample by the
// front-end test synthesiser (deterministic on every target).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "frontend_test_signals.h"
#include "mptrack/frontend/frontend_params.h"
#include "mptrack/frontend/radar_cube.h"
#include "mptrack/sbl/sbl_params.h"

namespace mptrack::test {

/// One echo at (x, y) [m] whose whitened amplitude is alpha' = gain e^{j phase}
/// (gain 1: the mean RCS, docs/algorithms/sbl.md §Signal model).
struct SblEcho {
  double x_m = 0.0, y_m = 30.0;
  double gain = 1.0;
  double phase_rad = 0.0;
};

/// Echo amplitude per sample [V] of a mean-RCS target at range r:
/// sqrt(E sigma) A G lambda / ((4 pi)^1.5 r^2).
inline double sbl_echo_volts(const mptrack::SblParams& p, double r_m) {
  const double lambda = mptrack::frontend::kSpeedOfLight_mps / p.carrier_hz;
  const double four_pi = 4.0 * mptrack::dmath::kPi<double>;
  return std::sqrt(p.mean_rcs_m2) * p.tx_amplitude * p.antenna_gain * lambda /
         (four_pi * std::sqrt(four_pi) * r_m * r_m);
}

/// The front-end parameters with the same waveform as p (for the synthesiser).
inline mptrack::frontend::FrontEndParams sbl_waveform(const mptrack::SblParams& p) {
  mptrack::frontend::FrontEndParams f;
  f.carrier_hz = p.carrier_hz;
  f.bandwidth_hz = p.bandwidth_hz;
  f.chirp_duration_s = p.chirp_duration_s;
  f.sample_rate_hz = p.sample_rate_hz;
  f.element_spacing_wavelengths = p.element_spacing_wavelengths;
  return f;
}

/// Fills cube with the echoes plus CN(0, noise_variance_v2) noise if `noise`.
template <class Caps>
void sbl_scene(const mptrack::SblParams& p, const SblEcho* echoes, std::size_t n, bool noise, std::uint64_t seed,
               mptrack::frontend::RadarCube<Caps>& cube) {
  SynthTarget t[8];
  for (std::size_t i = 0; i < n && i < 8; ++i) {
    const double r = std::sqrt(echoes[i].x_m * echoes[i].x_m + echoes[i].y_m * echoes[i].y_m);
    t[i].range_m = r;
    t[i].bearing_rad = mptrack::dmath::datan2(echoes[i].x_m, echoes[i].y_m);
    t[i].amplitude = echoes[i].gain * sbl_echo_volts(p, r);
    t[i].phase_rad = echoes[i].phase_rad;
  }
  synthesize<Caps>(sbl_waveform(p), t, n < 8 ? n : 8, noise ? p.noise_variance_v2 : 0.0, seed, cube);
}

}  // namespace mptrack::test
