// The MIMO matched-filter front end: raw ADC cube -> Scan of measurements.
//
//   FrontEnd<Seed004RadarCaps> fe;            // ~40 KB, place it statically
//   MPTRACK_TRY(fe.init(FrontEndParams{}));   // validates, builds all tables
//   per frame:
//     Status s = fe.process(cube, scan);      // scan: Scan<float, N>
//
// Pipeline (docs/algorithms/frontend.md): RangeMatchedFilter (fast-time pulse compression) ->
// DopplerProcessor (slow-time FFT when kNumChirps > 1) -> AngleProcessor
// (FFT beamformer, power map [d][a][g]) -> detection: every cell inside the
// range gate and the angle span that is a local maximum of the map (3x3x3
// neighbourhood; Doppler wraps; ties go to the lower cell index) and passes
// the CFAR test along range becomes a candidate (found threshold first: a
// constant-cost screen per line, cfar_screen.h, then the local-maximum and
// exact CFAR tests on the cells it keeps); the strongest
// min(max_detections, Caps::kMaxDetections, N) are kept (the rest counted),
// those a stronger candidate's range or angle sidelobes explain are dropped
// (sidelobe_filter.h; FrontEndParams::sidelobe_grouping, counted), the rest
// refined: angle by the steering-vector matched filter, range and
// Doppler by a parabola through the log powers of the bin and its two
// neighbours (offset clamped to +-0.5 bin; none at the map edge).
//
// Measurement fields: range_m = (g + delta) c / (2 f_s); azimuth_rad =
// bearing_to_azimuth(asin u) (CCW from +x, see measurement_convert.h);
// doppler_mps = radial velocity, positive receding; amplitude =
// sqrt(P_refined / z) with z the CFAR noise-power estimate, so amplitude^2
// is the SNR-like power ratio the MF-BP amplitude models expect.
// Measurements are ordered strongest first.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "mptrack/frontend/angle_processor.h"
#include "mptrack/frontend/cfar.h"
#include "mptrack/frontend/cfar_screen.h"
#include "mptrack/frontend/doppler_processor.h"
#include "mptrack/frontend/frontend_params.h"
#include "mptrack/frontend/measurement_convert.h"
#include "mptrack/frontend/peak_list.h"
#include "mptrack/frontend/radar_caps.h"
#include "mptrack/frontend/radar_cube.h"
#include "mptrack/frontend/range_matched_filter.h"
#include "mptrack/frontend/sidelobe_filter.h"
#include "mptrack/math/detmath.h"
#include "mptrack/measurement.h"
#include "mptrack/profile.h"
#include "mptrack/status.h"
#include "mptrack/validate.h"

namespace mptrack::frontend {

/// Processing stages, for per-stage timing.
enum class FrontEndStage : std::uint8_t { kRange = 0, kDoppler, kAngle, kDetect, kCount };

/// Optional per-stage timing: the caller supplies a cycle/tick source (from
/// platform/, core does not know clocks); process() stores per-stage deltas.
struct FrontEndStageTimes {
  std::uint32_t (*clock)() = nullptr;  ///< monotonic tick source; nullptr = no timing
  std::array<std::uint32_t, static_cast<std::size_t>(FrontEndStage::kCount)> ticks{};
};

/// Counters; nothing is dropped without being counted.
struct FrontEndCounters {
  std::uint64_t frames = 0;               ///< frames processed successfully
  std::uint64_t frames_rejected = 0;      ///< frames refused (not initialised, NaN/Inf input)
  std::uint64_t cells_tested = 0;         ///< exact CFAR tests run: local maxima in gate and
                                          ///< span among the cells the threshold screen kept
  std::uint64_t detections = 0;           ///< measurements emitted
  std::uint64_t detections_over_cap = 0;  ///< CFAR detections dropped by the per-frame cap
  std::uint64_t frames_over_ceiling = 0;  ///< float frames refused: a sample beyond max_abs_sample
                                          ///< (also in frames_rejected)
  std::uint64_t frames_all_zero = 0;      ///< frames refused: every sample exactly 0 (dead ADC
                                          ///< or link; also in frames_rejected)
  std::uint64_t frames_saturated = 0;     ///< int16 frames with more than saturation_fraction of
                                          ///< samples at full scale (processed, kPartial)
  std::uint64_t detections_nonfinite = 0; ///< detections dropped: amplitude not finite (F3)
  std::uint64_t detections_sidelobe = 0;  ///< candidates dropped as a stronger candidate's range
                                          ///< or angle sidelobe (sidelobe_filter.h)
};

template <class Caps>
class FrontEnd {
  static_assert(radar_caps_are_valid<Caps>());

