// Run-time tunables of the MIMO front end (README.md §Conventions a
// firmware engineer can rely on): units and defaults in the comments,
// validated once by FrontEnd::init() (FrontEnd::validate(): these fields,
// then the radar caps). Defaults reproduce seed 004
// (docs/algorithms/frontend.md §Departures from the paper: the 32 MHz
// decimated path).
#pragma once

#include <cstddef>
#include <cstdint>

#include "mptrack/frontend/reference_chirp.h"
#include "mptrack/frontend/window.h"
#include "mptrack/math/constants.h"
#include "mptrack/status.h"
#include "mptrack/validate.h"

namespace mptrack::frontend {

/// Speed of light [m/s] (exact, SI definition).
inline constexpr double kSpeedOfLight_mps = 299792458.0;

/// CFAR variants (Richards, Fundamentals of Radar Signal Processing, 6.5;
/// Gandhi & Kassam 1988 for GO/SO; Rohling 1983 for OS).
enum class CfarType : std::uint8_t {
  kCellAveraging = 0,  ///< CA: noise = mean of all 2T training cells
  kGreatestOf,         ///< GO: noise = max(mean left, mean right); robust at clutter edges
  kSmallestOf,         ///< SO: noise = min(mean left, mean right); resolves close targets
  kOrderedStatistic,   ///< OS: noise = k-th smallest training cell / E[k-th of 2T Exp(1)]
};

/// What happens where the training window runs past either end of a line.
enum class CfarEdge : std::uint8_t {
  kSkip = 0,  ///< cells without a full window on both sides are not tested
  kShift,     ///< the missing training cells are taken from the other side, so every
              ///< cell sees exactly 2T training cells and the same threshold (same Pfa)
  kWrap,      ///< circular indexing (only meaningful for periodic axes)
};

/// CFAR configuration. Detection: cell power > alpha * noise estimate, with
/// alpha solved in init() so that the false-alarm probability per tested
/// cell in homogeneous complex Gaussian noise (exponential power) equals pfa.
struct CfarParams {
  CfarType type = CfarType::kCellAveraging;  ///< variant
  CfarEdge edge = CfarEdge::kShift;          ///< edge policy
  std::size_t guard_cells = 2;               ///< guard cells per side [cells], 0..64
  std::size_t training_cells = 8;            ///< training cells per side T [cells], 1..64
  double pfa = 1e-4;                         ///< false-alarm probability per tested cell, (0, 0.5]
  std::size_t os_rank = 0;                   ///< OS rank k in 1..2T; 0 = round(3/4 * 2T)

  /// Cells a line needs for one full window: 2 (guard + training) + 1.
  std::size_t min_line_length() const { return 2 * (guard_cells + training_cells) + 1; }

  /// Validates CfarParams in isolation (line length checked by the user of
  /// it); on failure names the field ("cfar.<name>") in *where.
  Status validate(ParamError* where = nullptr) const {
    MPTRACK_CHECK_PARAM(where, "cfar.type",
                        check(type == CfarType::kCellAveraging || type == CfarType::kGreatestOf ||
                              type == CfarType::kSmallestOf || type == CfarType::kOrderedStatistic));
    MPTRACK_CHECK_PARAM(where, "cfar.edge",
                        check(edge == CfarEdge::kSkip || edge == CfarEdge::kShift || edge == CfarEdge::kWrap));
    MPTRACK_CHECK_PARAM(where, "cfar.guard_cells", check_at_most(guard_cells, 64));
    MPTRACK_CHECK_PARAM(where, "cfar.training_cells", check_range(training_cells, 1, 64));
    MPTRACK_CHECK_PARAM(where, "cfar.pfa", check_range(pfa, 1e-300, 0.5));
    MPTRACK_CHECK_PARAM(where, "cfar.os_rank", check(os_rank <= 2 * training_cells));
    return Status::kOk;
  }
};

/// Waveform, array and processing parameters.
struct FrontEndParams {
  // Waveform (seed 004 Sec. V-A; docs/algorithms/frontend.md §Signal model).
  double carrier_hz = 10e9;            ///< carrier f_c [Hz]; lambda = c / f_c
  double bandwidth_hz = 20e6;          ///< chirp sweep BW [Hz] (-BW/2 .. +BW/2)
  double chirp_duration_s = 3.6e-6;    ///< chirp length T_Tx [s]
  double sample_rate_hz = 32e6;        ///< complex fast-time sample rate f_s [Hz]
  double chirp_repetition_s = 24e-6;   ///< same-Tx chirp interval T_c [s] (Doppler sampling;
                                       ///< TDM: N_T * slot, 3 * 8 us)
  // Array (docs/algorithms/frontend.md §Frame input and checks).
  double element_spacing_wavelengths = 0.5;  ///< virtual ULA spacing d / lambda [-], (0, 1]
  // Processing.
  bool remove_dc = false;              ///< subtract each profile's complex mean before the MF
                                       ///< (Tx->Rx leakage / DC offset,
                                       ///< docs/algorithms/frontend.md §Range matched filter)
  WindowType range_window = WindowType::kRectangular;   ///< taper on the matched-filter reference
  WindowType doppler_window = WindowType::kHann;        ///< taper across chirps
  WindowType angle_window = WindowType::kRectangular;   ///< taper across virtual channels
  double max_abs_bearing_rad = 1.0471975511965976;      ///< angle grid span |theta| <= this [rad],
                                                        ///< (0, pi/2]; default 60 deg
  double min_range_m = 0.0;            ///< range gate lower end [m] (bins below not tested)
  double max_range_m = 100.0;          ///< range gate upper end [m] (seed 004 Sec. V-A: R_max)
  CfarParams cfar{};                   ///< detector along the range axis
  std::size_t max_detections = 64;     ///< per-frame cap (<= Caps::kMaxDetections; the Scan
                                       ///< capacity also caps it)
  double min_noise_power = 1e-30;      ///< floor on the CFAR noise estimate [map power units],
                                       ///< keeps amplitudes finite on noiseless data; >= 0
  bool sidelobe_grouping = true;       ///< drop a candidate that a stronger one's range or angle
                                       ///< sidelobes explain (sidelobe_filter.h)
  double sidelobe_margin_db = 3.0;     ///< margin over the sidelobe envelope for the noise on a
                                       ///< sidelobe [dB], in [0, 30]
  std::size_t angle_refine_iterations = 24;  ///< golden-section steps of the steering-vector MF,
                                             ///< 0 = grid angle only, <= 64
  // Frame-level input checks (docs/reliability.md F2 and "ADC frames").
  double max_abs_sample = 1e6;         ///< float cubes: a frame with |re| or |im| above this is
                                       ///< refused (kInvalidInput) [cube units], in [1e-6, 1e9].
                                       ///< Beyond ~1e15 the float power map overflows to Inf (F2);
                                       ///< 1e6 is 1e6 times int16 full scale.
  double saturation_fraction = 0.01;   ///< int16 cubes: a frame with more than this fraction of
                                       ///< its sample values at full scale (-32768 or 32767) is
                                       ///< flagged saturated (processed, kPartial) [-], in [0, 1]
  std::size_t adc_bits = 16;           ///< int16 cubes: ADC resolution [bits], 2..16. Codes are
                                       ///< left-justified (code / 32768 = fraction of full scale),
                                       ///< so the rails are -32768 and 32768 - 2^(16 - adc_bits)

