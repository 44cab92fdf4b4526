// Per-frame super-resolution sparse Bayesian learning (SBL) detector with
// gridless refinement: the detector of seed 004's detect-then-track baseline
// (docs/algorithms/sbl.md). Raw MIMO frame in, polar measurements out, the
// same shape as frontend::FrontEnd::process so a harness can swap the two:
//
//   SblDetector<float> det;                    // place it statically (88 KB float)
//   MPTRACK_TRY(det.init(SblParams{}));         // validates, builds the tables
//   per frame:
//     Status s = det.process(cube, scan);      // scan: Scan<float, N>
//     det.detection(i).cov_m2                  // Cartesian covariance of measurement i
//
// Per frame (docs/algorithms/sbl.md §Algorithm): whitened spectrum z
// (frontend/mimo_spectrum.h); then, greedily, the peak of the residual
// range/angle map (model/mimo_range_angle_map.h) becomes a component if its
// normalised power |s^H r|^2 / ||s||^2 >= eta; its position is refined by
// Gauss-Newton (sbl/position_refine.h); then joint iterations: amplitude
// posterior with per-component precisions gamma_k (model/joint_amplitude.h),
// 1/gamma_k = |mu_k|^2 + C_kk, and one Gauss-Newton step over all amplitudes and
// positions together (sbl/joint_gauss_newton.h), until no position moves by
// tolerance_m or max_iterations; components whose SNR (|mu_k|^2 + C_kk) ||s_k||^2 < eta
// are pruned. Adding stops when the peak is below eta, an added component is
// pruned, or max_components is reached.
//
// Measurement fields: range_m = |p|; azimuth_rad = bearing_to_azimuth(atan2(x, y))
// (CCW from +x, measurement_convert.h); amplitude = sqrt(estimated SNR);
// doppler_mps = 0 (has_doppler false). Strongest first. detection(i) holds the
// Cartesian position, covariance R = (2 e Re{J^H J})^-1 [m^2], SNR and mu.
#pragma once

#include <cstddef>
#include <cstdint>

#include <Eigen/Core>

#include "mptrack/frontend/front_end.h"
#include "mptrack/frontend/measurement_convert.h"
#include "mptrack/frontend/mimo_spectrum.h"
#include "mptrack/frontend/radar_caps.h"
#include "mptrack/frontend/radar_cube.h"
#include "mptrack/math/detmath.h"
#include "mptrack/measurement.h"
#include "mptrack/model/joint_amplitude.h"
#include "mptrack/model/mimo_atom.h"
#include "mptrack/model/mimo_range_angle_map.h"
#include "mptrack/sbl/joint_gauss_newton.h"
#include "mptrack/sbl/position_refine.h"
#include "mptrack/sbl/sbl_params.h"
#include "mptrack/static_vector.h"
#include "mptrack/status.h"
#include "mptrack/validate.h"

namespace mptrack {

/// One detection of the last frame, in the order of the emitted measurements.
template <class T>
struct SblDetection {
  T x_m = T(0), y_m = T(0);                                    ///< position [m]
  Eigen::Matrix<T, 2, 2> cov_m2 = Eigen::Matrix<T, 2, 2>::Zero();  ///< (2 e Re{J^H J})^-1 [m^2]
  T snr = T(0);                                                ///< (|mu|^2 + C_kk) ||s||^2 [-]
  model::Cx<T> mu{};                                           ///< posterior mean amplitude [-]
};

/// Counters; nothing is dropped without being counted.
struct SblCounters {
  std::uint64_t frames = 0;               ///< frames processed successfully
  std::uint64_t frames_rejected = 0;      ///< not initialised, NaN/Inf, over the ceiling, all zero
  std::uint64_t components_added = 0;     ///< greedy additions
  std::uint64_t components_pruned = 0;    ///< removed by the SNR test
  std::uint64_t outside_gate = 0;         ///< kept components outside range gate or bearing span
  std::uint64_t detections = 0;           ///< measurements emitted
  std::uint64_t detections_over_cap = 0;  ///< dropped because the Scan was full
  std::uint64_t numerical_failures = 0;   ///< amplitude precision not positive definite
};

template <class T, class Caps = SblDefaultCaps, class RadarCaps = frontend::Seed004RadarCaps>
class SblDetector {
  static_assert(sbl_caps_are_valid<Caps>());
  using Spectrum = frontend::MimoSpectrum<T, RadarCaps>;