 public:
  static constexpr std::size_t kNc = Caps::kNumChirps;
  static constexpr std::size_t kNa = Caps::kNumAngleBins;
  static constexpr std::size_t kNumRangeBins = Caps::kNumRangeBins;
  static constexpr std::size_t kNumVirtual = Caps::kNumTx * Caps::kNumRx;

  /// Checks every field (FrontEndParams::validate) and the fit to the
  /// radar caps: max_detections, the chirp within the range FFT, the CFAR
  /// window within a range line, a non-empty range gate. On failure names
  /// the field in *where (validate.h).
  static Status validate(const FrontEndParams& p, ParamError* where = nullptr) {
    MPTRACK_TRY(p.validate(where));
    MPTRACK_CHECK_PARAM(where, "max_detections", check_at_most(p.max_detections, Caps::kMaxDetections, "Caps::kMaxDetections"));
    const std::size_t len = chirp_samples(p);
    MPTRACK_CHECK_PARAM(where, "chirp_duration_s",
                        check(len >= 1 && len <= Caps::kNumSamples &&
                              len + kNumRangeBins - 1 <= RangeMatchedFilter<Caps>::kM));
    MPTRACK_CHECK_PARAM(where, "cfar.training_cells", check(p.cfar.min_line_length() <= kNumRangeBins));
    std::size_t g_lo = 0;
    std::size_t g_hi = 0;
    range_gate(p, g_lo, g_hi);
    MPTRACK_CHECK_PARAM(where, "max_range_m", check_above(g_hi, g_lo, "g_lo"));
    return Status::kOk;
  }

  /// Validates every parameter (validate() above) and builds all tables.
  /// On failure nothing may be processed (process() returns kNotInitialized).
  Status init(const FrontEndParams& p) {
    initialized_ = false;
    MPTRACK_TRY(validate(p));
    MPTRACK_TRY(rmf_.init(p));
    MPTRACK_TRY(dop_.init(p));
    MPTRACK_TRY(ang_.init(p));
    MPTRACK_TRY(cfar_.init(p.cfar));
    MPTRACK_TRY(sidelobe_.init(p));
    range_bin_m_ = frontend::range_bin_m(p);
    std::size_t g_lo = 0;
    std::size_t g_hi = 0;
    range_gate(p, g_lo, g_hi);
    gate_lo_ = g_lo;
    gate_hi_ = g_hi;
    max_detections_ = p.max_detections;
    min_noise_ = static_cast<float>(p.min_noise_power);
    // Flag when full-scale samples > fraction x total (integer compare, exact).
    saturated_limit_ = static_cast<std::size_t>(
        p.saturation_fraction * static_cast<double>(2 * RadarCubeT<Caps, float>::kNumComplex));
    initialized_ = true;
    return Status::kOk;
  }

