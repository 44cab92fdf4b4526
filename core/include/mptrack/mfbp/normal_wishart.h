// Normal-Wishart belief of one Gaussian clutter component in measurement
// (polar) space: N(x^c; mu, (c D)^-1) W(D; W, nu), q = 2 (docs/algorithms/mfbp.md
// §Clutter chain).
//
// We store W^-1 (covariance-like, "w_inv") rather than W: the conjugate
// update adds scatter matrices to W^-1 (Bishop 10.62) and the reported
// spread is E[D^-1] = W^-1 / (nu - 3).
#pragma once

#include <Eigen/Core>

#include "mptrack/math/detmath.h"
#include "mptrack/mfbp/cubature.h"
#include "mptrack/mfbp/mfbp_params.h"

namespace mptrack::mfbp {

/// Weighted measurement statistics of one component at one scan
/// (docs/algorithms/mfbp.md §Clutter chain, seed 000 eq. (58)), kept relative to a
/// reference point `ref` (azimuth offsets wrapped) so float sums of squares do not
/// cancel catastrophically.
template <class T>
struct NwStats {
  T n = T(0);                              ///< sum a_j [-]
  Vec2<T> ref = Vec2<T>::Zero();           ///< reference point [m, rad]
  Vec2<T> sum = Vec2<T>::Zero();           ///< sum a_j (y_j - ref)
  Mat2<T> sum_sq = Mat2<T>::Zero();        ///< sum a_j (y_j - ref)(y_j - ref)^T

  void add(const Vec2<T>& y, T weight) {
    Vec2<T> d = y - ref;
    d(1) = model::wrap_angle(d(1));
    n += weight;
    sum += weight * d;
    sum_sq += weight * (d * d.transpose());
  }

  /// this <- this + other (other moved to this reference).
  void accumulate(const NwStats& o) {
    if (!(o.n > T(0))) return;
    Vec2<T> d = o.ref - ref;
    d(1) = model::wrap_angle(d(1));
    n += o.n;
    sum += o.sum + o.n * d;
    sum_sq += o.sum_sq + o.sum * d.transpose() + d * o.sum.transpose() + o.n * (d * d.transpose());
  }

  void scale(T g) {
    n *= g;
    sum *= g;
    sum_sq *= g;
  }
};

template <class T>
struct NormalWishart {
  Vec2<T> mu = Vec2<T>::Zero();            ///< centroid mean [m, rad]
  T c = T(1);                              ///< centroid precision scale [-]
  Mat2<T> w_inv = Mat2<T>::Identity();     ///< W^-1 [m^2, m rad; ., rad^2]
  T nu = T(4);                             ///< degrees of freedom (> q + 1 = 3) [-]

  /// Forgetting transition (docs/algorithms/mfbp.md §Clutter chain): mu, c kept;
  /// nu <- xi (nu - 3) + 3; kMeanPreserving: W^-1 <- xi W^-1 (docs/algorithms/mfbp.md
  /// §Departures from the paper); kPaper: W^-1 <- W^-1 / xi.
  NormalWishart predicted(T xi, NwForgetting mode) const {
    NormalWishart out = *this;
    out.nu = xi * (nu - T(3)) + T(3);
    if (mode == NwForgetting::kMeanPreserving) {
      out.w_inv = xi * w_inv;
    } else {
      out.w_inv = w_inv / xi;
    }
    return out;
  }

  /// Conjugate update (seed 000 eq. (57)) [Bishop 10.60-10.63]; skipped for N < 1e-6.
  void update(const NwStats<T>& s) {
    if (!(s.n > T(1e-6))) return;
    const T N = s.n;
    const Vec2<T> mean_off = s.sum / N;            // x_bar - ref
    const Mat2<T> scatter = s.sum_sq - N * (mean_off * mean_off.transpose());  // N Xi
    Vec2<T> x_bar = s.ref + mean_off;
    Vec2<T> d = x_bar - mu;
    d(1) = model::wrap_angle(d(1));
    const T c_new = c + N;
    mu += (N / c_new) * d;  // (c mu + N x_bar)/c' with the wrapped offset
    mu(1) = model::wrap_angle(mu(1));
    w_inv += scatter + (c * N / c_new) * (d * d.transpose());
    w_inv(0, 1) = w_inv(1, 0) = T(0.5) * (w_inv(0, 1) + w_inv(1, 0));
    c = c_new;
    nu += N;
  }

  /// E[D^-1] = W^-1 / (nu - 3), guarded for nu close to 3.
  Mat2<T> expected_covariance() const {
    const T dof = nu - T(3) > T(1e-3) ? nu - T(3) : T(1e-3);
    return w_inv / dof;
  }

  /// Terms of E ln c(y) (docs/algorithms/mfbp.md §Clutter chain, Bishop 10.64-10.65)
  /// that do not depend on y: -ln(2 pi) + E ln|D| / 2. W = (W^-1)^-1, so ln|W| = -ln|W^-1|.
  T expected_log_norm() const {
    const T det = w_inv(0, 0) * w_inv(1, 1) - w_inv(0, 1) * w_inv(1, 0);
    const T e_log_det = dmath::ddigamma(T(0.5) * nu) + dmath::ddigamma(T(0.5) * (nu - T(1))) +
                        T(2) * T(0.69314718055994531) - dmath::dlog(det);
    return -dmath::kLnTwoPi<T> + T(0.5) * e_log_det;
  }

  /// E[(y - x^c)^T D (y - x^c)] = q / c + nu (y - mu)^T W (y - mu).
  T expected_mahalanobis(const Vec2<T>& y) const {
    Vec2<T> d = y - mu;
    d(1) = model::wrap_angle(d(1));
    const T det = w_inv(0, 0) * w_inv(1, 1) - w_inv(0, 1) * w_inv(1, 0);
    // d^T W d with W = adj(W^-1) / det(W^-1), 2x2 closed form.
    const T quad = (w_inv(1, 1) * d(0) * d(0) - T(2) * w_inv(0, 1) * d(0) * d(1) +
                    w_inv(0, 0) * d(1) * d(1)) / det;
    return T(2) / c + nu * quad;
  }
};

}  // namespace mptrack::mfbp
