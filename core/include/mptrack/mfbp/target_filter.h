// Target kinematics: CV prediction, cubature update on the association-
// weighted pseudo-measurement and the linear RTS smoother (docs/algorithms/mfbp.md
// §Target chain).
//
// Covariances stay symmetric positive definite in float through the SPD
// guard of model/spd_guard.h (symmetrise, Cholesky test with the F14 pivot
// rule, diagonal loading); a repair is reported to the caller (who counts
// it in TrackerCounters::numerical_repairs).
#pragma once

#include <array>
#include <cstddef>

#include <Eigen/Core>

#include "mptrack/mfbp/cubature.h"
#include "mptrack/model/cholesky.h"
#include "mptrack/model/cv_motion.h"
#include "mptrack/model/spd_guard.h"

namespace mptrack::mfbp {

/// A symmetric 4x4 covariance stored as its 10 upper-triangle entries
/// (the tracker keeps two per track and window scan; this saves 37%).
template <class T>
struct PackedCov4 {
  std::array<T, 10> v{};

  void set(const Mat4<T>& P) {
    std::size_t n = 0;
    for (int r = 0; r < 4; ++r) {
      for (int c = r; c < 4; ++c) v[n++] = P(r, c);
    }
  }
  Mat4<T> get() const {
    Mat4<T> P;
    std::size_t n = 0;
    for (int r = 0; r < 4; ++r) {
      for (int c = r; c < 4; ++c) {
        P(r, c) = v[n];
        P(c, r) = v[n];
        ++n;
      }
    }
    return P;
  }
};

/// F and Q of the CV model (model/cv_motion.h; q is the acceleration
/// variance sigma_v^2 [m^2/s^4]).
template <class T>
void cv_model(T dt_s, T q, Mat4<T>& F, Mat4<T>& Q) {
  model::cv_transition(dt_s, q, F, Q);
}

/// The SPD guard of every tracker (model/spd_guard.h). Returns true if a
/// repair beyond symmetrisation was needed.
template <class T, int N>
bool make_spd(Eigen::Matrix<T, N, N>& P) {
  return model::keep_spd(P, model::kDefaultMinVariance<T>);
}

/// x <- F x, P <- F P F^T + Q. Returns true if P needed a repair.
template <class T>
bool cv_predict(Vec4<T>& x, Mat4<T>& P, T dt_s, T q) {
  Mat4<T> F, Q;
  cv_model(dt_s, q, F, Q);
  x = F * x;
  P = F * P * F.transpose() + Q;
  return make_spd(P);
}

/// Cubature update with pseudo-measurement y_bar and noise R_bar = R / w
/// (seed 000 eq. (40); docs/algorithms/mfbp.md §Target chain); M = 2 (range, azimuth)
/// or 3 (+ Doppler). x, P are the prediction on input, the posterior on output.
/// Returns true if a numerical repair was needed.
/// If white is given it receives the whitened innovation L^-1 e, S = L L^T
/// (its first two rows, range and azimuth, do not depend on a Doppler row;
/// untouched when the update fails).
template <class T, int M>
bool cubature_update_m(Vec4<T>& x, Mat4<T>& P, const Eigen::Matrix<T, M, 1>& y_bar,
                       const Eigen::Matrix<T, M, M>& R_bar, Vec2<T>* white = nullptr) {
  using VecM = Eigen::Matrix<T, M, 1>;
  using MatM = Eigen::Matrix<T, M, M>;
  using Mat4M = Eigen::Matrix<T, 4, M>;
  bool repaired = make_spd(P);
  VecM z_hat;
  MatM Sz;
  Mat4M Cxz;
  if (!cubature_moments<T, M>(x, P, z_hat, Sz, Cxz)) return true;
  const MatM S = Sz + R_bar;
  MatM L;
  if (!model::cholesky<T, M>(S, L)) return true;
  // K = Cxz S^-1, computed as (S^-1 Cxz^T)^T through the factorisation.
  const Eigen::Matrix<T, M, 4> Kt = model::cholesky_solve<T, M, 4>(L, Cxz.transpose());
  const Mat4M K = Kt.transpose();
  VecM e = y_bar - z_hat;
  e(1) = model::wrap_angle(e(1));
  if (white != nullptr) *white = model::cholesky_whiten<T, M>(L, e).template head<2>();
  x += K * e;
  P -= K * S * K.transpose();
  repaired = make_spd(P) || repaired;
  return repaired;
}

/// The 2-row (range, azimuth) update.
template <class T>
bool cubature_update(Vec4<T>& x, Mat4<T>& P, const Vec2<T>& y_bar, const Mat2<T>& R_bar,
                     Vec2<T>* white = nullptr) {
  return cubature_update_m<T, 2>(x, P, y_bar, R_bar, white);
}

/// One RTS step (docs/algorithms/mfbp.md §Target chain): from the filtered (xf, Pf)
/// at k and the smoothed (xs_next, Ps_next) at k+1 (dt apart) to the smoothed
/// (xs, Ps) at k.
/// Returns true if a repair was needed.
template <class T>
bool rts_step(const Vec4<T>& xf, const Mat4<T>& Pf, const Vec4<T>& xs_next,
              const Mat4<T>& Ps_next, T dt_s, T q, Vec4<T>& xs, Mat4<T>& Ps) {
  Mat4<T> F, Q;
  cv_model(dt_s, q, F, Q);
  const Vec4<T> x_pred = F * xf;
  Mat4<T> P_pred = F * Pf * F.transpose() + Q;
  bool repaired = make_spd(P_pred);
  Mat4<T> L;
  if (!model::cholesky<T, 4>(P_pred, L)) {  // make_spd failed to repair: keep the filtered estimate
    xs = xf;
    Ps = Pf;
    return true;
  }
  // G = Pf F^T P_pred^-1  <=>  G^T = P_pred^-1 (F Pf)  (P_pred symmetric).
  const Mat4<T> FPf = F * Pf;
  const Mat4<T> G = model::cholesky_solve<T, 4, 4>(L, FPf).transpose();
  xs = xf + G * (xs_next - x_pred);
  Ps = Pf + G * (Ps_next - P_pred) * G.transpose();
  repaired = make_spd(Ps) || repaired;
  return repaired;
}

}  // namespace mptrack::mfbp
