// Target kinematics: CV prediction, cubature update on the association-
// weighted pseudo-measurement and the linear RTS smoother (spec 2.1, 3.9).
//
// Covariances stay symmetric positive definite in float: every update is
// re-symmetrised and checked with a Cholesky factorisation; a failed check
// is repaired by diagonal loading and reported to the caller (who counts it
// in TrackerCounters::numerical_repairs).
#pragma once

#include <array>
#include <cstddef>

#include <Eigen/Core>

#include "mptrack/mfbp/cholesky.h"
#include "mptrack/mfbp/cubature.h"

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

/// F = I2 (x) [[1, dt], [0, 1]] and Q = q I2 (x) [[dt^4/4, dt^3/2], [dt^3/2, dt^2]] (P103).
template <class T>
void cv_model(T dt_s, T q, Mat4<T>& F, Mat4<T>& Q) {
  F.setIdentity();
  F(0, 1) = dt_s;
  F(2, 3) = dt_s;
  const T dt2 = dt_s * dt_s;
  const T q11 = q * dt2 * dt2 * T(0.25);
  const T q12 = q * dt2 * dt_s * T(0.5);
  const T q22 = q * dt2;
  Q.setZero();
  Q(0, 0) = q11; Q(0, 1) = q12; Q(1, 0) = q12; Q(1, 1) = q22;
  Q(2, 2) = q11; Q(2, 3) = q12; Q(3, 2) = q12; Q(3, 3) = q22;
}

/// Forces symmetry and positive definiteness. Returns true if a repair
/// (diagonal loading) was needed beyond symmetrisation.
template <class T, int N>
bool make_spd(Eigen::Matrix<T, N, N>& P) {
  for (int r = 0; r < N; ++r) {
    for (int c = r + 1; c < N; ++c) {
      const T s = T(0.5) * (P(r, c) + P(c, r));
      P(r, c) = s;
      P(c, r) = s;
    }
  }
  bool repaired = false;
  Eigen::Matrix<T, N, N> L;
  // A pivot below 1e-4 of its diagonal (a multiple correlation above
  // 0.99995) counts as singular too: such a float covariance passes this
  // Cholesky but not Eigen's LLT after the next rounding (fuzz finding F14,
  // docs/reliability.md). Real track covariances stay far from it.
  const auto well_conditioned = [&L, &P]() {
    for (int j = 0; j < N; ++j) {
      if (!(L(j, j) * L(j, j) >= T(1e-4) * P(j, j))) return false;
    }
    return true;
  };
  for (int attempt = 0; attempt < 8; ++attempt) {
    if (cholesky<T, N>(P, L) && well_conditioned()) return repaired;
    repaired = true;
    T scale = T(0);
    for (int r = 0; r < N; ++r) scale = P(r, r) > scale ? P(r, r) : scale;
    T load = scale * T(1e-6);
    for (int k = 0; k < attempt; ++k) load *= T(10);
    if (!(load > T(0))) load = T(1e-6);
    for (int r = 0; r < N; ++r) {
      if (!(P(r, r) > T(0))) P(r, r) = T(0);
      P(r, r) += load;
    }
  }
  return repaired;
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
/// (spec 3.9, (P40)); M = 2 (range, azimuth) or 3 (+ Doppler). x, P are
/// the prediction on input, the posterior on output. Returns true if a
/// numerical repair was needed.
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
  if (!cholesky<T, M>(S, L)) return true;
  // K = Cxz S^-1, computed as (S^-1 Cxz^T)^T through the factorisation.
  const Eigen::Matrix<T, M, 4> Kt = cholesky_solve<T, M, 4>(L, Cxz.transpose());
  const Mat4M K = Kt.transpose();
  VecM e = y_bar - z_hat;
  e(1) = wrap_angle(e(1));
  if (white != nullptr) *white = cholesky_whiten<T, M>(L, e).template head<2>();
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

/// One RTS step (spec 3.9): from the filtered (xf, Pf) at k and the smoothed
/// (xs_next, Ps_next) at k+1 (dt apart) to the smoothed (xs, Ps) at k.
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
  if (!cholesky<T, 4>(P_pred, L)) {  // make_spd failed to repair: keep the filtered estimate
    xs = xf;
    Ps = Pf;
    return true;
  }
  // G = Pf F^T P_pred^-1  <=>  G^T = P_pred^-1 (F Pf)  (P_pred symmetric).
  const Mat4<T> FPf = F * Pf;
  const Mat4<T> G = cholesky_solve<T, 4, 4>(L, FPf).transpose();
  xs = xf + G * (xs_next - x_pred);
  Ps = Pf + G * (Ps_next - P_pred) * G.transpose();
  repaired = make_spd(Ps) || repaired;
  return repaired;
}

}  // namespace mptrack::mfbp
