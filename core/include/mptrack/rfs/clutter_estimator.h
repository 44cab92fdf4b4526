// Clutter model shared by the IGGM baselines: Poisson clutter as a union of
// sources, each with a rate (detections per scan), a spatial density and an
// IG-distributed Weibull amplitude scale (docs/algorithms/gm-phd.md §Clutter estimation):
//   kappa(z, a) = lambda_0 / V g_0(a) + sum_c lambda_c N(z; mu_c, C_c) g_c(a)
// with g the IG-marginal truncated Weibull (K_WB, seed 001 eqs. (62)-(63)).
//
// Estimation (our choice: docs/algorithms/gm-phd.md §Departures from the paper): seed
// 001 carries clutter generators inside the PHD (kappa-PHD); here each source keeps
// conjugate statistics instead, updated with the clutter responsibility of every
// measurement (what the filter's update says is clutter, split over the sources by
// their share of kappa):
//   rate   Gamma(s, t):      s += sum resp, t += 1     (forgetting s, t /= v)
//   power  IG(alpha, beta):  alpha += sum resp, beta += sum resp (a^2b - d^2b)
//   place  weighted moments of z (forgetting /= v): mu, C (C >= R on the diagonal)
// With a PHD update this is exactly the kappa-PHD weight update of a source with p_S = 1
// (docs/algorithms/gm-phd.md §Clutter estimation), without its bias from the clutter
// birth/survival values the paper does not give. Sources (hot spots) are seeded from boxes
// holding >= hotspot_min_points uniform-clutter measurements of one scan (far above the
// uniform expectation) and deleted when their rate drops below hotspot_min_rate. Overflow
// policy: a seed that finds all MaxSources slots taken is dropped and counted
// (clutter_cap_hits).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "mptrack/math/detmath.h"
#include "mptrack/model/amplitude_iggm.h"
#include "mptrack/model/inverse_gamma.h"
#include "mptrack/rfs/log_sum.h"
#include "mptrack/rfs/measurement_model.h"
#include "mptrack/rfs/rfs_params.h"
#include "mptrack/static_vector.h"
#include "mptrack/track_report.h"

namespace mptrack::rfs {

template <class T, std::size_t MaxMeasurements, std::size_t MaxSources>
class ClutterEstimator {
 public:
  /// One clutter source (index 0 of the list is always the uniform one).
  struct Source {
    std::uint32_t id = 0;
    bool uniform = false;
    T rate_shape = T(0);   ///< Gamma shape s: rate estimate s / t [1/scan]
    T rate_scans = T(1);   ///< Gamma rate t [scans]
    model::InverseGamma<T> power;     ///< Weibull scale sigma0 [-]
    T m0 = T(0);           ///< forgetting moments of the assigned measurements
    Vec2<T> m1 = Vec2<T>::Zero();
    Mat2<T> m2 = Mat2<T>::Zero();
    Vec2<T> mean = Vec2<T>::Zero();  ///< spatial mean [measurement units]
    Mat2<T> cov = Mat2<T>::Identity();
    Mat2<T> cov_inv = Mat2<T>::Identity();
    T log_det = T(0);

    T rate() const { return rate_shape / rate_scans; }
  };

  Status init(const RfsFilterParams<T>& p) {
    params_ = p;
    model_ = p.measurement_model();
    log_volume_ = dmath::dlog(p.region_volume());
    sources_.clear();
    Source u;
    u.id = 0;
    u.uniform = true;
    u.rate_shape = p.clutter_rate;
    u.rate_scans = T(1);
    u.power.a = p.clutter_alpha_prior;
    u.power.b = p.clutter_scale * (p.clutter_alpha_prior - T(1));
    MPTRACK_TRY(sources_.push_back(u));
    next_id_ = 1;
    born_ = deleted_ = cap_hits_ = 0;
    return Status::kOk;
  }

  /// Forgetting of every statistic (seed 001 eq. (50) for the powers).
  void predict() {
    if (params_.clutter_mode == ClutterMode::kKnownUniform) return;
    const T v = params_.clutter_forgetting;
    for (Source& s : sources_) {
      s.rate_shape /= v;
      s.rate_scans /= v;
      model::forget_clamped(s.power, params_.power_forgetting, params_.min_alpha);
      s.m0 /= v;
      s.m1 /= v;
      s.m2 /= v;
    }
  }

