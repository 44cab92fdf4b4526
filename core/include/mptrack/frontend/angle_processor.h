// Stage 3: angle processing across the virtual array.
//
// (a) FFT beamformer. For each range bin g and Doppler index d, the
//     windowed snapshot x_v (v = 0..N_V-1) is zero-padded to N_A =
//     kNumAngleBins and transformed:
//       B(g, d, h) = sum_v w_v x_v exp(-j 2 pi h v / N_A),   h = a - N_A/2,
//     i.e. the matched filter against the steering vector
//       [a(u)]_v = exp(j 2 pi (d/lambda) v u),  u = sin(theta_b),
//     sampled at u_h = h / (N_A d/lambda) (docs/algorithms/frontend.md §Angle: for d = lambda/2,
//     N_A = 64, u_h = h/32). The stage stores the power map |B|^2 laid out
//     [d][a][g] so that range lines (the CFAR axis) are contiguous. Bins with
//     |u_h| > sin(max_abs_bearing_rad) (or > 1, invisible space) are flagged
//     untested.
// (b) Refinement: the exact matched filter f(u) = |a(u)^H diag(w) x|^2 is
//     maximised by golden-section search over one grid step either side of
//     the FFT peak (unimodal there: the main lobe is 2/(N_V d/lambda) wide in
//     u, wider than two grid steps because N_A >= N_V). The phasors are a
//     fixed-order recurrence from one dmath::dsincos, so the result is
//     bit-exact across targets.
//
// Bearing convention: theta_b is measured from boresight (+y) towards the +x
// axis along which the array lies (seed 004 eq. (1): theta = atan2(x, y)). See
// measurement_convert.h for the mapping to Measurement::azimuth_rad.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "mptrack/dsp/fft_batch.h"
#include "mptrack/frontend/doppler_processor.h"
#include "mptrack/frontend/frontend_params.h"
#include "mptrack/frontend/window.h"
#include "mptrack/math/constants.h"
#include "mptrack/math/detmath.h"
#include "mptrack/status.h"
#include "mptrack/validate.h"

namespace mptrack::frontend {

/// Result of the steering-vector refinement.
struct AngleEstimate {
  float u = 0.0f;      ///< sine of theta_b [-]
  float power = 0.0f;  ///< |a(u)^H diag(w) x|^2 at u (same units as the power map)
};

template <class Caps>
class AngleProcessor {
  static_assert(radar_caps_are_valid<Caps>());

 public:
  static constexpr std::size_t kNa = Caps::kNumAngleBins;
  static constexpr std::size_t kNc = Caps::kNumChirps;
  static constexpr std::size_t kNumVirtual = Caps::kNumTx * Caps::kNumRx;
  static constexpr std::size_t kNumRangeBins = Caps::kNumRangeBins;
  static constexpr std::size_t kMapSize = kNc * kNa * kNumRangeBins;
  /// Range bins per block of process() (16 floats: one 64-byte map line).
  static constexpr std::size_t kBlock = 16;

  Status init(const FrontEndParams& p) {
    initialized_ = false;
    MPTRACK_TRY(check(is_valid_window(p.angle_window)));
    MPTRACK_TRY(check_range(p.element_spacing_wavelengths, 1e-3, 1.0));
    MPTRACK_TRY(check_range(p.max_abs_bearing_rad, 1e-6,
                            mptrack::dmath::kHalfPi<double>));
    MPTRACK_TRY(check_at_most(p.angle_refine_iterations, 64));
    MPTRACK_TRY(batch_.init());
    fill_window(p.angle_window, window_.data(), kNumVirtual);
    spacing_ = p.element_spacing_wavelengths;
    refine_iterations_ = p.angle_refine_iterations;
    const double u_max = mptrack::dmath::dsin(p.max_abs_bearing_rad);
    for (std::size_t a = 0; a < kNa; ++a) {
      const double u = bin_u(a);
      const double au = u < 0.0 ? -u : u;
      tested_[a] = (au <= u_max && au <= 1.0);
    }
    initialized_ = true;
    return Status::kOk;
  }

  /// Beamforms every (g, d) cell of dp into the power map.
  Status process(const DopplerProcessor<Caps>& dp) {
    if (!initialized_) return Status::kNotInitialized;
    // Blocks of kBlock range bins, one transform per lane (dsp::FftBatch:
    // each lane gets the bits of Fft<kNa>::forward() on its cell). Input
    // row v of a block is a 64-byte run of the Doppler stage's row (v, d)
    // and output row k the kBlock adjacent range bins of map line
    // (d, a = (k + N_A/2) mod N_A): one 64-byte store run, where one
    // transform per cell scattered down a column at stride kNumRangeBins.
    // Doppler outside, so both sides stream through their rows in order.
    // Every cell's operations are unchanged.
    for (std::size_t d = 0; d < kNc; ++d) {
      for (std::size_t g0 = 0; g0 < kNumRangeBins; g0 += kBlock) {
        const std::size_t lanes = kNumRangeBins - g0 < kBlock ? kNumRangeBins - g0 : kBlock;
        load_block(dp, g0, lanes, d);
        batch_.forward();
        store_powers(g0, lanes, d);
      }
    }
    return Status::kOk;
  }

