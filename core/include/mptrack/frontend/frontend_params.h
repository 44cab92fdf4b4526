// Run-time tunables of the MIMO front end (developers' guide rule 4):
// units and defaults in the comments, validated once by FrontEnd::init().
// Defaults reproduce seed 004 (spec section 1.7, 32 MHz decimated path).
#pragma once

#include <cstddef>
#include <cstdint>

#include "mptrack/frontend/window.h"
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
};

/// Validates CfarParams in isolation (line length checked by the user of it).
inline Status validate(const CfarParams& p) {
  MPTRACK_TRY(check(p.type == CfarType::kCellAveraging || p.type == CfarType::kGreatestOf ||
                    p.type == CfarType::kSmallestOf || p.type == CfarType::kOrderedStatistic));
  MPTRACK_TRY(check(p.edge == CfarEdge::kSkip || p.edge == CfarEdge::kShift ||
                    p.edge == CfarEdge::kWrap));
  MPTRACK_TRY(check(p.guard_cells <= 64));
  MPTRACK_TRY(check(p.training_cells >= 1 && p.training_cells <= 64));
  MPTRACK_TRY(check_range(p.pfa, 1e-300, 0.5));
  MPTRACK_TRY(check(p.os_rank <= 2 * p.training_cells));
  return Status::kOk;
}

/// Waveform, array and processing parameters.
struct FrontEndParams {
  // Waveform (spec 1.3, 1.7).
  double carrier_hz = 10e9;            ///< carrier f_c [Hz]; lambda = c / f_c
  double bandwidth_hz = 20e6;          ///< chirp sweep BW [Hz] (-BW/2 .. +BW/2)
  double chirp_duration_s = 3.6e-6;    ///< chirp length T_Tx [s]
  double sample_rate_hz = 32e6;        ///< complex fast-time sample rate f_s [Hz]
  double chirp_repetition_s = 24e-6;   ///< same-Tx chirp interval T_c [s] (Doppler sampling;
                                       ///< TDM: N_T * slot, 3 * 8 us)
  // Array (spec 1.2).
  double element_spacing_wavelengths = 0.5;  ///< virtual ULA spacing d / lambda [-], (0, 1]
  // Processing.
  bool remove_dc = false;              ///< subtract each profile's complex mean before the MF
                                       ///< (Tx->Rx leakage / DC offset, spec 2.1 step 1)
  WindowType range_window = WindowType::kRectangular;   ///< taper on the matched-filter reference
  WindowType doppler_window = WindowType::kHann;        ///< taper across chirps
  WindowType angle_window = WindowType::kRectangular;   ///< taper across virtual channels
  double max_abs_bearing_rad = 1.0471975511965976;      ///< angle grid span |theta| <= this [rad],
                                                        ///< (0, pi/2]; default 60 deg
  double min_range_m = 0.0;            ///< range gate lower end [m] (bins below not tested)
  double max_range_m = 100.0;          ///< range gate upper end [m] (spec R_max)
  CfarParams cfar{};                   ///< detector along the range axis
  std::size_t max_detections = 64;     ///< per-frame cap (<= Caps::kMaxDetections; the Scan
                                       ///< capacity also caps it)
  double min_noise_power = 1e-30;      ///< floor on the CFAR noise estimate [map power units],
                                       ///< keeps amplitudes finite on noiseless data; >= 0
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
};

/// lambda [m].
inline double wavelength_m(const FrontEndParams& p) { return kSpeedOfLight_mps / p.carrier_hz; }

/// Number of reference chirp samples L = round(T_Tx f_s).
inline std::size_t chirp_samples(const FrontEndParams& p) {
  const double x = p.chirp_duration_s * p.sample_rate_hz + 0.5;
  // NaN or beyond any cap maps to 0 ("does not fit", init() rejects it):
  // casting an out-of-range double is undefined (fuzz finding F6).
  return (x >= 1.0 && x < 1e9) ? static_cast<std::size_t>(x) : std::size_t{0};
}

/// Range per fast-time sample c / (2 f_s) [m].
inline double range_bin_m(const FrontEndParams& p) {
  return kSpeedOfLight_mps / (2.0 * p.sample_rate_hz);
}

}  // namespace mptrack::frontend