 public:
  static constexpr std::size_t kNV = Spectrum::kNumVirtual;
  static constexpr std::size_t kKB = Spectrum::kNumBins;
  static constexpr std::size_t kSize = Spectrum::kSize;
  static constexpr std::size_t kMaxK = Caps::kMaxComponents;
  using Basis = model::MimoAtomBasis<T, kNV, kKB>;
  using Atom = model::MimoAtom<T, kNV, kKB>;

  /// Every field (SblParams::validate) and the fit to the caps: max_components,
  /// max_iterations, the map grid, the chirp within a slot.
  static Status validate(const SblParams& p, ParamError* where = nullptr) {
    MPTRACK_TRY(p.validate(where));
    MPTRACK_CHECK_PARAM(where, "max_components", check_at_most(p.max_components, Caps::kMaxComponents, "Caps::kMaxComponents"));
    MPTRACK_CHECK_PARAM(where, "max_iterations", check_at_most(p.max_iterations, Caps::kMaxIterations, "Caps::kMaxIterations"));
    const double lx = p.chirp_duration_s * p.sample_rate_hz + 0.5;
    MPTRACK_CHECK_PARAM(where, "chirp_duration_s",
                        check(lx >= 1.0 && lx < static_cast<double>(RadarCaps::kNumSamples) + 1.0));
    MPTRACK_CHECK_PARAM(where, "range_step_m",
                        check((p.max_range_m - p.min_range_m) / p.range_step_m + 1.0 <=
                              static_cast<double>(Caps::kMaxRangeCells)));
    MPTRACK_CHECK_PARAM(where, "sin_step",
                        check(2.0 * dmath::dsin(p.max_abs_bearing_rad) / p.sin_step + 1.0 <=
                              static_cast<double>(Caps::kMaxAngleCells)));
    return Status::kOk;
  }

  /// Validates p, builds U[k], the atom basis and the map. On failure
  /// process() returns kNotInitialized.
  Status init(const SblParams& p) {
    initialized_ = false;
    MPTRACK_TRY(validate(p));
    frontend::MimoSpectrumConfig sc;
    sc.bandwidth_hz = p.bandwidth_hz;
    sc.chirp_duration_s = p.chirp_duration_s;
    sc.sample_rate_hz = p.sample_rate_hz;
    sc.noise_variance_v2 = p.noise_variance_v2;
    MPTRACK_TRY(spectrum_.init(sc));
    // rho~(r) = sqrt(mean RCS) A G lambda / ((4 pi)^1.5 sigma_w r^2) (seed 004 Table I;
    // docs/algorithms/sbl.md §Signal model).
    const double lambda = model::kLightSpeed_mps<double> / p.carrier_hz;
    const double four_pi = 2.0 * dmath::kTwoPi<double>;
    const double rho_scale = std::sqrt(p.mean_rcs_m2) * p.tx_amplitude * p.antenna_gain * lambda /
                             (four_pi * std::sqrt(four_pi) * std::sqrt(p.noise_variance_v2));
    basis_.init(spectrum_.u_re(), spectrum_.u_im(), spectrum_.f_hz(), static_cast<T>(p.element_spacing_wavelengths),
                static_cast<T>(rho_scale));
    u_max_ = dmath::dsin(p.max_abs_bearing_rad);
    if (!map_.init(basis_, static_cast<T>(p.min_range_m), static_cast<T>(p.max_range_m),
                   static_cast<T>(p.range_step_m), static_cast<T>(u_max_), static_cast<T>(p.sin_step))) {
      return Status::kInvalidArgument;
    }
    params_ = p;
    eta_ = static_cast<T>(p.eta);
    limits_.steps = p.gauss_newton_steps;
    limits_.tolerance_m = static_cast<T>(p.tolerance_m);
    limits_.max_step_m = static_cast<T>(p.max_step_m);
    max_abs_sample_ = static_cast<float>(p.max_abs_sample);
    initialized_ = true;
    return Status::kOk;
  }