  /// Exact steering-vector matched filter |a(u)^H diag(w) x|^2 for a snapshot.
  float steering_power(const float* xr, const float* xi, float u) const {
    float s = 0.0f;
    float c = 1.0f;
    const float phase = -mptrack::dmath::kTwoPi<float> * static_cast<float>(spacing_) * u;
    mptrack::dmath::dsincos(phase, s, c);
    float pr = 1.0f;  // phasor e^{-j 2 pi (d/lambda) v u}, by recurrence
    float pi = 0.0f;
    float acc_r = 0.0f;
    float acc_i = 0.0f;
    for (std::size_t v = 0; v < kNumVirtual; ++v) {
      const float yr = xr[v] * window_[v];
      const float yi = xi[v] * window_[v];
      acc_r = acc_r + (yr * pr - yi * pi);
      acc_i = acc_i + (yr * pi + yi * pr);
      const float nr = pr * c - pi * s;
      const float ni = pr * s + pi * c;
      pr = nr;
      pi = ni;
    }
    return acc_r * acc_r + acc_i * acc_i;
  }

  /// Refines the angle of the snapshot (g, d) around grid bin a.
  AngleEstimate refine(const DopplerProcessor<Caps>& dp, std::size_t g, std::size_t d,
                       std::size_t a) const {
    std::array<float, kNumVirtual> xr{};  // the snapshot, gathered from the channel rows
    std::array<float, kNumVirtual> xi{};
    for (std::size_t v = 0; v < kNumVirtual; ++v) {
      xr[v] = dp.snapshot_re(g, d, v);
      xi[v] = dp.snapshot_im(g, d, v);
    }
    return refine_snapshot(xr.data(), xi.data(), a);
  }

  /// Cells refine_lanes() takes at once.
  static constexpr std::size_t kRefineLanes = 8;

  /// refine() of n <= kRefineLanes cells (g[l], d[l], a[l]) into out[0..n):
  /// each lane does exactly refine()'s operations on its own cell, so the
  /// same bits. A search is a chain of dependent steps (each step's point
  /// depends on the last comparison, each steering power on a 12-step
  /// phasor recurrence), so one search leaves the core mostly idle; lanes
  /// side by side overlap them (docs/algorithms/frontend.md §Angle).
  /// The lanes' snapshots live in the processor (lanes_), not on the stack.
  void refine_lanes(const DopplerProcessor<Caps>& dp, const std::uint16_t* g, const std::uint16_t* d,
                    const std::uint16_t* a, std::size_t n, AngleEstimate* out) {
    constexpr std::size_t L = kRefineLanes;
    LaneSnapshot& y = lanes_;
    for (std::size_t l = 0; l < L; ++l) {
      const std::size_t k = l < n ? l : 0;  // spare lanes repeat cell 0 (never stored)
      for (std::size_t v = 0; v < kNumVirtual; ++v) {
        y.re[v][l] = dp.snapshot_re(g[k], d[k], v) * window_[v];
        y.im[v][l] = dp.snapshot_im(g[k], d[k], v) * window_[v];
      }
    }
    Lanes best_u{};
    Lanes best_p{};
    for (std::size_t l = 0; l < L; ++l) best_u[l] = static_cast<float>(bin_u(a[l < n ? l : 0]));
    steering_power_lanes(y, best_u, best_p);
    if (refine_iterations_ > 0) search_lanes(y, best_u, best_p);
    for (std::size_t l = 0; l < n; ++l) out[l] = AngleEstimate{best_u[l], best_p[l]};
  }

  /// sin(theta_b) at the centre of angle bin a.
  double bin_u(std::size_t a) const {
    const double h = static_cast<double>(a) - static_cast<double>(kNa / 2);
    return h / (static_cast<double>(kNa) * spacing_);
  }

  static constexpr std::size_t map_index(std::size_t g, std::size_t d, std::size_t a) {
    return (d * kNa + a) * kNumRangeBins + g;
  }
  /// Power map |B|^2, layout [d][a][g] (range contiguous).
  const float* power_map() const { return map_.data(); }
  float power(std::size_t g, std::size_t d, std::size_t a) const { return map_[map_index(g, d, a)]; }
  /// False for angle bins outside the configured span (not CFAR-tested).
  bool angle_tested(std::size_t a) const { return tested_[a]; }
  bool initialized() const { return initialized_; }

