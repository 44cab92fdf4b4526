// Two-point track birth (seed 000 Section III.G; docs/algorithms/mfbp.md
// §Birth): measurements that no track explains are paired across scans
// (k1, k2 = k1 + lag, lag <= birth_max_lag) inside the v_max box; at most
// one pair per second point (the shortest lag, then the nearest first
// point), no measurement in two pairs; the best birth_max_per_window pairs
// by amplitude sum start tracks (two_point_state, birth_snr_belief).
//
// "Unexplained" on a scan with association beliefs: sum_i a_ij below
// unexplained_threshold and Gaussian-clutter share below
// birth_max_component_share, or (birth inside clutter) an amplitude that
// every Gaussian component gating it makes unlikely (birth_amplitude_tail;
// at most birth_max_in_clutter such births per window); on a new scan (no
// beliefs yet): outside the chi^2 gate of every track. The TrackSpawner owns
// that per-measurement mark; clutter seeding (clutter_spawn.h) reads it on
// new scans.
//
// Full track table: a birth evicts the live tentative track least likely
// to be confirmed (smallest max_k b_s(1) over the window) if that is below
// the newborn's visibility_at_birth (tentative_evicted); a confirmed track
// or a track born in the same pass is never evicted. Otherwise the birth is
// refused (track_cap_hits).
//
// NEMP (docs/algorithms/nemp.md §Birth): a detection the classifier vetoes
// (ScanSlot::birth_vetoed, set by NempState::store_scan from
// NempParams::birth_min_target_prob) is no birth point, first or second,
// while its scan is in the window and after it has moved into history.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "mptrack/mfbp/clutter_slot.h"
#include "mptrack/mfbp/cubature.h"
#include "mptrack/mfbp/mfbp_caps.h"
#include "mptrack/mfbp/mfbp_params.h"
#include "mptrack/mfbp/model_constants.h"
#include "mptrack/mfbp/track_birth.h"
#include "mptrack/mfbp/track_slot.h"
#include "mptrack/mfbp/weaker_clutter.h"
#include "mptrack/mfbp/window_store.h"
#include "mptrack/model/mahalanobis.h"
#include "mptrack/profile.h"
#include "mptrack/track_report.h"

namespace mptrack::mfbp {

template <class T, class Caps>
class TrackSpawner {
 public:
  static constexpr std::size_t kMaxMeas = Caps::kMaxMeasurements;
  static constexpr std::size_t kStore = Caps::kMaxWindow;
  static constexpr std::size_t kMaxCandidates = kMaxBirthCandidates<Caps>;
  using Store = WindowStore<T, Caps>;
  using Tracks = TrackTable<T, Caps>;

  /// Marks the unexplained measurements of every stored scan and starts
  /// tracks from the best pairs among the n window scans (second points).
  void spawn(std::size_t n, Store& store, Tracks& tracks, const ClutterTable<T, Caps>& cl,
             const MfbpParams<T>& p, const ModelConstants<T>& mc, std::uint32_t& next_id,
             TrackerCounters& counters) {
    MPTRACK_PROFILE_STAGE(g_mfbp, MfbpStage::kBirth);
    mark_unexplained(store, tracks, cl, p, mc);
    Candidates cand{};
    std::size_t nc = 0;
    const std::size_t max_births = p.birth_max_per_window < kMaxCandidates ? p.birth_max_per_window : kMaxCandidates;
    for (std::size_t k2 = 0; k2 < n; ++k2) {
      const std::size_t s2 = store.n_hist() + k2;
      for (std::size_t j2 = 0; j2 < store.at(s2).count; ++j2) {
        if (birth_point(store, s2, j2)) pair_second_point(store, s2, j2, p, cand, nc, max_births);
      }
    }
    const std::uint32_t first_new = next_id;
    std::size_t in_clutter = 0;
    for (std::size_t b = 0; b < nc; ++b) {
      if (cand[b].in_clutter && in_clutter++ >= p.birth_max_in_clutter) {
        mark_used_by_birth(store, cand[b], false);  // bounded births inside clutter (not a cap)
        continue;
      }
      start_track(cand[b], store, tracks, p, first_new, next_id, counters);
    }
    if (p.birth_single_point_tail > T(0) && in_clutter < p.birth_max_in_clutter) {
      nc = single_points(n, store, tracks, p, mc, p.birth_max_in_clutter - in_clutter, cand);
      for (std::size_t b = 0; b < nc; ++b) start_track(cand[b], store, tracks, p, first_new, next_id, counters);
    }
  }

