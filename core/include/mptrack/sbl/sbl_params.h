// Caps and run-time tunables of the per-frame SBL detector (the detector of
// seed 004's detect-then-track baseline; docs/algorithms/sbl.md). Units and
// defaults in the comments; defaults reproduce seed 004's scenario on the
// 32 MHz sampling path (docs/algorithms/frontend.md §Departures from the paper).
#pragma once

#include <cstddef>

#include "mptrack/math/constants.h"
#include "mptrack/status.h"
#include "mptrack/validate.h"

namespace mptrack {

/// Compile-time capacities of SblDetector.
struct SblDefaultCaps {
  static constexpr std::size_t kMaxComponents = 8;  ///< components (detections) per frame
  static constexpr std::size_t kMaxRangeCells = 96;  ///< residual-map range cells (100 m at 1.17 m: 86)
  static constexpr std::size_t kMaxAngleCells = 64;  ///< residual-map cells in sin theta (step 1/32: 64)
  static constexpr std::size_t kMaxIterations = 50;  ///< ceiling on SblParams::max_iterations
};

template <class Caps>
constexpr bool sbl_caps_are_valid() {
  static_assert(Caps::kMaxComponents >= 1 && Caps::kMaxComponents <= 32, "1 <= kMaxComponents <= 32");
  static_assert(Caps::kMaxRangeCells >= 1 && Caps::kMaxAngleCells >= 1, "the residual map needs a cell");
  static_assert(Caps::kMaxIterations >= 1, "at least one joint iteration");
  return true;
}

/// Waveform, array, target model, search region and SBL iteration settings.
struct SblParams {
  // Waveform and receiver (seed 004 Sec. V-A; same names as adc::RadarSpec).
  double carrier_hz = 10e9;                  ///< f_c [Hz]; lambda = c / f_c
  double bandwidth_hz = 20e6;                ///< chirp sweep BW [Hz]
  double chirp_duration_s = 3.6e-6;          ///< T_Tx [s]
  double sample_rate_hz = 32e6;              ///< complex fast-time sample rate f_s [Hz]
  double element_spacing_wavelengths = 0.5;  ///< virtual ULA spacing d / lambda [-], (0, 1]
  double noise_variance_v2 = 1.380649e-23 * 290.0 * 32e6;  ///< sigma_w^2 per complex sample [V^2]
                                                           ///< (model A: k_b T0 f_s)
  // Target model: only sets the scale rho~ of the atoms (a per-frame constant; the
  // amplitude itself is estimated), so the estimated amplitude has E|alpha'|^2 = 1 at
  // the mean RCS (docs/algorithms/sbl.md §Signal model).
  double tx_amplitude = 0.53;                ///< A in rho(r) = A G lambda / ((4 pi)^1.5 r^2) [V/m]
  double antenna_gain = 1.0;                 ///< G [-]
  double mean_rcs_m2 = 0.05;                 ///< E[sigma_RCS] [m^2]
  // Search region (the residual map grid) and output gate.
  double min_range_m = 3.0;                  ///< range gate lower end [m], > 0
  double max_range_m = 100.0;                ///< range gate upper end [m] (seed 004: R_max)
  double max_abs_bearing_rad = 1.3089969389957472;  ///< |theta| <= this [rad], (0, 1.5]; 75 deg
  double range_step_m = 1.17;                ///< residual-map range step [m] (1024-point IFFT grid)
  double sin_step = 0.03125;                 ///< residual-map step in sin theta [-] (64 beams)
  // SBL (docs/algorithms/sbl.md §Algorithm).
  double eta = 12.8;                         ///< threshold on the normalised residual peak and on
                                             ///< the component SNR [-]: ln(N_eff / P_FA),
                                             ///< N_eff = 360, P_FA = 1e-3 per frame
  std::size_t max_components = 8;            ///< detections per frame (<= Caps::kMaxComponents)
  std::size_t max_iterations = 20;           ///< joint iterations (amplitudes + one joint
                                             ///< Gauss-Newton step) per addition (<= Caps::kMaxIterations)
  std::size_t gauss_newton_steps = 8;        ///< Gauss-Newton steps of a new component's refinement, 1..32
  double tolerance_m = 1e-3;                 ///< joint iterations stop when no position moved more [m]
  double max_step_m = 1.0;                   ///< Gauss-Newton step cap [m], > 0
  double max_abs_sample = 1e6;               ///< float cubes: |re| or |im| above this refuses the
                                             ///< frame [cube units], in [1e-6, 1e9] (as the front end)

  /// Every field on its own; the fit to the caps is SblDetector::validate()'s.
  /// On failure names the field in *where (validate.h).
  Status validate(ParamError* where = nullptr) const {
    MPTRACK_CHECK_PARAM(where, "carrier_hz", check_carrier_hz(carrier_hz));
    MPTRACK_CHECK_PARAM(where, "bandwidth_hz", check_positive(bandwidth_hz));
    MPTRACK_CHECK_PARAM(where, "chirp_duration_s", check_positive(chirp_duration_s));
    MPTRACK_CHECK_PARAM(where, "sample_rate_hz", check_positive(sample_rate_hz));
    MPTRACK_CHECK_PARAM(where, "element_spacing_wavelengths", check_range(element_spacing_wavelengths, 1e-3, 1.0));
    MPTRACK_CHECK_PARAM(where, "noise_variance_v2", check_range(noise_variance_v2, 1e-30, 1e30));
    MPTRACK_CHECK_PARAM(where, "tx_amplitude", check_range(tx_amplitude, 1e-12, 1e12));
    MPTRACK_CHECK_PARAM(where, "antenna_gain", check_range(antenna_gain, 1e-12, 1e12));
    MPTRACK_CHECK_PARAM(where, "mean_rcs_m2", check_range(mean_rcs_m2, 1e-12, 1e12));
    MPTRACK_CHECK_PARAM(where, "min_range_m", check_range(min_range_m, 0.1, 1e5));
    MPTRACK_CHECK_PARAM(where, "max_range_m", check_above(max_range_m, min_range_m, "min_range_m"));
    MPTRACK_CHECK_PARAM(where, "max_abs_bearing_rad", check_range(max_abs_bearing_rad, 1e-3, 1.5));
    MPTRACK_CHECK_PARAM(where, "range_step_m", check_range(range_step_m, 1e-3, 1e3));
    MPTRACK_CHECK_PARAM(where, "sin_step", check_range(sin_step, 1e-4, 1.0));
    MPTRACK_CHECK_PARAM(where, "eta", check_range(eta, 1e-3, 1e6));
    MPTRACK_CHECK_PARAM(where, "max_components", check_at_least(max_components, 1));
    MPTRACK_CHECK_PARAM(where, "max_iterations", check_at_least(max_iterations, 1));
    MPTRACK_CHECK_PARAM(where, "gauss_newton_steps", check_range(gauss_newton_steps, 1, 32));
    MPTRACK_CHECK_PARAM(where, "tolerance_m", check_range(tolerance_m, 1e-9, 10.0));
    MPTRACK_CHECK_PARAM(where, "max_step_m", check_range(max_step_m, 1e-3, 100.0));
    MPTRACK_CHECK_PARAM(where, "max_abs_sample", check_range(max_abs_sample, 1e-6, 1e9));
    return Status::kOk;
  }
};

}  // namespace mptrack
