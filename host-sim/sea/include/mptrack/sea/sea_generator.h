// Pulse-level synthesis of one sea-clutter scene, scan by scan
// (docs/algorithms/sea_clutter.md §Scene model). Deterministic: a scene is a
// function of (scenario, seed) only; draws use mptrack::scenario::Rng
// (libm-free) and the core FFT, so every host gives the same samples.
#pragma once

#include <cstdint>
#include <vector>

#include "mptrack/dsp/fft.h"
#include "mptrack/scenario/rng.h"
#include "mptrack/sea/sea_scenario.h"

namespace mptrack::sea {

/// Truth of one target at the centre of a CPI.
struct SeaTruth {
  std::uint32_t id = 0;
  double range_m = 0.0;         ///< range at the CPI centre [m]
  double range_rate_mps = 0.0;  ///< dr/dt [m/s] (positive = receding)
  double doppler_hz = 0.0;      ///< -2 rdot / lambda [Hz] (seed 003 eq. (4))
  double range_bin = 0.0;       ///< range_m / range_bin_m
  double doppler_bin = 0.0;     ///< pulses/2 + doppler_hz / doppler_bin_hz (fftshifted index)
};

/// One CPI: complex baseband samples, planar, [range bin][pulse].
struct SeaScan {
  std::uint32_t index = 0;
  double time_s = 0.0;          ///< CPI start [s]
  std::vector<float> re, im;    ///< range_bins * pulses each
  double clutter_power = 0.0;   ///< P_c: mean clutter power over the CPI (all bins, pulses)
  double noise_power = 1.0;     ///< thermal noise power per sample
  std::vector<SeaTruth> truth;
};

class SeaSceneGenerator {
 public:
  /// Throws std::invalid_argument if the scenario does not validate or its
  /// pulse count is not 512 (the FFT size of the speckle synthesis).
  SeaSceneGenerator(const SeaScenario& scenario, std::uint64_t seed);

  /// Fills `out` with the next scan; false after num_scans scans.
  bool next(SeaScan& out);

  const SeaScenario& scenario() const { return sc_; }

 private:
  struct Target {
    double r0_m = 0.0, rdot_mps = 0.0, length_m = 0.0, phase_rad = 0.0, log_amp = 0.0;
  };
  void place_targets();
  void step_texture(std::uint32_t scan);
  void synthesize_clutter(SeaScan& out, double time_s);
  void inject_targets(SeaScan& out, double time_s);

  SeaScenario sc_;
  std::uint64_t seed_ = 0;
  std::uint32_t scan_ = 0;
  double drift_phase_rad_ = 0.0;
  std::vector<Target> targets_;
  std::vector<double> gauss_;    ///< texture Gaussian components [component][range bin]
  std::vector<double> texture_;  ///< tau per range bin, this scan
  dsp::Fft<512> fft_;
};

}  // namespace mptrack::sea
