// Pieces every IGGM baseline runs per scan: measurement checks and
// amplitude terms, per-component linearisation (EKF for polar) with the
// Joseph-form posterior, gated log-likelihoods, the component update and
// measurement-driven births.
//
// Births (our choice: docs/algorithms/gm-phd.md §Departures from the paper): seed 001
// uses 6 fixed birth locations, which no other scenario has. Here every valid
// measurement of scan k-1 seeds a birth component at scan k (zero velocity, std
// birth_velocity_std_mps), with
// weight birth_rate * (1 - P_t(z)) / sum(1 - P_t), P_t(z) being the
// probability that z came from an existing target (Ristic et al. 2012,
// adaptive birth). Birth powers use the prior (target_power_prior,
// target_alpha_prior), not the seeding amplitude.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "mptrack/measurement.h"
#include "mptrack/model/amplitude_iggm.h"
#include "mptrack/model/cv_motion.h"
#include "mptrack/model/inverse_gamma.h"
#include "mptrack/model/measurement_validator.h"
#include "mptrack/model/spd_guard.h"
#include "mptrack/rfs/measurement_model.h"
#include "mptrack/rfs/mixture.h"
#include "mptrack/rfs/rfs_params.h"
#include "mptrack/validate.h"

namespace mptrack::rfs {

using model::AmplitudeTerms;

/// One scan's measurements as the filters use them.
template <class T, std::size_t MaxMeasurements>
struct MeasurementBatch {
  std::size_t n = 0;
  std::size_t invalid = 0;
  std::size_t duplicate = 0;  ///< exact duplicates of a valid earlier one (measurement.h, F11)
  std::array<Vec2<T>, MaxMeasurements> z{};
  std::array<AmplitudeTerms<T>, MaxMeasurements> amp{};
  std::array<bool, MaxMeasurements> valid{};