  /// Unexplained by the tracks at the last spawn() and not used by a birth.
  /// Defined on the window scans, the scans without beliefs and the
  /// birth_max_lag history scans before the window (mark_unexplained).
  bool unexplained(const Store& store, std::size_t si, std::size_t j) const {
    return unexplained_[si][j] != 0 && !store.at(si).used_by_birth(j);
  }

 private:
  struct Candidate {
    T score = T(0);
    std::uint16_t s1 = 0, j1 = 0, s2 = 0, j2 = 0;
    bool in_clutter = false;  ///< a point passed only by the amplitude test (inside_clutter)
    bool single = false;      ///< one-point birth (s1 == s2, j1 == j2)
  };
  /// Marks of unexplained_: not a candidate, a candidate, a candidate
  /// inside Gaussian clutter by its amplitude alone, and such a candidate
  /// whose amplitude also passes birth_single_point_tail (a one-point birth).
  static constexpr std::uint8_t kExplained = 0, kFree = 1, kInClutter = 2, kStandsAlone = 3;
  static bool inside_clutter(std::uint8_t mark) { return mark >= kInClutter; }
  using Candidates = std::array<Candidate, kMaxCandidates>;

  /// Unexplained and, with NEMP, not vetoed by the classifier (on window
  /// and history scans alike).
  bool birth_point(const Store& store, std::size_t si, std::size_t j) const {
    return unexplained(store, si, j) && !store.at(si).birth_vetoed(j);
  }

  void mark_unexplained(const Store& store, const Tracks& tracks, const ClutterTable<T, Caps>& cl,
                        const MfbpParams<T>& p, const ModelConstants<T>& mc) {
    const std::size_t k_ref = store.n_win() > 0 ? store.n_win() - 1 : 0;
    // Older history scans are read by nobody: first points lie at most
    // birth_max_lag scans before a window scan, and clutter seeding reads
    // the mark only on scans without beliefs.
    const std::size_t first_read = store.n_hist() > p.birth_max_lag ? store.n_hist() - p.birth_max_lag : 0;
    for (std::size_t si = 0; si < store.size(); ++si) {
      const ScanSlot<T, Caps>& s = store.at(si);
      if (si < first_read && s.has_beliefs) continue;
      for (std::size_t j = 0; j < s.count; ++j) {
        bool u = !s.used_by_birth(j);
        std::uint8_t clutter = kExplained;
        if (u && s.has_beliefs) {
          const T comp_share = T(1) - s.target_share[j] - s.uniform_share[j];
          const bool free_of_tracks = s.target_share[j] < p.unexplained_threshold;
          u = free_of_tracks &&
              (p.birth_max_component_share >= T(1) || comp_share < p.birth_max_component_share);
          if (free_of_tracks && !u) clutter = clutter_mark(s.r[j], s.az[j], s.amp[j], k_ref, s.time_us, cl, p, mc.n_order);
        }
        unexplained_[si][j] = clutter != kExplained ? clutter : (u ? kFree : kExplained);
      }
      if (!s.has_beliefs && si >= store.n_hist()) mark_gated(s, si, si - store.n_hist(), tracks, p, mc);
    }
  }

  /// Birth inside clutter (docs/algorithms/mfbp.md §Birth): kInClutter if
  /// the amplitude m is less likely than birth_amplitude_tail under every
  /// Gaussian clutter component whose gate (clutter_gate_chi2) holds (r, az),
  /// at its mean CNR on window scan k_ref (estimated map) or its known CNR
  /// (known map); kStandsAlone if also less likely than
  /// birth_single_point_tail; kExplained if no component gates it or the
  /// test is off.
  static std::uint8_t clutter_mark(T r, T az, T m, std::size_t k_ref, std::uint64_t time_us,
                                   const ClutterTable<T, Caps>& cl, const MfbpParams<T>& p, int n_order) {
    if (!(p.birth_amplitude_tail > T(0)) || !p.amplitude.use_amplitude) return kExplained;
    const T tail = amplitude_tail_in_clutter(r, az, m, k_ref, time_us, cl, p, n_order);
    if (!(tail < p.birth_amplitude_tail)) return kExplained;
    return tail < p.birth_single_point_tail ? kStandsAlone : kInClutter;
  }

