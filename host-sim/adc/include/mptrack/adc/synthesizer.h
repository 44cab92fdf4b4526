// Raw-ADC frame synthesizer for the seed 004 MIMO radar (seed 004 eq. (1)).
//
// Per frame n, Tx slot m, Rx j (virtual channel v = 3m + j), sample i at
// t_i = i / f_s within the slot:
//   y[m][j][i] = sum_l alpha_l a_v(theta_l) u(t_i - tau_l) + jam_v[m][i] + w[m][j][i]
// - u(t) = exp(j pi kappa (t - t_mid)^2) for t in [-1/(2 f_s), (L - 1/2)/f_s),
//   L = round(T_Tx f_s), t_mid = (L-1)/(2 f_s), kappa = BW/T_Tx: the same
//   sampled chirp the front end correlates with, so a zero-delay echo is
//   exactly its reference and range bin g <-> delay g / f_s;
// - tau = 2r/c; a_v(theta) = exp(j 2 pi d (v - 4) sin theta) (centred
//   reference); the carrier phase is absorbed in alpha (both: docs/algorithms/scenarios.md
//   §Seed 004);
// - alpha = sqrt(sigma) rho(r) exp(j phi), rho(r) = A G lambda/((4 pi)^1.5 r^2),
//   sigma ~ Gamma(shape, E[sigma]/shape) per frame (Swerling 1: shape 1,
//   Swerling 3: shape 2), phi uniform;
// - w ~ CN(0, sigma_w^2) i.i.d.: sigma_w^2 = k_b T0 f_s (model A) or k_b T0 BW;
// - the jammer is CN(0, J/Q) per source and sample, times a_v(theta_q).
// Samples are in volts (float). Clutter and chaff scatterers are point
// echoes too, with Swerling-1 amplitudes.
//
// Determinism: frame n of run r draws from the stream derive_seed(seed, r, n);
// scatterer layouts from derive_seed(seed ^ kLayoutTag, r, 0). Frames can be
// synthesised in any order, alone. Host-only: allocates in init().
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "mptrack/adc/adc_scenario.h"
#include "mptrack/adc/trajectory.h"
#include "mptrack/frontend/radar_caps.h"
#include "mptrack/frontend/radar_cube.h"
#include "mptrack/status.h"

namespace mptrack::adc {

using AdcCaps = frontend::Seed004RadarCaps;
using AdcCube = frontend::RadarCube<AdcCaps>;

/// Truth of one drone at one frame (what the evaluation compares against).
struct DroneTruth {
  std::uint32_t id = 0;
  DroneState state;
  double range_m = 0.0;
  double bearing_rad = 0.0;   ///< from +y towards +x
  double rcs_m2 = 0.0;        ///< this frame's Swerling draw
  double snr_mean = 0.0;      ///< mean component SNR at this range, linear
                              ///< (docs/algorithms/scenarios.md §Seed 004)
};

/// Options for tests and studies (defaults = the scenario as written).
struct SynthOptions {
  bool noise = true;          ///< thermal noise on/off
  bool fluctuate = true;      ///< false: every RCS equals its mean, phase 0 (deterministic echoes)
};

class FrameSynthesizer {
 public:
  /// Validates the scenario and lays out clutter/chaff scatterers for `run`.
  /// kInvalidArgument with error() set on a bad scenario.
  Status init(const AdcScenario& s, std::uint64_t seed, std::uint32_t run, const SynthOptions& opt = {});

  /// Synthesises frame n (1..num_frames) into cube (time_us = (n-1) dt) and
  /// the alive drones' truth into truth (cleared first).
  Status synthesize(std::uint32_t frame, AdcCube& cube, std::vector<DroneTruth>& truth) const;

  /// Adds one point echo of complex amplitude (amp_re, amp_im) [V] at
  /// (range, bearing) to the cube: the building block of synthesize().
  void add_echo(AdcCube& cube, double range_m, double bearing_rad, double amp_re, double amp_im) const;

  double noise_variance() const { return noise_var_; }   ///< sigma_w^2 per complex sample [V^2]
  double wavelength_m() const { return lambda_m_; }
  std::size_t chirp_samples() const { return chirp_len_; }
  /// Two-way amplitude gain rho(r) [V per sqrt(m^2)].
  double range_gain(double range_m) const;
  const std::string& error() const { return error_; }
  const AdcScenario& scenario() const { return spec_; }

 private:
  struct Scatterer {
    double x = 0.0, y = 0.0;  ///< patch: absolute position; chaff: unit-normal offsets
  };
  AdcScenario spec_;
  SynthOptions opt_;
  std::uint64_t seed_ = 0;
  std::uint32_t run_ = 0;
  double noise_var_ = 0.0;
  double lambda_m_ = 0.0;
  double kappa_ = 0.0;
  double t_mid_s_ = 0.0;
  std::size_t chirp_len_ = 0;
  std::vector<std::vector<Scatterer>> patches_;
  std::vector<std::vector<Scatterer>> chaff_;
  std::string error_;
  bool ready_ = false;
};

}  // namespace mptrack::adc
