// One object's kinematic chain over a sliding window of W frames with a frozen
// tail, and its process-noise precisions (seed 004 eqs. (4)-(5), (18), (20)-(25),
// App. C; docs/algorithms/vmp.md §Window).
//
// State [px, vx, py, vy] (m, m/s), Phi_n = T Phi_{n-1} + G a, a ~ N(0, Lambda_a^-1),
// G = diag(dt^2/2, dt, dt^2/2, dt) (4 x 4, invertible: position- and velocity-driving
// noises are independent), Lambda_a = diag(lambda) with Gamma posteriors.
// Per frame the chain stores only the frame's data message (m, Omega) and dt; the
// Gaussian q(Phi) of every window frame is recomputed by one exact forward
// (Kalman, information from the messages) / backward (Rauch-Tung-Striebel) pass,
// whose means are the fixed point of the paper's mean-field sweeps (eq. (22)).
// The frame that leaves the window is frozen: its filtered marginal becomes the
// prior of the window ("tail"), so no data is counted twice. The Gamma update
// uses the smoother's lag-one cross-covariances (the chain is kept jointly
// Gaussian inside the window), see docs/algorithms/vmp.md §Corrections.
#pragma once

#include <array>
#include <cstddef>

#include <Eigen/Core>

#include "mptrack/model/cholesky.h"
#include "mptrack/model/spd_guard.h"

namespace mptrack::vmp {

template <class T>
using Vec4 = Eigen::Matrix<T, 4, 1>;
template <class T>
using Mat4 = Eigen::Matrix<T, 4, 4>;
template <class T>
using Vec2 = Eigen::Matrix<T, 2, 1>;
template <class T>
using Mat2 = Eigen::Matrix<T, 2, 2>;

/// T(dt) for [px, vx, py, vy].
template <class T>
Mat4<T> cv_transition(T dt) {
  Mat4<T> f = Mat4<T>::Identity();
  f(0, 1) = dt;
  f(2, 3) = dt;
  return f;
}

/// diag(G) = (dt^2/2, dt, dt^2/2, dt).
template <class T>
Vec4<T> driving_gain(T dt) {
  Vec4<T> g;
  g << T(0.5) * dt * dt, dt, T(0.5) * dt * dt, dt;
  return g;
}

/// Q = G diag(1/lambda) G^T (diagonal).
template <class T>
Mat4<T> process_noise(T dt, const Vec4<T>& lambda) {
  const Vec4<T> g = driving_gain(dt);
  Mat4<T> q = Mat4<T>::Zero();
  for (int i = 0; i < 4; ++i) q(i, i) = g(i) * g(i) / lambda(i);
  return q;
}

template <class T>
struct ChainSlot {
  T dt_s = T(0);        ///< time since the previous frame [s]
  bool has_msg = false;
  Vec2<T> m = Vec2<T>::Zero();      ///< data-message mean (x, y) [m]
  Mat2<T> omega = Mat2<T>::Zero();  ///< data-message precision [1/m^2]
};

/// What one object keeps between frames (about 40 + 7 W scalars).
template <class T, std::size_t W>
struct TrackChain {
  std::array<ChainSlot<T>, W> slots{};
  std::size_t head = 0;   ///< ring index of the oldest window frame
  std::size_t count = 0;  ///< frames in the window
  bool has_tail = false;  ///< false: slot 0 is the birth frame
  Vec4<T> tail_x = Vec4<T>::Zero();
  Mat4<T> tail_p = Mat4<T>::Identity();
  Vec4<T> next_tail_x = Vec4<T>::Zero();  ///< filtered marginal of slot 0 (last pass)
  Mat4<T> next_tail_p = Mat4<T>::Identity();
  Vec4<T> x = Vec4<T>::Zero();      ///< q(Phi) mean at the newest frame
  Mat4<T> p = Mat4<T>::Identity();  ///< and its covariance
  Vec4<T> lambda = Vec4<T>::Ones();  ///< E[lambda_j], process-noise precisions
  T birth_velocity_var = T(25);      ///< birth prior on each velocity [m^2/s^2]

  ChainSlot<T>& slot(std::size_t i) { return slots[(head + i) % W]; }
  const ChainSlot<T>& slot(std::size_t i) const { return slots[(head + i) % W]; }
  ChainSlot<T>& newest() { return slot(count - 1); }