  /// Processes one frame. out is cleared first; out.time_us = cube.time_us,
  /// out.has_doppler = (kNumChirps > 1). kNotInitialized before init();
  /// kInvalidInput (out left empty, counted in frames_rejected) if the cube
  /// holds NaN/Inf, a float sample beyond max_abs_sample (also
  /// frames_over_ceiling, F2), or only zeros (frames_all_zero: no data).
  /// Over-cap detections: the strongest are kept, the rest counted in
  /// counters().detections_over_cap and last_frame_dropped(), and the call
  /// returns kCapacityExceeded (out is valid: a success with losses).
  /// Otherwise kPartial (out is valid) if the int16 frame is saturated
  /// (frames_saturated) or a detection was dropped for a non-finite
  /// amplitude (detections_nonfinite, F3); else kOk.
  template <class Sample, std::size_t N>
  Status process(const RadarCubeT<Caps, Sample>& cube, Scan<float, N>& out,
                 FrontEndStageTimes* times = nullptr) {
    out.measurements.clear();
    out.time_us = cube.time_us;
    out.has_doppler = DopplerProcessor<Caps>::kHasDoppler;
    last_dropped_ = 0;
    if (!initialized_) {
      ++counters_.frames_rejected;
      return Status::kNotInitialized;
    }
    MPTRACK_PROFILE_STEP(g_frontend);
    // Range and Doppler run channel by channel (docs/algorithms/frontend.md
    // §Stage layouts): the Doppler stage reads a channel's profiles right
    // after the range stage wrote them, from cache. Each stage's time is the
    // sum over the channels.
    // The frame checks (docs/algorithms/frontend.md §Frame input and checks)
    // are tallied by the range stage as it reads the cube, and decided after
    // the last channel in the same order as one check pass before it would:
    // a sample beyond the ceiling (+-Inf included), then an all-zero frame,
    // then NaN. A refused frame's snapshots are never used.
    rmf_.begin_frame();
    Status s = Status::kOk;
    std::uint32_t range_ticks = 0;
    std::uint32_t doppler_ticks = 0;
    for (std::size_t v = 0; v < kNumVirtual; ++v) {
      const std::uint32_t a = tick(times);
      {
        MPTRACK_PROFILE_STAGE(g_frontend, FrontEndStage::kRange);
        s = rmf_.process_channel(cube, v);
      }
      const std::uint32_t b = tick(times);
      {
        MPTRACK_PROFILE_STAGE(g_frontend, FrontEndStage::kDoppler);
        MPTRACK_TRY(dop_.process_channel(rmf_, v));
      }
      const std::uint32_t c = tick(times);
      range_ticks += b - a;  // wraps correctly
      doppler_ticks += c - b;
    }
    const FrameTally& ft = rmf_.tally();
    if (ft.over_ceiling > 0 || ft.zero == cube.iq.size() || s != Status::kOk) {
      ++counters_.frames_rejected;
      if (ft.over_ceiling > 0) {
        ++counters_.frames_over_ceiling;
      } else if (ft.zero == cube.iq.size()) {
        ++counters_.frames_all_zero;
      }
      return Status::kInvalidInput;
    }
    const bool saturated = ft.full_scale > saturated_limit_;
    if (saturated) ++counters_.frames_saturated;
    stamp(times, FrontEndStage::kRange, 0u, range_ticks);
    stamp(times, FrontEndStage::kDoppler, 0u, doppler_ticks);
    std::uint32_t t0 = tick(times);
    MPTRACK_PROFILE_STAGE(g_frontend, FrontEndStage::kAngle);
    MPTRACK_TRY(ang_.process(dop_));
    std::uint32_t t1 = tick(times);
    stamp(times, FrontEndStage::kAngle, t0, t1);
    MPTRACK_PROFILE_STAGE(g_frontend, FrontEndStage::kCfar);
    detect(N);
    MPTRACK_PROFILE_STAGE(g_frontend, FrontEndStage::kPeaks);
    const std::size_t nonfinite = emit(out);
    t0 = tick(times);
    stamp(times, FrontEndStage::kDetect, t1, t0);
    ++counters_.frames;
    if (last_dropped_ > 0) return Status::kCapacityExceeded;
    return (saturated || nonfinite > 0) ? Status::kPartial : Status::kOk;
  }

  /// Per-virtual-channel complex calibration (see RangeMatchedFilter).
  Status set_channel_calibration(
      const std::array<float, Caps::kNumTx * Caps::kNumRx>& re,
      const std::array<float, Caps::kNumTx * Caps::kNumRx>& im) {
    return rmf_.set_channel_calibration(re, im);
  }

  const FrontEndCounters& counters() const { return counters_; }
  /// Candidates dropped by the cap in the last frame.
  std::size_t last_frame_dropped() const { return last_dropped_; }
  const RangeMatchedFilter<Caps>& range_stage() const { return rmf_; }
  const DopplerProcessor<Caps>& doppler_stage() const { return dop_; }
  const AngleProcessor<Caps>& angle_stage() const { return ang_; }
  const Cfar& cfar() const { return cfar_; }
  /// Range per bin c/(2 f_s) [m].
  double range_bin_m() const { return range_bin_m_; }
  bool initialized() const { return initialized_; }

 private:
  /// Range gate: bins [lo, hi) whose centre lies in [min_range_m, max_range_m].
  static void range_gate(const FrontEndParams& p, std::size_t& lo, std::size_t& hi) {
    const double bin_m = frontend::range_bin_m(p);
    lo = 0;
    while (lo < kNumRangeBins && static_cast<double>(lo) * bin_m < p.min_range_m) ++lo;
    hi = lo;
    while (hi < kNumRangeBins && static_cast<double>(hi) * bin_m <= p.max_range_m) ++hi;
  }
  static std::uint32_t tick(const FrontEndStageTimes* t) {
    return (t != nullptr && t->clock != nullptr) ? t->clock() : 0u;
  }
  static void stamp(FrontEndStageTimes* t, FrontEndStage s, std::uint32_t a, std::uint32_t b) {
    if (t != nullptr) t->ticks[static_cast<std::size_t>(s)] = b - a;  // wraps correctly
  }