  /// The largest amplitude_tail of m under the Gaussian components whose
  /// gate holds (r, az) (see clutter_mark); 1 if none gates it, and 1 under a
  /// component of mean CNR above birth_in_clutter_max_cnr (when set).
  static T amplitude_tail_in_clutter(T r, T az, T m, std::size_t k_ref, std::uint64_t time_us,
                                     const ClutterTable<T, Caps>& cl, const MfbpParams<T>& p, int n_order) {
    const T d = p.amplitude.threshold;
    bool gated = false;
    T tail_max = T(0);
    const auto consider = [&](const Vec2<T>& mu, const Mat2<T>& cov, T varsigma) {
      if (!(varsigma > T(0)) || !in_gaussian_gate(r, az, mu, cov, p.clutter_gate_chi2)) return;
      gated = true;
      const bool too_strong = p.birth_in_clutter_max_cnr > T(0) && varsigma - T(1) > p.birth_in_clutter_max_cnr;
      const T tail = too_strong ? T(1) : amplitude_tail(m, d, varsigma, n_order);
      tail_max = tail > tail_max ? tail : tail_max;
    };
    for_each_gaussian_component(k_ref, time_us, cl, p, consider);
    return gated ? tail_max : T(1);
  }

  /// One-point births inside clutter (docs/algorithms/mfbp.md §Birth): up to
  /// `room` unpaired window points marked kStandsAlone (clutter_mark) and
  /// outside every live track's gate, the strongest first (ties: earlier
  /// scan, lower index), ranked by offer() (so marked used by a birth).
  std::size_t single_points(std::size_t n, Store& store, const Tracks& tracks, const MfbpParams<T>& p,
                            const ModelConstants<T>& mc, std::size_t room, Candidates& cand) const {
    if (room > kMaxCandidates) room = kMaxCandidates;
    std::size_t nc = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t si = store.n_hist() + k;
      const ScanSlot<T, Caps>& s = store.at(si);
      for (std::size_t j = 0; j < s.count; ++j) {
        if (unexplained_[si][j] != kStandsAlone || !birth_point(store, si, j)) continue;
        // Cheaper than the gate: a point no stronger than the weakest kept
        // one cannot enter the list.
        if (nc == room && !(s.amp[j] > cand[nc - 1].score)) continue;
        if (in_a_track_gate(s.r[j], s.az[j], k, tracks, p, mc)) continue;
        Candidate c;
        c.score = s.amp[j];
        c.s1 = c.s2 = static_cast<std::uint16_t>(si);
        c.j1 = c.j2 = static_cast<std::uint16_t>(j);
        c.in_clutter = c.single = true;
        offer(c, store, cand, nc, room);
      }
    }
    return nc;
  }

  /// Predicted measurement of track t on window scan k and the covariance
  /// S_z + R of its chi^2 gate; false if t is absent at k or the cubature
  /// fails. One cubature.
  static bool track_gate(const TrackSlot<T, Caps>& t, std::size_t k, const ModelConstants<T>& mc, Vec2<T>& z_hat,
                         Mat2<T>& S) {
    if (!t.alive || k < t.first) return false;
    Mat2<T> Sz;
    if (!cubature_measurement_moments<T, 2>(t.xs[k], t.Ps[k].get(), z_hat, Sz)) return false;
    S = Sz + mc.R;
    return true;
  }

  /// Inside the chi^2 gate (gate_chi2) of a live track present on window scan k.
  static bool in_a_track_gate(T r, T az, std::size_t k, const Tracks& tracks, const MfbpParams<T>& p,
                              const ModelConstants<T>& mc) {
    for (const auto& t : tracks) {
      Vec2<T> z_hat;
      Mat2<T> S;
      if (!track_gate(t, k, mc, z_hat, S)) continue;
      const model::Mahalanobis2<T> gate(S);
      if (gate.valid() && gate.distance2(r - z_hat(0), model::wrap_angle(az - z_hat(1))) <= p.gate_chi2) return true;
    }
    return false;
  }

