// Sidelobe-aware peak grouping: drops a detection candidate that a stronger
// candidate's range or angle sidelobes explain.
//
// A strong target's sidelobes are local maxima of the power map that pass
// CFAR (docs/results/seed004.md §Sidelobe control: a 28 dB drone under the
// rectangular range window gives ~1.3 false detections a frame). Their level
// relative to the target is known from the processing alone:
//   range: the matched filter's response to an echo delayed by a
//     fractional lag x (samples), R(x) = sum_i u(i + x) w[i] conj(u[i])
//     (range_matched_filter.h; u the continuous chirp, zero outside the
//     pulse), so an echo between bins g0 and g0 + 1 puts |R(k - delta)|^2 in
//     bin g0 + k;
//   angle: the beamformer's response to a plane wave between FFT bins,
//     A(x) = |sum_v w_v exp(j 2 pi v x / N_A)|^2, x the offset in bins
//     (angle_processor.h; periodic in N_A).
// init() tabulates the envelope E[k] = the largest ratio, over sub-bin
// offsets delta = 0, 1/8, .., 7/8, of the response k bins from the sampled
// peak beyond the main lobe's first null to the sampled peak itself, made
// non-increasing in k (an envelope, not
// a pattern with nulls that move with delta). A point target's map response
// is the product of its range, angle and Doppler responses (the stages are
// separable), so candidate c is dropped if a kept, stronger candidate s
// (candidates visited strongest first) lies at most kMaxRangeLag range bins
// away and
//   P_c < P_s m E_range[|g_c - g_s|] E_angle[|a_c - a_s|] E_doppler[|d_c - d_s|]
// (angle and Doppler distances circular; E_doppler the Doppler FFT's
// response to a tone between bins, as the angle one with chirps for
// channels; E[0] = E[1] = 1: adjacent bins are inside the local-maximum
// neighbourhood and never both candidates),
// with the margin m = 10^(margin_db / 10) for the noise added to a sidelobe.
// Range lags beyond kMaxRangeLag are not grouped (an unwindowed chirp's
// sidelobes there are ~30 dB down). A target below a stronger one's
// envelope plus the margin is lost with the sidelobes: the resolution cost.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "mptrack/frontend/frontend_params.h"
#include "mptrack/frontend/peak_list.h"
#include "mptrack/frontend/radar_caps.h"
#include "mptrack/frontend/reference_chirp.h"
#include "mptrack/frontend/window.h"
#include "mptrack/math/constants.h"
#include "mptrack/math/detmath.h"
#include "mptrack/status.h"

namespace mptrack::frontend {

template <class Caps>
class SidelobeFilter {
  static_assert(radar_caps_are_valid<Caps>());

 public:
  static constexpr std::size_t kNumVirtual = Caps::kNumTx * Caps::kNumRx;
  static constexpr std::size_t kNa = Caps::kNumAngleBins;
  static constexpr std::size_t kNc = Caps::kNumChirps;
  /// Largest range lag grouped [bins].
  static constexpr std::size_t kMaxRangeLag = 16;
  /// Sub-bin offsets per bin over which the envelope is maximised.
  static constexpr std::size_t kSubBins = 8;

  /// Builds both envelopes (double, dmath only: bit-identical tables on every
  /// target). The chirp must fit (FrontEnd::validate checks it first).
  Status init(const FrontEndParams& p) {
    enabled_ = p.sidelobe_grouping;
    const double m = mptrack::dmath::dexp(p.sidelobe_margin_db * (mptrack::dmath::kLn10<double> / 10.0));
    const std::size_t len = chirp_samples(p);
    if (len < 1) return Status::kInvalidArgument;
    range_envelope(p, len);
    array_envelope(p.angle_window, kNumVirtual, kNa, angle_env_);
    if constexpr (kNc > 1) array_envelope(p.doppler_window, kNc, kNc, doppler_env_);
    margin_ = static_cast<float>(m);
    return Status::kOk;
  }

  /// Marks keep[i] for candidates[i] (strongest first); returns how many are
  /// dropped. With grouping off every candidate is kept.
  template <std::size_t N>
  std::size_t apply(const PeakList<N>& peaks, std::array<bool, N>& keep) const {
    std::size_t dropped = 0;
    for (std::size_t i = 0; i < peaks.size(); ++i) {
      keep[i] = true;
      if (!enabled_) continue;
      for (std::size_t j = 0; j < i; ++j) {
        if (keep[j] && explains(peaks[j], peaks[i])) {
          keep[i] = false;
          ++dropped;
          break;
        }
      }
    }
    return dropped;
  }

  /// Margin factor 10^(margin_db / 10) [-].
  float margin() const { return margin_; }
  /// Envelope at range lag k (k <= kMaxRangeLag) [-].
  float range_envelope_at(std::size_t k) const { return range_env_[k]; }
  /// Envelope at angle offset k (k <= kNa / 2) [-].
  float angle_envelope_at(std::size_t k) const { return angle_env_[k]; }
  /// Envelope at Doppler offset k (k <= kNc / 2; kNc > 1) [-].
  float doppler_envelope_at(std::size_t k) const { return doppler_env_[k]; }

 private:
  static std::size_t dist(std::size_t a, std::size_t b) { return a > b ? a - b : b - a; }
  static std::size_t circ_dist(std::size_t a, std::size_t b, std::size_t n) {
    const std::size_t d = dist(a, b);
    return d <= n - d ? d : n - d;
  }