  /// Processes one frame. out is cleared first; out.time_us = cube.time_us,
  /// out.has_doppler = false. kNotInitialized before init(); kInvalidInput (out
  /// empty, counted in frames_rejected) if the cube holds NaN/Inf, a sample
  /// beyond max_abs_sample, or only zeros. kCapacityExceeded (out valid) if
  /// detections did not fit the Scan (counted, last_frame_dropped()); kNumericalError
  /// (out valid, from the components before the failure) if an amplitude
  /// precision was not positive definite; else kOk.
  /// times (optional, the front end's type so a harness can swap the two):
  /// kRange = whitened spectrum, kDoppler = 0, kAngle = residual-map searches,
  /// kDetect = refinement, pruning and output.
  template <std::size_t N>
  Status process(const frontend::RadarCube<RadarCaps>& cube, Scan<T, N>& out,
                 frontend::FrontEndStageTimes* times = nullptr) {
    out.measurements.clear();
    out.time_us = cube.time_us;
    out.has_doppler = false;
    last_.clear();
    last_dropped_ = 0;
    n_ = 0;
    if (times != nullptr) times->ticks = {};
    const std::uint32_t t0 = tick(times);
    if (!initialized_ || !frame_ok(cube) || spectrum_.process(cube) != Status::kOk) {
      ++counters_.frames_rejected;
      return initialized_ ? Status::kInvalidInput : Status::kNotInitialized;
    }
    const std::uint32_t t1 = tick(times);
    std::uint32_t search = 0;
    const Status s = reconstruct(times, search);
    if (s == Status::kNumericalError) ++counters_.numerical_failures;
    const bool over = emit(out);
    const std::uint32_t t2 = tick(times);
    if (times != nullptr) {
      times->ticks[static_cast<std::size_t>(frontend::FrontEndStage::kRange)] = t1 - t0;
      times->ticks[static_cast<std::size_t>(frontend::FrontEndStage::kAngle)] = search;
      times->ticks[static_cast<std::size_t>(frontend::FrontEndStage::kDetect)] = (t2 - t1) - search;
    }
    ++counters_.frames;
    if (s != Status::kOk) return s;
    return over ? Status::kCapacityExceeded : Status::kOk;
  }

  /// Detections of the last frame, index-aligned with its measurements.
  std::size_t num_detections() const { return last_.size(); }
  const SblDetection<T>& detection(std::size_t i) const { return last_[i]; }
  const SblCounters& counters() const { return counters_; }
  /// Detections of the last frame dropped because the Scan was full.
  std::size_t last_frame_dropped() const { return last_dropped_; }
  const Basis& basis() const { return basis_; }
  bool initialized() const { return initialized_; }

 private:
  bool frame_ok(const frontend::RadarCube<RadarCaps>& cube) const {
    std::size_t zero = 0;
    for (const float x : cube.iq) {
      if (!is_finite(x) || x > max_abs_sample_ || x < -max_abs_sample_) return false;
      if (x == 0.0f) ++zero;
    }
    return zero < cube.iq.size();
  }

  /// residual = z - sum_k mu_k s_k.
  void rebuild_residual() {
    for (std::size_t i = 0; i < kSize; ++i) {
      res_re_[i] = spectrum_.z_re()[i];
      res_im_[i] = spectrum_.z_im()[i];
    }
    for (std::size_t k = 0; k < n_; ++k) model::atom_accumulate(atoms_[k], model::cx_scale(mu_[k], T(-1)), res_re_.data(), res_im_.data());
  }

