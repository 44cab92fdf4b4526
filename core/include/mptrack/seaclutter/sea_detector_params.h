// Tunables of the sea-clutter detection chain (docs/algorithms/sea_clutter.md
// §Detection chain): radar constants, the CFAR, the clustering and the patch
// scaling.
#pragma once

#include <cstddef>

#include "mptrack/frontend/frontend_params.h"
#include "mptrack/frontend/window.h"
#include "mptrack/validate.h"

namespace mptrack::seaclutter {

struct SeaDetectorParams {
  // Radar (the scene's; seed 003 Sec. IV).
  double carrier_hz = 9.4e9;   ///< f_c [Hz]; range rate = -f_D c / (2 f_c) (seed 003 eq. (4))
  double prf_hz = 1000.0;      ///< PRF [Hz]; Doppler bin = prf_hz / kDopplerBins
  double range_bin_m = 15.0;   ///< range cell size [m]; bin m is centred at m * range_bin_m
  frontend::WindowType doppler_window = frontend::WindowType::kHann;  ///< taper across pulses
  /// CFAR along range, one line per Doppler bin. CA with the paper's permissive
  /// P_FA = 0.28 per cell (seed 003 Sec. IV): alpha solves (1 + alpha/2T)^-2T = P_FA.
  frontend::CfarParams cfar{frontend::CfarType::kCellAveraging, frontend::CfarEdge::kShift, 1, 8, 0.28, 0};
  // DBSCAN on the detection grid (Chebyshev neighbourhood, seed 003 Sec. III-A).
  std::size_t eps_range_bins = 1;    ///< neighbourhood half-width in range [bins] (15 m)
  std::size_t eps_doppler_bins = 1;  ///< neighbourhood half-width in Doppler [bins] (1.95 Hz)
  std::size_t min_points = 5;        ///< a core cell has >= this many detections in its
                                     ///< neighbourhood, itself included (paper: 5)
  // Patch scaling: code = floor((10 log10(P / median) - floor_db) * 255 / span_db), clipped to 0..255.
  double patch_floor_db = -10.0;  ///< dB relative to the patch median that maps to code 0
  double patch_span_db = 60.0;    ///< dB covered by codes 0..255 (0.235 dB per code)

  Status validate(ParamError* where = nullptr) const {
    MPTRACK_CHECK_PARAM(where, "carrier_hz", check_carrier_hz(carrier_hz));
    MPTRACK_CHECK_PARAM(where, "prf_hz", check_positive(prf_hz));
    MPTRACK_CHECK_PARAM(where, "range_bin_m", check_positive(range_bin_m));
    MPTRACK_CHECK_PARAM(where, "doppler_window", check(frontend::is_valid_window(doppler_window)));
    MPTRACK_TRY(cfar.validate(where));
    MPTRACK_CHECK_PARAM(where, "eps_range_bins", check(eps_range_bins >= 1 && eps_range_bins <= 4));
    MPTRACK_CHECK_PARAM(where, "eps_doppler_bins", check(eps_doppler_bins >= 1 && eps_doppler_bins <= 8));
    MPTRACK_CHECK_PARAM(where, "min_points", check(min_points >= 1 && min_points <= 81));
    MPTRACK_CHECK_PARAM(where, "patch_floor_db", check_range(patch_floor_db, -100.0, 100.0));
    MPTRACK_CHECK_PARAM(where, "patch_span_db", check_range(patch_span_db, 1.0, 200.0));
    return Status::kOk;
  }
};

}  // namespace mptrack::seaclutter
