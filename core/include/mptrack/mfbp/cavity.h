// Cavity (extrinsic) measurement-space moments of a target at one scan:
// the smoothed belief with that scan's own pseudo-measurement removed
// (MfbpParams::association_cavity; our choice, not in the paper:
// docs/algorithms/mfbp.md §Departures from the paper).
//
// Gaussian division in information form, measurement space (2x2):
//   S_cav^-1 = Sz^-1 - w R^-1
//   z_cav    = S_cav (Sz^-1 z_hat - w R^-1 y_bar)
//            = z_hat - S_cav w R^-1 (y_bar - z_hat)
// where (y_bar, R / w) is the pseudo-measurement of the previous iteration
// (seed 000 eq. (40); docs/algorithms/mfbp.md §Target chain) and R is diagonal. The
// second form needs only the innovation e_bar = y_bar - z_hat (azimuth already wrapped
// by the caller).
// No libm, no heap; closed-form 2x2 inverses.
#pragma once

#include <Eigen/Core>

#include "mptrack/mfbp/cubature.h"

namespace mptrack::mfbp {

/// Removes the pseudo-measurement (z_hat + e_bar, R / w) from the moments
/// (z_hat, Sz). r_inv_diag = (1/R00, 1/R11). Returns false and leaves
/// z_hat, Sz unchanged when Sz is not positive definite or the division is
/// not positive definite (the measurement is not "inside" the belief, e.g.
/// after a prior/stale association); the azimuth of z_hat is re-wrapped.
template <class T>
bool remove_pseudo_measurement(Vec2<T>& z_hat, Mat2<T>& Sz, const Vec2<T>& e_bar, T w,
                               const Vec2<T>& r_inv_diag) {
  const T det = Sz(0, 0) * Sz(1, 1) - Sz(0, 1) * Sz(1, 0);
  if (!(det > T(0))) return false;
  Mat2<T> info;  // Sz^-1 - w R^-1
  info << Sz(1, 1) / det - w * r_inv_diag(0), -Sz(0, 1) / det, -Sz(1, 0) / det,
      Sz(0, 0) / det - w * r_inv_diag(1);
  const T det_i = info(0, 0) * info(1, 1) - info(0, 1) * info(1, 0);
  if (!(info(0, 0) > T(0)) || !(det_i > T(0))) return false;
  Mat2<T> S_cav;
  S_cav << info(1, 1) / det_i, -info(0, 1) / det_i, -info(1, 0) / det_i, info(0, 0) / det_i;
  const Vec2<T> g(w * r_inv_diag(0) * e_bar(0), w * r_inv_diag(1) * e_bar(1));
  z_hat -= S_cav * g;
  z_hat(1) = model::wrap_angle(z_hat(1));
  Sz = S_cav;
  return true;
}

}  // namespace mptrack::mfbp