  /// Converts and checks with p.validator() (model/measurement_validator.h:
  /// finite, inside the region, amplitude > d and <= max_amplitude when
  /// amplitude is used, > 0 otherwise), and the clutter term a^(2b) <=
  /// RfsFilterParams::kMaxAmplitudeTerm (docs/reliability.md F4: larger values
  /// overflow the amplitude moments). Exact duplicates of a valid earlier
  /// measurement are flagged too and counted in `duplicate` (measurement.h,
  /// F11). Invalid ones stay in place (flag false) so measurement indices
  /// keep their meaning.
  template <std::size_t N>
  void load(const Scan<T, N>& scan, const RfsFilterParams<T>& p, const MeasurementModel<T>& mm) {
    static_assert(N <= MaxMeasurements, "batch smaller than the scan");
    n = scan.measurements.size();
    invalid = 0;
    duplicate = 0;
    const model::MeasurementValidator<T> check = p.validator();
    for (std::size_t i = 0; i < n; ++i) {
      const Measurement<T>& y = scan.measurements[i];
      bool ok = check.values_valid(y);
      if (ok) {
        z[i] = mm.vector_of(y);
        ok = check.inside(z[i](0), z[i](1));
      }
      valid[i] = ok;
      if (!ok) {
        ++invalid;
        continue;
      }
      amp[i] = p.amplitude.use_amplitude
                   ? model::amplitude_terms(y.amplitude, p.amplitude.threshold, p.weibull_shape)
                   : AmplitudeTerms<T>{};
      if (p.amplitude.use_amplitude &&
          !(amp[i].clutter_excess <= RfsFilterParams<T>::kMaxAmplitudeTerm)) {
        valid[i] = false;  // a^(2b) too large for this Weibull shape b
        ++invalid;
      } else if (is_duplicate(scan, i, [this](std::size_t k) { return valid[k]; })) {
        valid[i] = false;
        ++duplicate;
      }
    }
  }
};

/// Per-component quantities of one scan's update.
template <class T>
struct Linearized {
  Vec2<T> z_hat = Vec2<T>::Zero();
  Mat2<T> S_inv = Mat2<T>::Identity();
  T log_det = T(0);
  Eigen::Matrix<T, 4, 2> K = Eigen::Matrix<T, 4, 2>::Zero();
  Mat4<T> P_post = Mat4<T>::Identity();
  T pd = T(0);         ///< detection probability [-]
  T log_pd = T(0);
  bool ok = false;     ///< false: S not SPD; the component is only missed
};

template <class T>
T clamp_probability(T p) {
  const T lo = T(1e-6);
  const T hi = T(1) - T(1e-6);
  return p < lo ? lo : (p > hi ? hi : p);
}

/// Linearises c: S = H P H^T + R, K = P H^T S^-1, Joseph-form posterior.
/// Returns true if a covariance needed repair.
template <class T>
bool linearize_component(const TargetComponent<T>& c, const MeasurementModel<T>& mm,
                         const RfsFilterParams<T>& p, Linearized<T>& out) {
  Mat24<T> H;
  mm.linearize(c.x, out.z_hat, H);
  const Eigen::Matrix<T, 4, 2> PHt = c.P * H.transpose();
  Mat2<T> S = H * PHt + mm.R;
  model::symmetrize(S);
  out.ok = invert_spd2(S, out.S_inv, out.log_det);
  const T pd = p.amplitude.use_amplitude
                   ? model::target_detection_probability(c.power, p.amplitude.threshold, p.amplitude.order())
                   : p.detection_prob;
  out.pd = clamp_probability(pd);
  out.log_pd = dmath::dlog(out.pd);
  if (!out.ok) return false;
  out.K = PHt * out.S_inv;
  const Mat4<T> IKH = Mat4<T>::Identity() - out.K * H;
  out.P_post = IKH * c.P * IKH.transpose() + out.K * mm.R * out.K.transpose();
  return model::keep_spd(out.P_post, T(1e-9));
}

/// ln(P_D g_z g_a) of component c for measurement i, or false if outside
/// the gate (d^2 > gate) or not linearised. `v` receives the innovation.
template <class T, std::size_t M>
bool log_detection_likelihood(const TargetComponent<T>& c, const Linearized<T>& lin,
                              const MeasurementBatch<T, M>& batch, std::size_t i,
                              const MeasurementModel<T>& mm, const RfsFilterParams<T>& p, T gate,
                              Vec2<T>& v, T& log_q) {
  if (!lin.ok) return false;
  v = mm.residual(batch.z[i], lin.z_hat);
  if (mahalanobis2(v, lin.S_inv) > gate) return false;
  log_q = lin.log_pd + log_gauss2(v, lin.S_inv, lin.log_det);
  if (p.amplitude.use_amplitude) {
    log_q += model::log_target_amplitude(c.power, batch.amp[i], p.amplitude.order());
  }
  return true;
}

/// The component c updated with measurement i (weight set by the caller).
template <class T, std::size_t M>
TargetComponent<T> updated_component(const TargetComponent<T>& c, const Linearized<T>& lin,
                                     const MeasurementBatch<T, M>& batch, std::size_t i,
                                     const Vec2<T>& v, const RfsFilterParams<T>& p) {
  TargetComponent<T> u = c;
  u.x = c.x + lin.K * v;
  u.P = lin.P_post;
  if (p.amplitude.use_amplitude) model::ig_update_target(u.power, batch.amp[i], p.amplitude.order());
  u.measurement = static_cast<std::int32_t>(i);
  return u;
}

/// Prediction of one component over dt [s]: CV kinematics, power forgetting.
template <class T>
void predict_component(TargetComponent<T>& c, const RfsFilterParams<T>& p, T dt) {
  model::cv_predict(c.x, c.P, dt, p.accel_var_m2ps4);
  if (p.amplitude.use_amplitude) model::forget_clamped(c.power, p.power_forgetting, p.min_alpha);
  c.measurement = -1;
}

/// Birth component on measurement z (see the file comment).
template <class T>
TargetComponent<T> birth_component(const Vec2<T>& z, T weight, std::uint32_t label,
                                   const MeasurementModel<T>& mm, const RfsFilterParams<T>& p) {
  TargetComponent<T> b;
  Vec2<T> pos;
  Mat2<T> cov;
  mm.position_of(z, pos, cov);
  b.weight = weight;
  b.x << pos(0), T(0), pos(1), T(0);
  b.P.setZero();
  b.P(0, 0) = cov(0, 0);
  b.P(0, 2) = cov(0, 1);
  b.P(2, 0) = cov(1, 0);
  b.P(2, 2) = cov(1, 1);
  const T vv = p.birth_velocity_std_mps * p.birth_velocity_std_mps;
  b.P(1, 1) = vv;
  b.P(3, 3) = vv;
  b.power.a = p.target_alpha_prior;
  b.power.b = p.target_power_prior * (p.target_alpha_prior - T(1));
  b.label = label;
  b.measurement = -1;
  return b;
}

/// d^2 gate of a 2-dof chi-square at probability p: -2 ln(1 - p).
template <class T>
T chi2_gate_2dof(T p) {
  return T(-2) * dmath::dlog(T(1) - p);
}

}  // namespace mptrack::rfs
