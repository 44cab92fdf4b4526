// The scans MF-BP holds: the sliding window of seed 000 Algorithm 1 (K
// scans processed together) and, in front of it, as many finalised
// ("history") scans as fit.
//
// The online filter (window 1) keeps 6 history scans for two-point birth
// (lag <= 3) and clutter seeding; a window-K smoother needs none: a birth
// pair that reaches before the window has its second point on an overlap
// scan and was considered already (docs/algorithms/mfbp.md §Window schedule).
// Each scan carries its measurements, the association beliefs summed per
// measurement, the clutter statistics per source (eqs. (54)-(55), (69))
// that the clutter chain reads, and the pool of gated (track, measurement)
// beliefs of eqs. (99)-(102) every track's edges on it point into (a track
// keeps its offset and count; docs/algorithms/mfbp.md §Evidence and association).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

#include "mptrack/measurement.h"
#include "mptrack/mfbp/amplitude_model.h"
#include "mptrack/mfbp/amplitude_stats.h"
#include "mptrack/mfbp/mfbp_caps.h"
#include "mptrack/mfbp/mfbp_params.h"
#include "mptrack/mfbp/normal_wishart.h"
#include "mptrack/model/measurement_validator.h"
#include "mptrack/track_report.h"
#include "mptrack/validate.h"

namespace mptrack::mfbp {

/// One stored scan (window or history).
template <class T, class Caps>
struct ScanSlot {
  static constexpr std::size_t kMaxMeas = Caps::kMaxMeasurements;
  static constexpr std::size_t kSources = Caps::kMaxClutterComponents + 1;
  static constexpr std::size_t kPool = kMaxGatePool<Caps>;

  std::uint64_t time_us = 0;
  std::size_t count = 0;
  bool has_beliefs = false;          ///< BP has run on it (overlap scan)
  bool doppler = false;              ///< dop[] is valid and used
  T lambda_hat = T(0);               ///< expected clutter count used by the BP
  std::array<T, kMaxMeas> r{}, az{}, amp{}, dop{};
  std::array<std::uint16_t, kMaxMeas> orig_index{};
  std::array<T, kMaxMeas> target_share{};   ///< sum_i a_hat^t_ij
  std::array<T, kMaxMeas> uniform_share{};  ///< a_hat^c_0j
  /// Per measurement, bits kUsedByBirth | kBirthVetoed | kTentativeVetoed
  /// (one byte for all: the vetoes must not grow plain MF-BP's footprint).
  std::array<std::uint8_t, kMaxMeas> birth_flags{};
  std::array<std::uint16_t, kMaxMeas> by_range{};  ///< indices sorted by (range, index)
  std::array<NwStats<T>, kSources> nw_stats{};       ///< per source slot (0 = uniform)
  std::array<AmplitudeStats<T>, kSources> amp_stats{};
  /// Edges of every track on this scan: measurement and belief a_hat^t_ij
  /// (TrackSlot::edge_begin / n_edges index them).
  std::array<std::uint16_t, kPool> edge_meas{};
  std::array<T, kPool> edge_w{};

  /// In a two-point birth pair (TrackSpawner), so in no other pair.
  static constexpr std::uint8_t kUsedByBirth = 1;
  /// NEMP: the classifier calls it clutter, so it starts no track. Kept in
  /// the slot so the veto follows the scan into history, where births take
  /// their first points (docs/algorithms/nemp.md §Birth).
  static constexpr std::uint8_t kBirthVetoed = 2;
  /// NEMP (NempParams::tentative_min_target_prob): kept out of the
  /// association of every unconfirmed track (target_evidence;
  /// docs/algorithms/nemp.md §Birth, "Tentative tracks").
  static constexpr std::uint8_t kTentativeVetoed = 4;

  bool used_by_birth(std::size_t j) const { return (birth_flags[j] & kUsedByBirth) != 0; }
  bool birth_vetoed(std::size_t j) const { return (birth_flags[j] & kBirthVetoed) != 0; }
  bool tentative_vetoed(std::size_t j) const { return (birth_flags[j] & kTentativeVetoed) != 0; }
  void set_used_by_birth(std::size_t j, bool on) { set_flag(j, kUsedByBirth, on); }
  void set_birth_vetoed(std::size_t j, bool on) { set_flag(j, kBirthVetoed, on); }
  void set_tentative_vetoed(std::size_t j, bool on) { set_flag(j, kTentativeVetoed, on); }

  void clear_source_stats() {
    for (std::size_t src = 0; src < kSources; ++src) {
      nw_stats[src] = NwStats<T>{};
      amp_stats[src] = AmplitudeStats<T>{};
    }
  }

 private:
  void set_flag(std::size_t j, std::uint8_t bit, bool on) {
    birth_flags[j] = static_cast<std::uint8_t>(on ? (birth_flags[j] | bit) : (birth_flags[j] & ~bit));
  }
};

template <class T, class Caps>
class WindowStore {
 public:
  static constexpr std::size_t kStore = Caps::kMaxWindow;
  static constexpr std::size_t kMaxMeas = Caps::kMaxMeasurements;
  using Slot = ScanSlot<T, Caps>;