  /// Every field on its own; the fit to the radar caps (chirp length,
  /// range gate, CFAR window, max_detections) is FrontEnd::validate()'s.
  /// On failure names the field in *where (validate.h).
  Status validate(ParamError* where = nullptr) const {
    MPTRACK_CHECK_PARAM(where, "carrier_hz", check_carrier_hz(carrier_hz));
    MPTRACK_CHECK_PARAM(where, "bandwidth_hz", check_positive(bandwidth_hz));
    MPTRACK_CHECK_PARAM(where, "chirp_duration_s", check_positive(chirp_duration_s));
    MPTRACK_CHECK_PARAM(where, "sample_rate_hz", check_positive(sample_rate_hz));
    MPTRACK_CHECK_PARAM(where, "chirp_repetition_s", check_range(chirp_repetition_s, 1e-9, 1.0));  // F15: 1 ns .. 1 s
    MPTRACK_CHECK_PARAM(where, "element_spacing_wavelengths", check_range(element_spacing_wavelengths, 1e-3, 1.0));
    MPTRACK_CHECK_PARAM(where, "range_window", check(is_valid_window(range_window)));
    MPTRACK_CHECK_PARAM(where, "doppler_window", check(is_valid_window(doppler_window)));
    MPTRACK_CHECK_PARAM(where, "angle_window", check(is_valid_window(angle_window)));
    MPTRACK_CHECK_PARAM(where, "max_abs_bearing_rad",
                        check_range(max_abs_bearing_rad, 1e-6, mptrack::dmath::kHalfPi<double>));
    MPTRACK_CHECK_PARAM(where, "min_range_m", check_at_least(min_range_m, 0.0));
    MPTRACK_CHECK_PARAM(where, "max_range_m", check_above(max_range_m, min_range_m, "min_range_m"));
    MPTRACK_TRY(cfar.validate(where));
    MPTRACK_CHECK_PARAM(where, "max_detections", check_at_least(max_detections, 1));
    MPTRACK_CHECK_PARAM(where, "min_noise_power", check_range(min_noise_power, 0.0, 1e30));
    MPTRACK_CHECK_PARAM(where, "sidelobe_margin_db", check_range(sidelobe_margin_db, 0.0, 30.0));
    MPTRACK_CHECK_PARAM(where, "angle_refine_iterations", check_at_most(angle_refine_iterations, 64));
    MPTRACK_CHECK_PARAM(where, "max_abs_sample", check_range(max_abs_sample, 1e-6, 1e9));
    MPTRACK_CHECK_PARAM(where, "saturation_fraction", check_range(saturation_fraction, 0.0, 1.0));
    MPTRACK_CHECK_PARAM(where, "adc_bits", check_range(adc_bits, 2, 16));
    return Status::kOk;
  }
};

/// lambda [m].
inline double wavelength_m(const FrontEndParams& p) { return kSpeedOfLight_mps / p.carrier_hz; }

/// Number of reference chirp samples L = round(T_Tx f_s) (reference_chirp.h; 0: does not fit).
inline std::size_t chirp_samples(const FrontEndParams& p) {
  return chirp_length(p.chirp_duration_s, p.sample_rate_hz);
}

/// Range per fast-time sample c / (2 f_s) [m].
inline double range_bin_m(const FrontEndParams& p) {
  return kSpeedOfLight_mps / (2.0 * p.sample_rate_hz);
}

}  // namespace mptrack::frontend