 private:
  // refine() on a snapshot given as kNumVirtual planar values (the scalar
  // reference refine_lanes() is tested against).
  AngleEstimate refine_snapshot(const float* xr, const float* xi, std::size_t a) const {
    AngleEstimate best;
    best.u = static_cast<float>(bin_u(a));
    best.power = steering_power(xr, xi, best.u);
    if (refine_iterations_ == 0) return best;
    const float step = static_cast<float>(1.0 / (static_cast<double>(kNa) * spacing_));
    float lo = best.u - step;
    float hi = best.u + step;
    if (lo < -1.0f) lo = -1.0f;
    if (hi > 1.0f) hi = 1.0f;
    // Golden-section search (Kiefer 1953), fixed iteration count.
    constexpr float kInvPhi = 0.618033988749894848f;
    float x1 = hi - kInvPhi * (hi - lo);
    float x2 = lo + kInvPhi * (hi - lo);
    float f1 = steering_power(xr, xi, x1);
    float f2 = steering_power(xr, xi, x2);
    for (std::size_t it = 0; it < refine_iterations_; ++it) {
      if (f1 > best.power) best = AngleEstimate{x1, f1};
      if (f2 > best.power) best = AngleEstimate{x2, f2};
      if (f1 >= f2) {  // maximum in [lo, x2]
        hi = x2;
        x2 = x1;
        f2 = f1;
        x1 = hi - kInvPhi * (hi - lo);
        f1 = steering_power(xr, xi, x1);
      } else {
        lo = x1;
        x1 = x2;
        f1 = f2;
        x2 = lo + kInvPhi * (hi - lo);
        f2 = steering_power(xr, xi, x2);
      }
    }
    if (f1 > best.power) best = AngleEstimate{x1, f1};
    if (f2 > best.power) best = AngleEstimate{x2, f2};
    return best;
  }

  using Lanes = std::array<float, kRefineLanes>;
  /// Windowed snapshots w_v x_v of kRefineLanes cells, lane innermost.
  struct LaneSnapshot {
    std::array<Lanes, kNumVirtual> re{};
    std::array<Lanes, kNumVirtual> im{};
  };

  // steering_power() at u[l] for every lane (its operations, lane by lane).
  void steering_power_lanes(const LaneSnapshot& y, const Lanes& u, Lanes& power) const {
    Lanes s{};
    Lanes c{};
    for (std::size_t l = 0; l < kRefineLanes; ++l) {
      const float phase = -mptrack::dmath::kTwoPi<float> * static_cast<float>(spacing_) * u[l];
      mptrack::dmath::dsincos(phase, s[l], c[l]);
    }
    Lanes pr{};
    Lanes pi{};
    Lanes acc_r{};
    Lanes acc_i{};
    pr.fill(1.0f);
    for (std::size_t v = 0; v < kNumVirtual; ++v) {
      for (std::size_t l = 0; l < kRefineLanes; ++l) {
        const float yr = y.re[v][l];
        const float yi = y.im[v][l];
        acc_r[l] = acc_r[l] + (yr * pr[l] - yi * pi[l]);
        acc_i[l] = acc_i[l] + (yr * pi[l] + yi * pr[l]);
        const float nr = pr[l] * c[l] - pi[l] * s[l];
        const float ni = pr[l] * s[l] + pi[l] * c[l];
        pr[l] = nr;
        pi[l] = ni;
      }
    }
    for (std::size_t l = 0; l < kRefineLanes; ++l) power[l] = acc_r[l] * acc_r[l] + acc_i[l] * acc_i[l];
  }