  /// ln kappa_c(z_i, a_i) for every source and their total, for the
  /// measurements flagged valid.
  void evaluate(const Vec2<T>* z, const model::AmplitudeTerms<T>* amp, const bool* valid, std::size_t n) {
    n_ = n;
    const bool use_amp = params_.amplitude.use_amplitude;
    for (std::size_t i = 0; i < n; ++i) {
      if (!valid[i]) continue;
      LogSum<T> total;
      for (std::size_t c = 0; c < sources_.size(); ++c) {
        const Source& s = sources_[c];
        T l = T(0);
        if (s.uniform) {
          l = dmath::dlog(s.rate()) - log_volume_;
        } else {
          const Vec2<T> v = z[i] - s.mean;
          l = dmath::dlog(s.rate()) + log_gauss2(v, s.cov_inv, s.log_det);
        }
        if (use_amp) {
          l += params_.clutter_mode == ClutterMode::kKnownUniform
                   ? model::log_clutter_amplitude_known(params_.clutter_scale, amp[i])
                   : model::log_clutter_amplitude(s.power, amp[i]);
        }
        log_source_[i][c] = l;
        total.add(l);
      }
      log_kappa_[i] = total.value();
    }
  }

  /// ln kappa(z_i, a_i) from the last evaluate().
  T log_intensity(std::size_t i) const { return log_kappa_[i]; }

  /// Expected clutter detections per scan (sum of the source rates).
  T total_rate() const {
    T r = T(0);
    for (const Source& s : sources_) r += s.rate();
    return r;
  }

  /// Conjugate updates from clutter_prob[i] = P(measurement i is clutter),
  /// then hot-spot seeding, deletion and merging (map mode only).
  void update(const Vec2<T>* z, const model::AmplitudeTerms<T>* amp, const bool* valid,
              const T* clutter_prob) {
    if (params_.clutter_mode == ClutterMode::kKnownUniform) return;
    const bool use_amp = params_.amplitude.use_amplitude;
    for (std::size_t c = 0; c < sources_.size(); ++c) {
      Source& s = sources_[c];
      T sum_r = T(0);
      T sum_re = T(0);
      Vec2<T> s1 = Vec2<T>::Zero();
      Mat2<T> s2 = Mat2<T>::Zero();
      for (std::size_t i = 0; i < n_; ++i) {
        if (!valid[i]) continue;
        const T r = clutter_prob[i] * dmath::dexp(log_source_[i][c] - log_kappa_[i]);
        share_[i] = c == 0 ? r : share_[i];
        sum_r += r;
        sum_re += r * amp[i].clutter_excess;
        s1 += r * z[i];
        s2 += r * (z[i] * z[i].transpose());
      }
      s.rate_shape += sum_r;
      s.rate_scans += T(1);
      if (use_amp) {
        s.power.a += sum_r;
        s.power.b += sum_re;
      }
      s.m0 += sum_r;
      s.m1 += s1;
      s.m2 += s2;
    }
    if (params_.clutter_mode != ClutterMode::kEstimatedMap) return;
    refresh_geometry();
    delete_weak();
    seed_hotspots(z, amp, valid);
  }

  /// Appends the clutter map (uniform source first) to `out`.
  template <std::size_t N>
  void report(StaticVector<ClutterReport<T>, N>& out) const {
    for (const Source& s : sources_) {
      ClutterReport<T> r;
      r.id = s.id;
      r.uniform = s.uniform;
      r.mean = s.mean;
      r.covariance = s.uniform ? Mat2<T>::Zero() : s.cov;
      r.expected_count = s.rate();
      r.cnr = mean_power(s) - T(1);
      if (out.push_back(r) != Status::kOk) return;
    }
  }

  std::size_t size() const { return sources_.size(); }
  const Source& source(std::size_t c) const { return sources_[c]; }
  std::uint64_t born() const { return born_; }
  std::uint64_t deleted() const { return deleted_; }
  std::uint64_t cap_hits() const { return cap_hits_; }

 private:
  // Mean clutter power E[a^2] = sigma0^(1/b) Gamma(1 + 1/b) (docs/algorithms/models.md
  // §Amplitude likelihoods).
  T mean_power(const Source& s) const {
    const T b = params_.weibull_shape;
    const T sigma0 = params_.clutter_mode == ClutterMode::kKnownUniform ? params_.clutter_scale
                                                                       : s.power.mean();
    return dmath::dexp(dmath::dlog(sigma0) / b + dmath::dlgamma(T(1) + T(1) / b));
  }

  // mu = m1/m0, C = m2/m0 - mu mu^T with the diagonal floored at R's and
  // the correlation kept below 0.95 (C stays SPD).
  void refresh_geometry() {
    for (Source& s : sources_) {
      if (s.uniform || !(s.m0 > T(1e-9))) continue;
      s.mean = s.m1 / s.m0;
      Mat2<T> c = s.m2 / s.m0 - s.mean * s.mean.transpose();
      set_cov(s, c);
    }
  }