  bool is_local_max(std::size_t g, std::size_t d, std::size_t a, float p) const {
    const std::size_t self = AngleProcessor<Caps>::map_index(g, d, a);
    // Range neighbours first (same line, contiguous): two of the 26 tests
    // below, repeated here because in noise they reject two cells in three
    // before the strided Doppler/angle reads. A conjunction, so the answer
    // is unchanged.
    const float* map = ang_.power_map();
    if (g > 0 && map[self - 1] >= p) return false;  // lower index: ties lose
    if (g + 1 < kNumRangeBins && map[self + 1] > p) return false;
    for (int dd = -1; dd <= 1; ++dd) {
      std::size_t d2 = d;
      if constexpr (kNc > 1) {
        d2 = (d + kNc + static_cast<std::size_t>(dd + 1) - 1) % kNc;
      } else if (dd != 0) {
        continue;
      }
      for (int da = -1; da <= 1; ++da) {
        if ((da < 0 && a == 0) || (da > 0 && a + 1 == kNa)) continue;
        const std::size_t a2 = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(a) + da);
        for (int dg = -1; dg <= 1; ++dg) {
          if ((dg < 0 && g == 0) || (dg > 0 && g + 1 == kNumRangeBins)) continue;
          const std::size_t g2 = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(g) + dg);
          const std::size_t idx = AngleProcessor<Caps>::map_index(g2, d2, a2);
          if (idx == self) continue;
          const float q = ang_.power_map()[idx];
          if (q > p || (q == p && idx < self)) return false;
        }
      }
    }
    return true;
  }

  void detect(std::size_t scan_capacity) {
    std::size_t cap = max_detections_ < scan_capacity ? max_detections_ : scan_capacity;
    peaks_.reset(cap);
    for (std::size_t d = 0; d < kNc; ++d) {
      for (std::size_t a = 0; a < kNa; ++a) {
        if (!ang_.angle_tested(a)) continue;
        const float* line = ang_.power_map() + AngleProcessor<Caps>::map_index(0, d, a);
        // Threshold first: the screen keeps a superset of the cells CFAR
        // detects (cfar_screen.h), so the local-maximum and exact CFAR tests
        // below run on few cells and decide exactly as over every cell.
        const std::size_t kept = screen_.run(cfar_, line, gate_lo_, gate_hi_);
        for (std::size_t j = 0; j < kept; ++j) {
          const std::size_t g = screen_.cells()[j];
          const float p = line[g];
          if (!(p > 0.0f) || !is_local_max(g, d, a, p)) continue;
          const CfarResult r = cfar_.test(line, kNumRangeBins, g);
          if (!r.tested) continue;
          ++counters_.cells_tested;
          const float noise = r.noise > min_noise_ ? r.noise : min_noise_;
          if (!r.detected || !(noise > 0.0f)) continue;
          PeakCandidate c;
          c.cell = static_cast<std::uint32_t>(AngleProcessor<Caps>::map_index(g, d, a));
          c.range_bin = static_cast<std::uint16_t>(g);
          c.doppler_bin = static_cast<std::uint16_t>(d);
          c.angle_bin = static_cast<std::uint16_t>(a);
          c.power = p;
          c.noise = noise;
          peaks_.insert(c);
        }
      }
    }
    last_dropped_ = peaks_.dropped();
    counters_.detections_over_cap += last_dropped_;
    counters_.detections_sidelobe += sidelobe_.apply(peaks_, keep_);
  }

  /// Sub-bin offset of a peak from the powers of the bin and its two
  /// neighbours: the vertex of the parabola through the log powers
  /// ("Gaussian" interpolation; exact for a Gaussian main lobe and nearly so
  /// for tapered windows, far less biased than a parabola on magnitudes).
  /// Clamped to [-0.5, 0.5]; 0 if the bin is not a strict maximum.
  static float log_parabolic_offset(float pm, float p0, float pp) {
    if (!(pm > 0.0f && pp > 0.0f && p0 > pm && p0 > pp)) return 0.0f;
    const float lm = mptrack::dmath::dlog(pm);
    const float l0 = mptrack::dmath::dlog(p0);
    const float lp = mptrack::dmath::dlog(pp);
    const float den = lm - 2.0f * l0 + lp;
    if (!(den < 0.0f)) return 0.0f;
    float off = 0.5f * (lm - lp) / den;
    if (off > 0.5f) off = 0.5f;
    if (off < -0.5f) off = -0.5f;
    return off;
  }

  /// Returns the number of detections dropped for a non-finite amplitude
  /// (F3: a noise estimate at the min_noise_power floor under a huge peak).
  template <std::size_t N>
  std::size_t emit(Scan<float, N>& out) {
    refine_kept();
    std::size_t nonfinite = 0;
    for (std::size_t i = 0; i < peaks_.size(); ++i) {
      if (!keep_[i]) continue;  // a stronger candidate's sidelobe
      const PeakCandidate& c = peaks_[i];
      const std::size_t g = c.range_bin;
      const std::size_t d = c.doppler_bin;
      const std::size_t a = c.angle_bin;
      const AngleEstimate ae = refined_[i];
      float dg = 0.0f;
      if (g > 0 && g + 1 < kNumRangeBins) {
        dg = log_parabolic_offset(ang_.power(g - 1, d, a), c.power, ang_.power(g + 1, d, a));
      }
      float dd = 0.0f;
      if constexpr (kNc > 1) {
        dd = log_parabolic_offset(ang_.power(g, (d + kNc - 1) % kNc, a), c.power,
                              ang_.power(g, (d + 1) % kNc, a));
      }
      float u = ae.u;
      if (u > 1.0f) u = 1.0f;
      if (u < -1.0f) u = -1.0f;
      const float bearing = mptrack::dmath::datan2(u, std::sqrt((1.0f - u) * (1.0f + u)));
      Measurement<float> m;
      m.range_m = static_cast<float>((static_cast<double>(g) + static_cast<double>(dg)) * range_bin_m_);
      m.azimuth_rad = bearing_to_azimuth(bearing);
      m.amplitude = std::sqrt(ae.power / c.noise);
      if (!is_finite(m.amplitude)) {
        ++nonfinite;
        ++counters_.detections_nonfinite;
        continue;
      }
      m.doppler_mps =
          static_cast<float>(dop_.velocity_mps(static_cast<double>(d) + static_cast<double>(dd)));
      // Capacity was reserved in detect() (cap <= N), so this cannot fail.
      if (out.measurements.push_back(m) != Status::kOk) ++counters_.detections_over_cap;
      ++counters_.detections;
    }
    return nonfinite;
  }

  /// Angle refinement of every kept peak into refined_, kRefineLanes peaks
  /// at a time (AngleProcessor::refine_lanes: the bits of refine()).
  void refine_kept() {
    constexpr std::size_t L = AngleProcessor<Caps>::kRefineLanes;
    std::array<std::uint16_t, L> g{};
    std::array<std::uint16_t, L> d{};
    std::array<std::uint16_t, L> a{};
    std::array<std::size_t, L> at{};
    std::array<AngleEstimate, L> est{};
    std::size_t n = 0;
    for (std::size_t i = 0; i <= peaks_.size(); ++i) {
      if (i < peaks_.size()) {
        if (!keep_[i]) continue;
        g[n] = peaks_[i].range_bin;
        d[n] = peaks_[i].doppler_bin;
        a[n] = peaks_[i].angle_bin;
        at[n++] = i;
        if (n < L) continue;
      }
      if (n == 0) continue;
      ang_.refine_lanes(dop_, g.data(), d.data(), a.data(), n, est.data());
      for (std::size_t l = 0; l < n; ++l) refined_[at[l]] = est[l];
      n = 0;
    }
  }

  RangeMatchedFilter<Caps> rmf_{};
  DopplerProcessor<Caps> dop_{};
  AngleProcessor<Caps> ang_{};
  Cfar cfar_{};
  CfarScreen<kNumRangeBins> screen_{};
  PeakList<Caps::kMaxDetections> peaks_{};
  SidelobeFilter<Caps> sidelobe_{};
  std::array<bool, Caps::kMaxDetections> keep_{};  ///< peaks_[i] survives sidelobe grouping
  std::array<AngleEstimate, Caps::kMaxDetections> refined_{};  ///< refine() of kept peaks_[i]
  FrontEndCounters counters_{};
  double range_bin_m_ = 0.0;
  std::size_t gate_lo_ = 0;
  std::size_t gate_hi_ = 0;
  std::size_t max_detections_ = 0;
  std::size_t last_dropped_ = 0;
  float min_noise_ = 0.0f;
  std::size_t saturated_limit_ = 0;
  bool initialized_ = false;
};

}  // namespace mptrack::frontend