  /// Starts the chain at its birth frame with the birth message.
  void start(const Vec2<T>& m, const Mat2<T>& omega, const Vec4<T>& lambda0, T velocity_var) {
    head = 0;
    count = 1;
    has_tail = false;
    lambda = lambda0;
    birth_velocity_var = velocity_var;
    ChainSlot<T>& s = slots[0];
    s.dt_s = T(0);
    s.has_msg = true;
    s.m = m;
    s.omega = omega;
  }

  /// Appends a frame dt after the newest (no message yet), freezing the oldest
  /// frame into the tail when the window is full.
  void push(T dt) {
    if (count == W) {
      tail_x = next_tail_x;
      tail_p = next_tail_p;
      has_tail = true;
      head = (head + 1) % W;
      --count;
    }
    ChainSlot<T>& s = slots[(head + count) % W];
    s.dt_s = dt;
    s.has_msg = false;
    ++count;
  }
};

/// Scratch for the forward/backward pass of one chain (shared by all objects).
template <class T, std::size_t W>
class ChainSmoother {
 public:
  /// One exact pass: filtered then smoothed marginals over the window; sets
  /// ch.x, ch.p (newest frame) and ch.next_tail_*. Returns the number of
  /// covariance repairs.
  std::size_t smooth(TrackChain<T, W>& ch, T min_variance) {
    std::size_t repairs = 0;
    load_dt(ch);
    const std::size_t n = ch.count;
    for (std::size_t i = 0; i < n; ++i) {
      const ChainSlot<T>& s = ch.slot(i);
      if (i == 0 && !ch.has_tail) {
        // Birth: position from the message, velocity N(0, sigma_v0^2).
        xf_[0] << s.m(0), T(0), s.m(1), T(0);
        pf_[0] = Mat4<T>::Zero();
        const Mat2<T> r = inverse2(s.omega);
        pf_[0](0, 0) = r(0, 0);
        pf_[0](0, 2) = r(0, 1);
        pf_[0](2, 0) = r(1, 0);
        pf_[0](2, 2) = r(1, 1);
        pf_[0](1, 1) = ch.birth_velocity_var;
        pf_[0](3, 3) = ch.birth_velocity_var;
        continue;
      }
      const Mat4<T> f = cv_transition(s.dt_s);
      const Vec4<T>& xprev = i == 0 ? ch.tail_x : xf_[i - 1];
      const Mat4<T>& pprev = i == 0 ? ch.tail_p : pf_[i - 1];
      xp_[i] = f * xprev;
      pp_[i] = f * pprev * f.transpose() + process_noise(s.dt_s, ch.lambda);
      xf_[i] = xp_[i];
      pf_[i] = pp_[i];
      if (s.has_msg) update(s, xf_[i], pf_[i]);
      if (model::keep_spd(pf_[i], min_variance)) ++repairs;
    }
    xs_[n - 1] = xf_[n - 1];
    ps_[n - 1] = pf_[n - 1];
    for (std::size_t i = n - 1; i-- > 0;) repairs += rts_step(xf_[i], pf_[i], i + 1, xs_[i], ps_[i], cross_[i]);
    if (ch.has_tail) repairs += rts_step(ch.tail_x, ch.tail_p, 0, tail_xs_, tail_ps_, tail_cross_);
    ch.x = xf_[n - 1];
    ch.p = pf_[n - 1];
    ch.next_tail_x = xf_[0];
    ch.next_tail_p = pf_[0];
    return repairs;
  }

  /// Gamma update of the process-noise precisions from the last smooth():
  ///   lambda_j = (N + zeta) / (chi + sum_n [V_n]_jj),
  ///   V_n = G^-1 E[(Phi_{n+1} - T Phi_n)(.)^T] G^-T
  ///       = G^-1 [d d^T + P_{n+1} + T P_n T^T - C T^T - T C^T] G^-T,  C = cov(Phi_{n+1}, Phi_n).
  void update_gamma(TrackChain<T, W>& ch, T zeta, T chi, T min_rate) const {
    Vec4<T> sum = Vec4<T>::Zero();
    std::size_t transitions = 0;
    const std::size_t n = ch.count;
    for (std::size_t i = 0; i + 1 < n; ++i) {
      accumulate(ch.slot(i + 1).dt_s, xs_[i], ps_[i], xs_[i + 1], ps_[i + 1], cross_[i], sum);
      ++transitions;
    }
    if (ch.has_tail) {
      accumulate(ch.slot(0).dt_s, tail_xs_, tail_ps_, xs_[0], ps_[0], tail_cross_, sum);
      ++transitions;
    }
    for (int j = 0; j < 4; ++j) {
      T rate = chi + sum(j);
      if (rate < min_rate) rate = min_rate;
      ch.lambda(j) = (static_cast<T>(transitions) + zeta) / rate;
    }
  }