  /// New scan: a measurement inside the chi^2 gate of a track present on
  /// window scan k is explained. One cubature per track.
  void mark_gated(const ScanSlot<T, Caps>& s, std::size_t si, std::size_t k, const Tracks& tracks,
                  const MfbpParams<T>& p, const ModelConstants<T>& mc) {
    for (const auto& t : tracks) {
      Vec2<T> z_hat;
      Mat2<T> S;
      if (!track_gate(t, k, mc, z_hat, S)) continue;
      const model::Mahalanobis2<T> gate(S);
      if (!gate.valid()) continue;
      for (std::size_t j = 0; j < s.count; ++j) {
        if (unexplained_[si][j] == 0) continue;
        const T er = s.r[j] - z_hat(0);
        const T ea = model::wrap_angle(s.az[j] - z_hat(1));
        if (gate.distance2(er, ea) <= p.gate_chi2) unexplained_[si][j] = 0;
      }
    }
  }

  /// The nearest unexplained first point on stored scan s1 for the second
  /// point (s2, j2) inside the v_max box; kMaxMeas if none.
  std::size_t nearest_first_point(const Store& store, std::size_t s1, std::size_t s2, std::size_t j2,
                                  const MfbpParams<T>& p) const {
    const ScanSlot<T, Caps>& a1 = store.at(s1);
    const T r2 = store.at(s2).r[j2];
    const T dt = dt_s<T>(a1.time_us, store.at(s2).time_us);
    const Vec2<T> p2 = model::cartesian_of_polar(r2, store.at(s2).az[j2]);
    const T reach = birth_reach(dt, p.v_max_x_mps, p.v_max_y_mps);
    // Only first points within the range reach can pass the box gate
    // (birth_range_gate): start at the first one in range order, stop
    // after the last, so the search is O(log N + hits), not O(N).
    std::size_t lo = 0, hi = a1.count;
    while (lo < hi) {
      const std::size_t mid = (lo + hi) / 2;
      if (a1.r[a1.by_range[mid]] < r2 &&
          !within_birth_reach(a1.r[a1.by_range[mid]], r2, reach)) {
        lo = mid + 1;
      } else {
        hi = mid;
      }
    }
    T best_d = T(0);
    std::size_t best_j = kMaxMeas;
    for (std::size_t q = lo; q < a1.count; ++q) {
      const std::size_t j1 = a1.by_range[q];
      if (!within_birth_reach(a1.r[j1], r2, reach)) {
        if (a1.r[j1] > r2) break;  // beyond the reach: so is every later one
        continue;
      }
      if (!birth_point(store, s1, j1)) continue;
      const Vec2<T> p1 = model::cartesian_of_polar(a1.r[j1], a1.az[j1]);
      if (!birth_gate(p1, p2, dt, p.v_max_x_mps, p.v_max_y_mps)) continue;
      const T dist = (p2 - p1).squaredNorm();
      // Nearest first point; ties go to the lowest index (as in index order).
      if (best_j == kMaxMeas || dist < best_d || (!(best_d < dist) && j1 < best_j)) {
        best_d = dist;
        best_j = j1;
      }
    }
    return best_j;
  }

  /// The pair of second point (s2, j2) at the shortest lag, ranked among
  /// the candidates (its measurements are marked used by a birth while it stays).
  void pair_second_point(Store& store, std::size_t s2, std::size_t j2, const MfbpParams<T>& p,
                         Candidates& cand, std::size_t& nc, std::size_t max_births) const {
    for (std::size_t lag = 1; lag <= p.birth_max_lag && lag <= s2; ++lag) {
      const std::size_t s1 = s2 - lag;
      const std::size_t j1 = nearest_first_point(store, s1, s2, j2, p);
      if (j1 == kMaxMeas) continue;
      Candidate c;
      c.score = store.at(s1).amp[j1] + store.at(s2).amp[j2];
      c.s1 = static_cast<std::uint16_t>(s1);
      c.j1 = static_cast<std::uint16_t>(j1);
      c.s2 = static_cast<std::uint16_t>(s2);
      c.j2 = static_cast<std::uint16_t>(j2);
      c.in_clutter = inside_clutter(unexplained_[s1][j1]) || inside_clutter(unexplained_[s2][j2]);
      offer(c, store, cand, nc, max_births);
      return;
    }
  }