  /// True if the sidelobes of s (stronger) explain c: the response of a
  /// point target is the product of the three axes' responses (the stages
  /// are separable), so the bound is the product of the envelopes.
  bool explains(const PeakCandidate& s, const PeakCandidate& c) const {
    const std::size_t dg = dist(s.range_bin, c.range_bin);
    if (dg > kMaxRangeLag) return false;
    float bound = s.power * margin_;
    bound = bound * range_env_[dg];
    bound = bound * angle_env_[circ_dist(s.angle_bin, c.angle_bin, kNa)];
    if constexpr (kNc > 1) bound = bound * doppler_env_[circ_dist(s.doppler_bin, c.doppler_bin, kNc)];
    return c.power < bound;
  }

  /// Sidelobe envelope: the largest over sub-bin offsets of
  /// response(k bins from the sampled peak) / response(sampled peak) for k
  /// beyond the main lobe's first null on that side (inside the main lobe
  /// the response falls monotonically and makes no local maximum, so a
  /// candidate there is another target or noise, not a sidelobe); then
  /// non-increasing in k, so inside the main lobe E is the peak sidelobe
  /// level beyond it. resp(x) is the power response x bins from the true peak.
  template <std::size_t K, class Resp>
  static void envelope(std::array<float, K>& env, const Resp& resp) {
    constexpr std::size_t kmax = K - 1;
    std::array<double, K> best{};
    // First null either side of the true peak: walk out in 1/16-bin steps
    // until the continuous response rises again.
    const double null_lo = first_null(resp, -1.0, static_cast<double>(kmax) + 1.0);
    const double null_hi = first_null(resp, 1.0, static_cast<double>(kmax) + 1.0);
    for (std::size_t s = 0; s < kSubBins; ++s) {
      const double delta = static_cast<double>(s) / static_cast<double>(kSubBins);
      // Sampled peak: bin 0 (offset -delta) or bin 1 (offset 1 - delta).
      const double p0 = resp(-delta);
      const double p1 = resp(1.0 - delta);
      const double peak = p0 >= p1 ? p0 : p1;
      const double centre = p0 >= p1 ? 0.0 : 1.0;
      if (!(peak > 0.0)) continue;
      for (std::size_t k = 1; k <= kmax; ++k) {
        const double kk = static_cast<double>(k);
        const double lo = centre - kk - delta;  // offsets from the true peak [bins]
        const double hi = centre + kk - delta;
        double r = 0.0;
        if (-lo >= null_lo) r = resp(lo);
        if (hi >= null_hi) {
          const double v = resp(hi);
          r = v > r ? v : r;
        }
        r = r / peak;
        if (r > best[k]) best[k] = r;
      }
    }
    double run = 0.0;  // running maximum from the far end
    for (std::size_t k = kmax + 1; k-- > 0;) {
      if (best[k] > run) run = best[k];
      env[k] = static_cast<float>(run);
    }
    env[0] = 1.0f;
    if (kmax >= 1) env[1] = 1.0f;  // adjacent bins: inside the 3x3x3 local-maximum test anyway
  }

  /// Distance [bins] from the true peak to the first null in direction dir
  /// (+-1), or `limit` if the response keeps falling that far.
  template <class Resp>
  static double first_null(const Resp& resp, double dir, double limit) {
    constexpr double kStep = 1.0 / 16.0;
    double prev = resp(0.0);
    for (double x = kStep; x <= limit; x += kStep) {
      const double v = resp(dir * x);
      if (v > prev) return x - kStep;
      prev = v;
    }
    return limit;
  }

  void range_envelope(const FrontEndParams& p, std::size_t len) {
    const ReferenceChirp chirp(p.bandwidth_hz, p.chirp_duration_s, p.sample_rate_hz, len);
    const auto resp = [&](double x) {
      double acc_r = 0.0;
      double acc_i = 0.0;
      for (std::size_t i = 0; i < len; ++i) {
        const double at = static_cast<double>(i) + x;
        if (at < 0.0 || at >= static_cast<double>(len)) continue;  // echo outside the pulse
        double yr = 1.0;
        double yi = 0.0;
        chirp.sample_at(at, yr, yi);
        double ur = 1.0;
        double ui = 0.0;
        chirp.sample(i, ur, ui);
        const double w = window_value(p.range_window, i, len);
        acc_r += w * (yr * ur + yi * ui);  // y conj(u)
        acc_i += w * (yi * ur - yr * ui);
      }
      return acc_r * acc_r + acc_i * acc_i;
    };
    envelope(range_env_, resp);
  }

  /// Envelope of an FFT over n windowed elements zero-padded to nfft bins:
  /// A(x) = |sum_v w_v exp(j 2 pi v x / nfft)|^2, x the offset in bins
  /// (angle: across the virtual channels; Doppler: across the chirps).
  template <std::size_t K>
  static void array_envelope(WindowType window, std::size_t n, std::size_t nfft, std::array<float, K>& env) {
    const auto resp = [&](double x) {
      double acc_r = 0.0;
      double acc_i = 0.0;
      for (std::size_t v = 0; v < n; ++v) {
        double s = 0.0;
        double c = 1.0;
        mptrack::dmath::dsincos(mptrack::dmath::kTwoPi<double> * static_cast<double>(v) * x /
                                    static_cast<double>(nfft), s, c);
        const double w = window_value(window, v, n);
        acc_r += w * c;
        acc_i += w * s;
      }
      return acc_r * acc_r + acc_i * acc_i;
    };
    envelope(env, resp);
  }

  std::array<float, kMaxRangeLag + 1> range_env_{};
  std::array<float, kNa / 2 + 1> angle_env_{};
  std::array<float, (kNc > 1 ? kNc / 2 + 1 : 1)> doppler_env_{};
  float margin_ = 1.0f;
  bool enabled_ = false;
};

}  // namespace mptrack::frontend