 private:
  static Mat2<T> inverse2(const Mat2<T>& a) {
    const T det = a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0);
    Mat2<T> r;
    r << a(1, 1) / det, -a(0, 1) / det, -a(1, 0) / det, a(0, 0) / det;
    return r;
  }

  // Kalman update with the position message: H = [e_px; e_py], R = Omega^-1.
  static void update(const ChainSlot<T>& s, Vec4<T>& x, Mat4<T>& p) {
    const Mat2<T> r = inverse2(s.omega);
    Mat2<T> sm;
    sm << p(0, 0) + r(0, 0), p(0, 2) + r(0, 1), p(2, 0) + r(1, 0), p(2, 2) + r(1, 1);
    const Mat2<T> si = inverse2(sm);
    Eigen::Matrix<T, 4, 2> ph;
    ph.col(0) = p.col(0);
    ph.col(1) = p.col(2);
    const Eigen::Matrix<T, 4, 2> k = ph * si;
    Vec2<T> nu;
    nu << s.m(0) - x(0), s.m(1) - x(2);
    x += k * nu;
    p -= k * ph.transpose();
    const Mat4<T> sym = T(0.5) * (p + p.transpose());
    p = sym;
  }

  // RTS step for frame with filtered (x, p) whose successor is window index j.
  std::size_t rts_step(const Vec4<T>& x, const Mat4<T>& p, std::size_t j, Vec4<T>& xs, Mat4<T>& ps,
                       Mat4<T>& cross) const {
    const Mat4<T> f = cv_transition(dt_of_(j));
    Mat4<T> l;
    if (!model::cholesky<T, 4>(pp_[j], l)) {
      xs = x;
      ps = p;
      cross = Mat4<T>::Zero();
      return 1;
    }
    const Mat4<T> fp = f * p;
    const Mat4<T> jt = model::cholesky_solve<T, 4, 4>(l, fp);  // J^T = Pp^-1 F P
    const Mat4<T> g = jt.transpose();
    xs = x + g * (xs_[j] - xp_[j]);
    const Mat4<T> d = ps_[j] - pp_[j];
    ps = p + g * d * jt;
    const Mat4<T> sym = T(0.5) * (ps + ps.transpose());
    ps = sym;
    cross = ps_[j] * jt;
    return 0;
  }

  static void accumulate(T dt, const Vec4<T>& x0, const Mat4<T>& p0, const Vec4<T>& x1, const Mat4<T>& p1,
                         const Mat4<T>& c, Vec4<T>& sum) {
    const Mat4<T> f = cv_transition(dt);
    const Vec4<T> d = x1 - f * x0;
    const Mat4<T> fc = f * c.transpose();  // T C^T
    const Mat4<T> e = d * d.transpose() + p1 + f * p0 * f.transpose() - fc - fc.transpose();
    const Vec4<T> g = driving_gain(dt);
    for (int j = 0; j < 4; ++j) sum(j) += e(j, j) / (g(j) * g(j));
  }

  T dt_of_(std::size_t j) const { return dt_[j]; }

  void load_dt(const TrackChain<T, W>& ch) {
    for (std::size_t i = 0; i < ch.count; ++i) dt_[i] = ch.slot(i).dt_s;
  }

  std::array<T, W> dt_{};
  std::array<Vec4<T>, W> xp_{}, xf_{}, xs_{};
  std::array<Mat4<T>, W> pp_{}, pf_{}, ps_{}, cross_{};
  Vec4<T> tail_xs_ = Vec4<T>::Zero();
  Mat4<T> tail_ps_ = Mat4<T>::Zero(), tail_cross_ = Mat4<T>::Zero();
};

}  // namespace mptrack::vmp