  /// Joint amplitude posterior at the current positions, then the SBL
  /// precision update 1/gamma_k = |mu_k|^2 + C_kk (seed 004 eqs. (12)-(14)
  /// with a per-component prior; docs/algorithms/sbl.md §Joint amplitudes).
  Status solve_amplitudes() {
    MPTRACK_TRY(amp_.reset(n_));
    std::array<Cx, kMaxK> c{};
    for (std::size_t k = 0; k < n_; ++k) {
      c[k] = model::atom_inner(atoms_[k], spectrum_.z_re(), spectrum_.z_im());
      for (std::size_t j = 0; j < k; ++j) amp_.lambda(k, j) = sbl::gram_from_factors(atoms_[k], atoms_[j]);
      amp_.lambda(k, k) = Cx{model::atom_norm2(basis_, atoms_[k]) + gamma_[k], T(0)};
    }
    MPTRACK_TRY(amp_.solve(c.data()));
    for (std::size_t k = 0; k < n_; ++k) {
      mu_[k] = amp_.mu(k);
      e_[k] = model::cx_norm2(mu_[k]) + amp_.cov(k, k).re;
      T g = T(1) / e_[k];
      if (!(g >= kGammaMin)) g = kGammaMin;
      if (!(g <= kGammaMax)) g = kGammaMax;
      gamma_[k] = g;
    }
    return Status::kOk;
  }

  /// Joint iterations (docs/algorithms/sbl.md §Algorithm): re-freeze rho~ at the
  /// current ranges, amplitude posterior and precisions, then one joint
  /// Gauss-Newton step over all amplitudes and positions; until no position
  /// moves by tolerance_m or max_iterations.
  Status joint_refine() {
    for (std::size_t it = 0; it < params_.max_iterations; ++it) {
      for (std::size_t k = 0; k < n_; ++k) model::make_atom(basis_, atoms_[k].x, atoms_[k].y, T(-1), atoms_[k]);
      MPTRACK_TRY(solve_amplitudes());
      const T moved = gn_.step(basis_, atoms_.data(), mu_.data(), gamma_.data(), n_, spectrum_.z_re(),
                               spectrum_.z_im(), res_re_.data(), res_im_.data(), limits_.max_step_m);
      if (moved < limits_.tolerance_m) break;
    }
    return solve_amplitudes();
  }

  /// Removes components with SNR < eta; true if component `newest` was removed.
  bool prune(std::size_t newest) {
    bool newest_gone = false;
    std::size_t w = 0;
    for (std::size_t k = 0; k < n_; ++k) {
      if (e_[k] * model::atom_norm2(basis_, atoms_[k]) >= eta_) {
        atoms_[w] = atoms_[k];
        gamma_[w] = gamma_[k];
        mu_[w] = mu_[k];
        e_[w] = e_[k];
        ++w;
      } else {
        ++counters_.components_pruned;
        if (k == newest) newest_gone = true;
      }
    }
    n_ = w;
    return newest_gone;
  }

  static std::uint32_t tick(const frontend::FrontEndStageTimes* t) {
    return (t != nullptr && t->clock != nullptr) ? t->clock() : 0u;
  }

  /// Greedy addition with joint refinement and pruning (the whole frame);
  /// search_ticks accumulates the residual-map searches.
  Status reconstruct(const frontend::FrontEndStageTimes* times, std::uint32_t& search_ticks) {
    const T norm = T(1) / (static_cast<T>(kNV) * basis_.e_u());  // |B|^2 -> |s^H r|^2 / ||s||^2
    rebuild_residual();
    // An addition may prune an older component instead of itself; the cap on
    // additions keeps such a frame from cycling.
    for (std::size_t added = 0; n_ < params_.max_components && added < 2 * params_.max_components; ++added) {
      const std::uint32_t ts = tick(times);
      const model::MapPeak<T> pk =
          map_.best(basis_, res_re_.data(), res_im_.data(), [](T, T, T p) { return p; });
      search_ticks += tick(times) - ts;
      if (!pk.found || pk.beam_power * norm < eta_) break;
      const T u = pk.sin_t;
      Atom& at = atoms_[n_];
      model::make_atom(basis_, pk.range_m * u, pk.range_m * std::sqrt((T(1) - u) * (T(1) + u)), T(-1), at);
      (void)sbl::refine_position(basis_, at, res_re_.data(), res_im_.data(), Cx{}, T(0), true, limits_);
      const Cx c = model::atom_inner(at, res_re_.data(), res_im_.data());
      const T n2 = model::atom_norm2(basis_, at);
      const T p = model::cx_norm2(c) / (n2 * n2);  // |mu_ML|^2
      gamma_[n_] = p > T(1) / kGammaMax ? T(1) / p : kGammaMax;
      mu_[n_] = Cx{};
      ++n_;
      ++counters_.components_added;
      const Status s = joint_refine();
      if (s != Status::kOk) {
        --n_;  // drop the newest, keep the frame's earlier solution
        if (solve_amplitudes() != Status::kOk) n_ = 0;
        return Status::kNumericalError;
      }
      const bool newest_pruned = prune(n_ - 1);
      MPTRACK_TRY(solve_amplitudes());
      rebuild_residual();
      if (newest_pruned) break;
    }
    return Status::kOk;
  }