  /// Window scan k (0 = oldest scan of the window).
  Slot& win(std::size_t k) { return store_[n_hist_ + k]; }
  const Slot& win(std::size_t k) const { return store_[n_hist_ + k]; }
  /// Stored scan si (history first, then the window).
  Slot& at(std::size_t si) { return store_[si]; }
  const Slot& at(std::size_t si) const { return store_[si]; }
  std::size_t n_hist() const { return n_hist_; }
  std::size_t n_win() const { return n_win_; }
  std::size_t size() const { return n_hist_ + n_win_; }

  void clear() {
    n_hist_ = 0;
    n_win_ = 0;
  }

  /// Copies the valid measurements of `scan` to the slot after the window
  /// (the caller commits it with push_window()). kept[j]: measurement j
  /// kept (scratch for the duplicate rule). Returns true if some were rejected.
  template <std::size_t N>
  bool store_scan(const Scan<T, N>& scan, const MfbpParams<T>& p, TrackerCounters& counters,
                  std::array<bool, N>& kept) {
    Slot& s = store_[n_hist_ + n_win_];
    s.time_us = scan.time_us;
    s.count = 0;
    s.has_beliefs = false;
    s.lambda_hat = T(0);
    s.doppler = scan.has_doppler && p.use_doppler;
    const model::MeasurementValidator<T> check = intake_check(p, s.doppler);
    bool rejected = false;
    for (std::size_t j = 0; j < scan.measurements.size(); ++j) {
      const Measurement<T>& m = scan.measurements[j];
      ++counters.measurements_in;
      kept[j] = false;
      if (!check.valid(m)) {
        ++counters.measurements_invalid;
        rejected = true;
        continue;
      }
      if (is_duplicate(scan, j, [&kept](std::size_t i) { return kept[i]; })) {
        ++counters.measurements_duplicate;  // the first copy is kept (measurement.h)
        rejected = true;
        continue;
      }
      kept[j] = true;
      const std::size_t c = s.count++;
      s.r[c] = m.range_m;
      s.az[c] = m.azimuth_rad;
      s.amp[c] = m.amplitude;
      s.dop[c] = s.doppler ? m.doppler_mps : T(0);
      s.orig_index[c] = static_cast<std::uint16_t>(j);
      s.target_share[c] = T(0);
      s.uniform_share[c] = T(1);
      s.birth_flags[c] = 0;
    }
    s.clear_source_stats();
    sort_by_range(s);
    return rejected;
  }

  /// The scan filled by store_scan() joins the window.
  void push_window() { ++n_win_; }

  /// The window slides by fc scans: they become history, the oldest history
  /// scans fall off so that history + window_length scans fit.
  void shift(std::size_t fc, std::size_t window_length) {
    const std::size_t n = n_win_;
    const std::size_t hist_cap = kStore - window_length;
    std::size_t new_hist = n_hist_ + fc;
    std::size_t drop = new_hist > hist_cap ? new_hist - hist_cap : 0;
    if (drop > 0) {
      for (std::size_t si = drop; si < n_hist_ + n; ++si) store_[si - drop] = store_[si];
      new_hist -= drop;
    }
    n_hist_ = new_hist;
    n_win_ = n - fc;
  }

 private:
  // The shared intake check (model/measurement_validator.h): finite, inside
  // the region, amplitude in (d, max_amplitude] (also for the kinematics-only
  // variant: the detector threshold holds either way), radial velocity
  // within +-doppler_span_mps when the scan's Doppler is used.
  static model::MeasurementValidator<T> intake_check(const MfbpParams<T>& p, bool doppler) {
    model::MeasurementValidator<T> v = p.region.validator();
    v.amplitude = model::AmplitudeRule::kThresholded;
    v.threshold = p.amplitude.threshold;
    v.max_amplitude = p.amplitude.max_amplitude;
    v.check_doppler = doppler;
    v.doppler_span_mps = p.doppler_span_mps;
    return v;
  }

  /// Range order for the birth search (track_spawn.h); ties by index, so the
  /// order is unique and the same on every target.
  static void sort_by_range(Slot& s) {
    for (std::size_t c = 0; c < s.count; ++c) s.by_range[c] = static_cast<std::uint16_t>(c);
    std::sort(s.by_range.begin(), s.by_range.begin() + static_cast<std::ptrdiff_t>(s.count),
              [&s](std::uint16_t a, std::uint16_t b) {
                return s.r[a] < s.r[b] || (!(s.r[b] < s.r[a]) && a < b);
              });
  }

  std::array<Slot, kStore> store_{};
  std::size_t n_hist_ = 0;  ///< history scans at the front of store_
  std::size_t n_win_ = 0;   ///< window scans after them
};

}  // namespace mptrack::mfbp