  // refine()'s golden-section search, every lane on its own bracket: the
  // branches become per-lane choices, each lane's values those of refine().
  void search_lanes(const LaneSnapshot& y, Lanes& best_u, Lanes& best_p) const {
    constexpr float kInvPhi = 0.618033988749894848f;
    const float step = static_cast<float>(1.0 / (static_cast<double>(kNa) * spacing_));
    Lanes lo{};
    Lanes hi{};
    Lanes x1{};
    Lanes x2{};
    for (std::size_t l = 0; l < kRefineLanes; ++l) {
      lo[l] = best_u[l] - step;
      hi[l] = best_u[l] + step;
      if (lo[l] < -1.0f) lo[l] = -1.0f;
      if (hi[l] > 1.0f) hi[l] = 1.0f;
      x1[l] = hi[l] - kInvPhi * (hi[l] - lo[l]);
      x2[l] = lo[l] + kInvPhi * (hi[l] - lo[l]);
    }
    Lanes f1{};
    Lanes f2{};
    steering_power_lanes(y, x1, f1);
    steering_power_lanes(y, x2, f2);
    std::array<bool, kRefineLanes> left{};  // maximum in [lo, x2]: refine()'s f1 >= f2
    Lanes xn{};
    Lanes fn{};
    for (std::size_t it = 0; it < refine_iterations_; ++it) {
      for (std::size_t l = 0; l < kRefineLanes; ++l) {
        keep_better(x1[l], f1[l], best_u[l], best_p[l]);
        keep_better(x2[l], f2[l], best_u[l], best_p[l]);
        left[l] = f1[l] >= f2[l];
        if (left[l]) {
          hi[l] = x2[l];
          x2[l] = x1[l];
          f2[l] = f1[l];
          x1[l] = hi[l] - kInvPhi * (hi[l] - lo[l]);
          xn[l] = x1[l];
        } else {
          lo[l] = x1[l];
          x1[l] = x2[l];
          f1[l] = f2[l];
          x2[l] = lo[l] + kInvPhi * (hi[l] - lo[l]);
          xn[l] = x2[l];
        }
      }
      steering_power_lanes(y, xn, fn);
      for (std::size_t l = 0; l < kRefineLanes; ++l) (left[l] ? f1[l] : f2[l]) = fn[l];
    }
    for (std::size_t l = 0; l < kRefineLanes; ++l) {
      keep_better(x1[l], f1[l], best_u[l], best_p[l]);
      keep_better(x2[l], f2[l], best_u[l], best_p[l]);
    }
  }

  static void keep_better(float x, float f, float& best_u, float& best_p) {
    if (f > best_p) {
      best_u = x;
      best_p = f;
    }
  }

  // Lane l of the batch = range bin g0 + l: the windowed snapshot of cell
  // (g0 + l, d), zero-padded to N_A. Input row v is the run g0..g0+lanes of
  // the Doppler stage's row (v, d). Lanes past the last range bin (a
  // partial last block) hold zeros, so they never grow or go NaN.
  void load_block(const DopplerProcessor<Caps>& dp, std::size_t g0, std::size_t lanes,
                  std::size_t d) {
    for (std::size_t v = 0; v < kNumVirtual; ++v) {
      const float w = window_[v];
      if (lanes == kBlock) {
        scale_row(dp.row_re(v, d) + g0, w, batch_.input_re(v));
        scale_row(dp.row_im(v, d) + g0, w, batch_.input_im(v));
        continue;
      }
      float* yr = batch_.input_re(v);
      float* yi = batch_.input_im(v);
      for (std::size_t l = 0; l < kBlock; ++l) {
        yr[l] = l < lanes ? dp.row_re(v, d)[g0 + l] * w : 0.0f;
        yi[l] = l < lanes ? dp.row_im(v, d)[g0 + l] * w : 0.0f;
      }
    }
    for (std::size_t v = kNumVirtual; v < kNa; ++v) batch_.zero_input(v);
  }

  static void scale_row(const float* __restrict x, float w, float* __restrict y) {
    for (std::size_t l = 0; l < kBlock; ++l) y[l] = x[l] * w;
  }

  // The no-alias facts as __restrict parameters, so GCC emits a vector loop
  // (it left it scalar with the rows and the map as plain pointers).
  static void power_row(const float* __restrict re, const float* __restrict im,
                        float* __restrict out) {
    for (std::size_t l = 0; l < kBlock; ++l) out[l] = re[l] * re[l] + im[l] * im[l];
  }

  // |B|^2 of output row k to map line (d, a), fftshift a = (k + N_A/2) mod N_A.
  void store_powers(std::size_t g0, std::size_t lanes, std::size_t d) {
    constexpr std::size_t kHalf = kNa / 2;
    for (std::size_t k = 0; k < kNa; ++k) {
      const std::size_t a = k < kHalf ? k + kHalf : k - kHalf;
      const float* br = batch_.output_re(k);
      const float* bi = batch_.output_im(k);
      float* out = map_.data() + map_index(g0, d, a);
      if (lanes == kBlock) {
        power_row(br, bi, out);
      } else {
        for (std::size_t l = 0; l < lanes; ++l) out[l] = br[l] * br[l] + bi[l] * bi[l];
      }
    }
  }

  dsp::FftBatch<kNa, kBlock> batch_{};
  std::array<float, kNumVirtual> window_{};
  std::array<float, kMapSize> map_{};
  std::array<bool, kNa> tested_{};
  LaneSnapshot lanes_{};  ///< refine_lanes() workspace
  double spacing_ = 0.5;
  std::size_t refine_iterations_ = 0;
  bool initialized_ = false;
};

}  // namespace mptrack::frontend