  /// Measurements strongest first; true if some did not fit the Scan.
  template <std::size_t N>
  bool emit(Scan<T, N>& out) {
    std::array<std::size_t, kMaxK> order{};
    std::array<T, kMaxK> snr{};
    for (std::size_t k = 0; k < n_; ++k) {
      snr[k] = e_[k] * model::atom_norm2(basis_, atoms_[k]);
      std::size_t pos = k;  // insertion sort, ties keep the component order
      while (pos > 0 && snr[order[pos - 1]] < snr[k]) {
        order[pos] = order[pos - 1];
        --pos;
      }
      order[pos] = k;
    }
    bool over = false;
    for (std::size_t i = 0; i < n_; ++i) {
      const Atom& at = atoms_[order[i]];
      const T bearing = dmath::datan2(at.x, at.y);
      if (at.r < static_cast<T>(params_.min_range_m) || at.r > static_cast<T>(params_.max_range_m) ||
          !(bearing <= static_cast<T>(params_.max_abs_bearing_rad)) ||
          !(bearing >= -static_cast<T>(params_.max_abs_bearing_rad))) {
        ++counters_.outside_gate;
        continue;
      }
      if (out.measurements.size() >= N) {
        ++counters_.detections_over_cap;
        ++last_dropped_;
        over = true;
        continue;
      }
      Measurement<T> m;
      m.range_m = at.r;
      m.azimuth_rad = frontend::bearing_to_azimuth(bearing);
      m.amplitude = std::sqrt(snr[order[i]]);
      (void)out.measurements.push_back(m);
      SblDetection<T> d;
      d.x_m = at.x;
      d.y_m = at.y;
      d.snr = snr[order[i]];
      d.mu = mu_[order[i]];
      const Eigen::Matrix<T, 2, 2> info = T(2) * e_[order[i]] * model::atom_fisher(basis_, at);
      const T det = info(0, 0) * info(1, 1) - info(0, 1) * info(1, 0);
      d.cov_m2(0, 0) = info(1, 1) / det;
      d.cov_m2(1, 1) = info(0, 0) / det;
      d.cov_m2(0, 1) = -info(0, 1) / det;
      d.cov_m2(1, 0) = d.cov_m2(0, 1);
      (void)last_.push_back(d);
      ++counters_.detections;
    }
    return over;
  }

  using Cx = model::Cx<T>;
  static constexpr T kGammaMin = T(1e-6);  ///< prior precision floor (|mu|^2 <= 1e6 at the mean RCS)
  static constexpr T kGammaMax = T(1e6);   ///< ceiling (a component explained away)

  Spectrum spectrum_{};
  Basis basis_{};
  model::MimoRangeAngleMap<T, kNV, kKB, Caps::kMaxRangeCells, Caps::kMaxAngleCells> map_{};
  model::JointAmplitude<T, kMaxK> amp_{};
  sbl::JointGaussNewton<T, kNV, kKB, kMaxK> gn_{};
  std::array<T, kSize> res_re_{};
  std::array<T, kSize> res_im_{};
  std::array<Atom, kMaxK> atoms_{};
  std::array<Cx, kMaxK> mu_{};
  std::array<T, kMaxK> gamma_{};
  std::array<T, kMaxK> e_{};  ///< |mu_k|^2 + C_kk
  std::size_t n_ = 0;
  std::size_t last_dropped_ = 0;
  StaticVector<SblDetection<T>, kMaxK> last_{};
  SblCounters counters_{};
  SblParams params_{};
  sbl::RefineLimits<T> limits_{};
  T eta_ = T(12.8);
  double u_max_ = 0.0;
  float max_abs_sample_ = 1e6f;
  bool initialized_ = false;
};

}  // namespace mptrack