  /// Keeps the best max_births candidates by score (ties: earlier wins).
  static void offer(const Candidate& c, Store& store, Candidates& cand, std::size_t& nc,
                    std::size_t max_births) {
    if (nc == max_births) {
      if (!(c.score > cand[nc - 1].score)) return;
      mark_used_by_birth(store, cand[nc - 1], false);
      --nc;
    }
    mark_used_by_birth(store, c, true);  // so no measurement joins two pairs
    std::size_t pos = nc;
    while (pos > 0 && c.score > cand[pos - 1].score) {
      cand[pos] = cand[pos - 1];
      --pos;
    }
    cand[pos] = c;
    ++nc;
  }

  static void mark_used_by_birth(Store& store, const Candidate& c, bool on) {
    store.at(c.s1).set_used_by_birth(c.j1, on);
    store.at(c.s2).set_used_by_birth(c.j2, on);
  }

  /// The live tentative track least likely to be confirmed (smallest
  /// max_k b_s(1) over its window scans), if below visibility_at_birth and
  /// born before this pass (id < first_new): deleted, its slot returned
  /// (tentative_evicted). Tracks::kSize if none qualifies.
  static std::size_t evict_tentative(Tracks& tracks, std::size_t n, const MfbpParams<T>& p,
                                     std::uint32_t first_new, TrackerCounters& counters) {
    std::size_t worst = Tracks::kSize;
    T worst_vis = p.visibility_at_birth;
    for (std::size_t i = 0; i < Tracks::kSize; ++i) {
      const TrackSlot<T, Caps>& t = tracks[i];
      if (!t.alive || t.confirmed || t.id >= first_new) continue;
      T best = T(0);
      for (std::size_t k = t.first; k < n; ++k) best = t.vis[k] > best ? t.vis[k] : best;
      if (best < worst_vis) {
        worst_vis = best;
        worst = i;
      }
    }
    if (worst == Tracks::kSize) return worst;
    tracks[worst].alive = false;
    ++counters.tracks_deleted;
    ++counters.tentative_evicted;
    return worst;
  }

  static void start_track(const Candidate& c, Store& store, Tracks& tracks, const MfbpParams<T>& p,
                          std::uint32_t first_new, std::uint32_t& next_id, TrackerCounters& counters) {
    std::size_t slot = tracks.free_slot();
    if (slot == Tracks::kSize) slot = evict_tentative(tracks, store.n_win(), p, first_new, counters);
    if (slot == Tracks::kSize) {
      ++counters.track_cap_hits;
      mark_used_by_birth(store, c, false);
      return;
    }
    const ScanSlot<T, Caps>& a = store.at(c.s1);
    const ScanSlot<T, Caps>& b = store.at(c.s2);
    TrackSlot<T, Caps>& t = tracks[slot];
    t.start(next_id++, c.s2 - store.n_hist(), p.visibility_at_birth);
    if (c.single) {
      one_point_state(b.r[c.j2], b.az[c.j2], p.noise.range_std_m, p.noise.azimuth_std_rad, p.v_max_x_mps,
                      p.v_max_y_mps, t.x0, t.P0);
    } else {
      two_point_state(a.r[c.j1], a.az[c.j1], b.r[c.j2], b.az[c.j2], dt_s<T>(a.time_us, b.time_us),
                      p.noise.range_std_m, p.noise.azimuth_std_rad, p.v_max_x_mps, p.v_max_y_mps, t.x0, t.P0);
    }
    t.ig0 = birth_snr_belief(a.amp[c.j1], b.amp[c.j2], p.amplitude.threshold, p.ig_birth_shape,
                             p.ig_birth_scale_factor);
    t.t0_us = b.time_us;
    ++counters.tracks_born;
  }

  std::array<std::array<std::uint8_t, kMaxMeas>, kStore> unexplained_{};
};

}  // namespace mptrack::mfbp