  void set_cov(Source& s, Mat2<T> c) {
    for (int k = 0; k < 2; ++k) {
      if (!(c(k, k) > model_.R(k, k))) c(k, k) = model_.R(k, k);
    }
    const T lim = T(0.95) * std::sqrt(c(0, 0) * c(1, 1));
    T off = T(0.5) * (c(0, 1) + c(1, 0));
    if (off > lim) off = lim;
    if (off < -lim) off = -lim;
    c(0, 1) = off;
    c(1, 0) = off;
    s.cov = c;
    if (!invert_spd2(s.cov, s.cov_inv, s.log_det)) {
      s.cov = model_.R;
      (void)invert_spd2(s.cov, s.cov_inv, s.log_det);
    }
  }

  void delete_weak() {
    for (std::size_t c = sources_.size(); c > 1; --c) {
      if (sources_[c - 1].rate() < params_.hotspot_min_rate) {
        (void)sources_.erase(c - 1);
        ++deleted_;
      }
    }
  }

  // Greedy box seeding over the measurements uniform clutter explains
  // (share > 0.5): the box with the most such points first, ties to the
  // lowest index; members are used once.
  void seed_hotspots(const Vec2<T>* z, const model::AmplitudeTerms<T>* amp, const bool* valid) {
    const T hw0 = params_.hotspot_half_width0;
    const T hw1 = params_.hotspot_half_width1;
    const T box_volume = T(4) * hw0 * hw1;
    const Source& u = sources_[0];
    const T expected = u.rate() * box_volume / params_.region_volume();
    const T need_raw = T(3) * expected + T(1);
    const T min_points = T(params_.hotspot_min_points);
    const T need = need_raw > min_points ? need_raw : min_points;
    for (std::size_t i = 0; i < n_; ++i) candidate_[i] = valid[i] && share_[i] > T(0.5);
    for (;;) {
      std::size_t best = n_;
      std::size_t best_count = 0;
      for (std::size_t i = 0; i < n_; ++i) {
        if (!candidate_[i]) continue;
        std::size_t count = 0;
        for (std::size_t j = 0; j < n_; ++j) {
          if (candidate_[j] && in_box(z[i], z[j], hw0, hw1)) ++count;
        }
        if (count > best_count) {
          best_count = count;
          best = i;
        }
      }
      if (best == n_ || T(best_count) < need) return;
      Source s;
      s.uniform = false;
      T sum_e = T(0);
      for (std::size_t j = 0; j < n_; ++j) {
        if (!candidate_[j] || !in_box(z[best], z[j], hw0, hw1)) continue;
        candidate_[j] = false;
        s.m0 += T(1);
        s.m1 += z[j];
        s.m2 += z[j] * z[j].transpose();
        sum_e += amp[j].clutter_excess;
      }
      if (sources_.full()) {
        ++cap_hits_;
        return;
      }
      s.id = next_id_++;
      s.rate_shape = s.m0;
      s.rate_scans = T(1);
      s.power.a = T(1) + s.m0;
      s.power.b = sum_e > T(0) ? sum_e : params_.clutter_scale * s.m0;
      if (!params_.amplitude.use_amplitude) s.power = sources_[0].power;
      s.mean = s.m1 / s.m0;
      set_cov(s, s.m2 / s.m0 - s.mean * s.mean.transpose());
      // These points were credited to the uniform source this scan.
      Source& uni = sources_[0];
      uni.rate_shape = uni.rate_shape - s.m0 > T(1e-3) ? uni.rate_shape - s.m0 : T(1e-3);
      (void)sources_.push_back(s);
      ++born_;
    }
  }

  static bool in_box(const Vec2<T>& a, const Vec2<T>& b, T hw0, T hw1) {
    const T d0 = a(0) - b(0);
    const T d1 = a(1) - b(1);
    return d0 <= hw0 && d0 >= -hw0 && d1 <= hw1 && d1 >= -hw1;
  }

  RfsFilterParams<T> params_;
  MeasurementModel<T> model_;
  T log_volume_ = T(0);
  StaticVector<Source, MaxSources + 1> sources_;
  std::uint32_t next_id_ = 1;
  std::size_t n_ = 0;
  std::array<std::array<T, MaxSources + 1>, MaxMeasurements> log_source_{};
  std::array<T, MaxMeasurements> log_kappa_{};
  std::array<T, MaxMeasurements> share_{};
  std::array<bool, MaxMeasurements> candidate_{};
  std::uint64_t born_ = 0, deleted_ = 0, cap_hits_ = 0;
};

}  // namespace mptrack::rfs
