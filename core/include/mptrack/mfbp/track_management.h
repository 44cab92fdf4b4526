// Confirmation and deletion of tracks and components after each window
// (seed 000 Section III.G; docs/algorithms/mfbp.md §Confirmation and
// reporting):
//   * a tentative track is confirmed once its visibility b_s (eq. (64))
//     reaches confirm_threshold on a window scan (confirmation_threshold: a
//     young track inside weaker clutter needs confirm_threshold_in_clutter
//     on a scan with confirm_lookahead_in_clutter later window scans, or in
//     the online filter the score of filter_score_confirms);
//   * a track is deleted when b_s < delete_threshold on delete_run
//     consecutive scans (finalised history + the window tail), or when it
//     stays tentative for tentative_timeout_scans finalised scans; a
//     confirmed track inside a Gaussian clutter component at least as strong
//     as itself gets delete_run_in_clutter scans instead (deletion_run);
//   * a Gaussian clutter component dies when its expected count
//     M_tau,k = M_k E[pi_tau] stays below clutter_death_count on every
//     finalised scan of clutter_death_windows consecutive windows.
#pragma once

#include <cstddef>
#include <cstdint>

#include "mptrack/math/detmath.h"
#include "mptrack/mfbp/clutter_slot.h"
#include "mptrack/mfbp/mfbp_params.h"
#include "mptrack/mfbp/model_constants.h"
#include "mptrack/mfbp/track_slot.h"
#include "mptrack/mfbp/weaker_clutter.h"
#include "mptrack/model/mahalanobis.h"
#include "mptrack/model/polar_measurement.h"
#include "mptrack/track_report.h"

namespace mptrack::mfbp {

/// Does a tentative track need confirm_threshold_in_clutter (docs/algorithms/
/// mfbp.md §Birth, young tracks inside weaker clutter)? Yes once it has
/// scored measurements with the predictive density (predictive_evidence) or,
/// in the online filter, been predicted inside any Gaussian component
/// (predicted_in_component), and the in-clutter threshold is the higher. The predictive
/// density lets a loose young track take a clutter point near its prediction
/// at fair odds, so one or two lucky scans would confirm it at 0.75; a target
/// keeps b_s near 1 scan after scan as the track tightens, clutter does not.
template <class T, class Caps>
bool held_to_clutter_threshold(const TrackSlot<T, Caps>& t, const MfbpParams<T>& p) {
  return p.tentative_predictive_in_clutter && (t.predictive_evidence || t.predicted_in_component) &&
         p.confirm_threshold_in_clutter > p.confirm_threshold;
}

/// held_to_clutter_threshold's threshold, or confirm_threshold.
template <class T, class Caps>
T confirmation_threshold(const TrackSlot<T, Caps>& t, const MfbpParams<T>& p) {
  return held_to_clutter_threshold(t, p) ? p.confirm_threshold_in_clutter : p.confirm_threshold;
}

/// Finalised scans a tentative track may stay unconfirmed: longer for one
/// held_to_clutter_threshold: it takes its target's detections at fair odds
/// against the component only once it has tightened, and at the plain
/// timeout it died before reaching 0.99 (docs/algorithms/mfbp.md §Birth).
template <class T, class Caps>
std::size_t tentative_timeout(const TrackSlot<T, Caps>& t, const MfbpParams<T>& p) {
  return held_to_clutter_threshold(t, p) &&
                 p.tentative_timeout_in_clutter_scans > p.tentative_timeout_scans
             ? p.tentative_timeout_in_clutter_scans
             : p.tentative_timeout_scans;
}

/// Online filter (window_length 1) only (docs/algorithms/mfbp.md §Birth, the
/// online filter inside clutter): adds the scan's visibility evidence
/// ln(xi(1)/xi(0)) to the score of a track held to confirm_threshold_in_clutter
/// and says whether the score reaches filter_confirm_score_in_clutter. A
/// filtered b_s is capped by one scan's evidence: at most p_s xi1 / (p_s xi1 +
/// (1 - p_s) xi0), so with p_s = 0.8 it reaches 0.99 only on a scan with
/// xi1/xi0 >= 24.75, which a young track inside a component rarely sees. The
/// score keeps every scan's evidence: a sequential likelihood-ratio test.
template <class T, class Caps>
bool filter_score_confirms(TrackSlot<T, Caps>& t, std::size_t n, const MfbpParams<T>& p) {
  if (p.window_length != 1 || n != 1 || !(p.filter_confirm_score_in_clutter > T(0)) ||
      !held_to_clutter_threshold(t, p)) {
    return false;
  }
  if (t.participates(0) && t.xi1[0] > T(0) && t.xi0[0] > T(0)) t.score += dmath::dlog(t.xi1[0] / t.xi0[0]);
  return t.score >= p.filter_confirm_score_in_clutter;
}

/// Window scans after the last scan on which a track held to
/// confirm_threshold_in_clutter may confirm (confirm_lookahead_in_clutter,
/// capped at n - 1). 0 when this window finalises every scan it holds
/// (flush(), or slide == window_length): no later window will see them.
template <class T>
std::size_t confirm_lookahead(std::size_t n, std::size_t finalize_count, const MfbpParams<T>& p) {
  if (n == 0 || finalize_count >= n) return 0;
  return p.confirm_lookahead_in_clutter < n - 1 ? p.confirm_lookahead_in_clutter : n - 1;
}

/// Confirms tentative tracks on window scans 0..n-1 (b_s >= the track's
/// confirmation_threshold on some scan; a track held to the in-clutter
/// threshold only on a scan with `lookahead` window scans after it).
template <class T, class Caps>
void confirm_tracks(TrackTable<T, Caps>& tracks, std::size_t n, std::size_t lookahead,
                    const MfbpParams<T>& p, TrackerCounters& counters) {
  for (auto& t : tracks) {
    if (!t.alive || t.confirmed) continue;
    if (filter_score_confirms(t, n, p)) {
      t.confirmed = true;
      ++counters.tracks_confirmed;
      continue;
    }
    const T threshold = confirmation_threshold(t, p);
    const std::size_t last = held_to_clutter_threshold(t, p) ? n - lookahead : n;
    for (std::size_t k = t.first; k < last; ++k) {
      if (t.vis[k] >= threshold) {
        t.confirmed = true;
        ++counters.tracks_confirmed;
        break;
      }
    }
  }
}

/// Low-visibility scans before track t is deleted (docs/algorithms/mfbp.md
/// §Confirmation and reporting, track continuity in clutter): delete_run, or
/// delete_run_in_clutter for a confirmed track whose smoothed position on
/// window scan k lies in the gate (clutter_gate_chi2) of a Gaussian clutter
/// component whose mean CNR is at least the track's mean SNR. There the
/// component explains the target's detections as well as the track does, so
/// a run of missed associations is weak evidence that the target is gone.
template <class T, class Caps>
std::size_t deletion_run(const TrackSlot<T, Caps>& t, std::size_t k, std::uint64_t time_us,
                         const ClutterTable<T, Caps>& cl, const MfbpParams<T>& p) {
  if (!t.confirmed || !(p.delete_run_in_clutter > p.delete_run)) return p.delete_run;
  const Vec2<T> z = model::polar_of_state(t.xs[k]);
  // Mean total powers E[1 + SNR] against E[1 + CNR] (for_each_gaussian_component's);
  // without amplitude every component counts (SNR 0).
  const T varsigma_t = p.amplitude.use_amplitude ? t.igs[k].mean() : T(1);
  bool inside = false;
  const auto consider = [&](const Vec2<T>& mu, const Mat2<T>& cov, T varsigma_c) {
    const model::Mahalanobis2<T> gate(cov);
    if (inside || !gate.valid() || varsigma_c < varsigma_t) return;
    inside = gate.distance2(z(0) - mu(0), model::wrap_angle(z(1) - mu(1))) <= p.clutter_gate_chi2;
  };
  for_each_gaussian_component(k, time_us, cl, p, consider);
  return inside ? p.delete_run_in_clutter : p.delete_run;
}

/// Deletion after a window of n scans whose first fc are finalised; the
/// newest of them at newest_us.
template <class T, class Caps>
void manage_tracks(TrackTable<T, Caps>& tracks, const ClutterTable<T, Caps>& cl, std::size_t n, std::size_t fc,
                   std::uint64_t newest_us, const MfbpParams<T>& p, TrackerCounters& counters) {
  for (auto& t : tracks) {
    if (!t.alive) continue;
    const std::size_t run_needed = n > 0 ? deletion_run(t, n - 1, newest_us, cl, p) : p.delete_run;
    for (std::size_t k = t.first; k < fc; ++k) {
      t.low_run = t.vis[k] < p.delete_threshold ? t.low_run + 1u : 0u;
      ++t.age;
    }
    bool remove = t.low_run >= run_needed;
    std::uint32_t run = t.low_run;
    for (std::size_t k = (fc > t.first ? fc : t.first); k < n && !remove; ++k) {
      run = t.vis[k] < p.delete_threshold ? run + 1u : 0u;
      remove = run >= run_needed;
    }
    if (!t.confirmed && t.age >= tentative_timeout(t, p)) remove = true;
    if (remove) {
      t.alive = false;
      ++counters.tracks_deleted;
    }
  }
}

/// Is track b (younger, or tentative) a duplicate of track a on window scan
/// k? Both present at k, at least one confirmed, and their smoothed states
/// closer than duplicate_chi2 in Mahalanobis^2 under P_a + P_b (4-D: a
/// crossing pair differs in velocity).
template <class T, class Caps>
bool is_duplicate(const TrackSlot<T, Caps>& a, const TrackSlot<T, Caps>& b, std::size_t k, const MfbpParams<T>& p) {
  if (!a.alive || !b.alive || k < a.first || k < b.first || !(a.confirmed || b.confirmed)) return false;
  const Vec4<T> e = a.xs[k] - b.xs[k];
  const Mat4<T> C = a.Ps[k].get() + b.Ps[k].get();
  T d2 = T(0);
  return model::mahalanobis_n<T, 4>(e, C, d2) && d2 < p.duplicate_chi2;
}

/// Of a duplicate pair, the track to keep: a confirmed one over a tentative
/// one, then the older (smaller id: ids are issued in birth order).
template <class T, class Caps>
bool keep_first(const TrackSlot<T, Caps>& a, const TrackSlot<T, Caps>& b) {
  if (a.confirmed != b.confirmed) return a.confirmed;
  return a.id < b.id;
}

/// Duplicate suppression after a window of n scans (docs/algorithms/mfbp.md
/// §Confirmation and reporting; ours, duplicate_chi2 > 0): two tracks on one
/// target (a strong target's split detections) otherwise both survive,
/// since each takes one of the detections. The duplicate is deleted
/// (tracks_deleted), never merged into the kept track's beliefs. O(N_T^2)
/// 4x4 Cholesky factorisations per window.
template <class T, class Caps>
void suppress_duplicates(TrackTable<T, Caps>& tracks, std::size_t n, const MfbpParams<T>& p,
                         TrackerCounters& counters) {
  if (!(p.duplicate_chi2 > T(0)) || n == 0) return;
  const std::size_t k = n - 1;
  for (auto& a : tracks) {
    for (auto& b : tracks) {
      if (&a == &b || !a.alive || !keep_first(a, b) || !is_duplicate(a, b, k, p)) continue;
      b.alive = false;
      ++counters.tracks_deleted;
    }
  }
}

/// Is measurement-space point z = (range, azimuth) in the gate of a
/// component's Normal-Wishart belief nw (in_gaussian_gate under E[D^-1])?
template <class T>
bool in_component_gate(const Vec2<T>& z, const NormalWishart<T>& nw, T chi2) {
  return in_gaussian_gate(z(0), z(1), nw.mu, nw.expected_covariance(), chi2);
}

/// Is z in the gate (clutter_gate_chi2) of a live component other than
/// `slot` on window scan k?
template <class T, class Caps>
bool in_other_component_gate(const Vec2<T>& z, const ClutterTable<T, Caps>& cl, std::size_t slot, std::size_t k,
                             const MfbpParams<T>& p) {
  for (std::size_t c = 0; c < ClutterTable<T, Caps>::kMaxComp; ++c) {
    if (c != slot && cl.comps[c].alive && in_component_gate(z, cl.comps[c].nws[k], p.clutter_gate_chi2)) return true;
  }
  return false;
}

/// Tracks that a newly born clutter component explains (docs/algorithms/
/// mfbp.md §Birth, tracks a new component explains; ours;
/// retire_in_new_clutter): alive on at most seed_scans scans up to the
/// newest window scan n - 1, i.e. born on the scans the component was seeded
/// from, and inside its gate (clutter_gate_chi2 under E[D^-1]) there. Before
/// the cloud was a component its points were unexplained, so they started
/// tracks; now they are clutter, and such a track has no evidence of its
/// own. A target tracked from before those scans is older and kept, and so
/// are tracks already scored against clutter there, which the rules for
/// young tracks inside clutter decide: one held_to_clutter_threshold (a
/// component there died and is born again) and one inside the gate of
/// another live component (the new one was seeded in its tail). Deleted
/// tracks are counted in tracks_deleted.
template <class T, class Caps>
void retire_tracks_in_new_component(TrackTable<T, Caps>& tracks, const ClutterTable<T, Caps>& cl, std::size_t slot,
                                    std::size_t seed_scans, std::size_t n, const MfbpParams<T>& p,
                                    TrackerCounters& counters) {
  const CompSlot<T, Caps>& cs = cl.comps[slot];
  if (n == 0 || !cs.alive) return;
  for (auto& t : tracks) {
    // Scans lived up to n - 1: the finalised ones (age) and its window scans.
    if (!t.alive || t.first >= n || t.age + (n - t.first) > seed_scans || held_to_clutter_threshold(t, p)) continue;
    const Vec2<T> z = model::polar_of_state(t.xs[n - 1]);
    if (!in_component_gate(z, cs.nws[n - 1], p.clutter_gate_chi2) || in_other_component_gate(z, cl, slot, n - 1, p)) {
      continue;
    }
    t.alive = false;
    ++counters.tracks_deleted;
  }
}

/// Component death after a window whose first fc scans are finalised.
template <class T, class Caps>
void manage_components(ClutterTable<T, Caps>& cl, std::size_t fc, const MfbpParams<T>& p,
                       TrackerCounters& counters) {
  for (std::size_t c = 0; c < ClutterTable<T, Caps>::kMaxComp; ++c) {
    CompSlot<T, Caps>& cs = cl.comps[c];
    if (!cs.alive) continue;
    bool all_low = fc > 0;
    for (std::size_t k = 0; k < fc; ++k) {
      if (!(cl.component_count(k, c + 1) < p.clutter_death_count)) all_low = false;
    }
    cs.low_windows = all_low ? cs.low_windows + 1u : 0u;
    if (cs.low_windows >= p.clutter_death_windows) {
      cs.alive = false;
      ++counters.clutter_deleted;
    }
  }
}

/// Max-gap restart: every track and Gaussian component is dropped (counted).
template <class T, class Caps>
void drop_all(TrackTable<T, Caps>& tracks, ClutterTable<T, Caps>& cl, TrackerCounters& counters) {
  for (auto& t : tracks) {
    if (!t.alive) continue;
    t.alive = false;
    ++counters.tracks_deleted;
  }
  for (auto& c : cl.comps) {
    if (!c.alive) continue;
    c.alive = false;
    ++counters.clutter_deleted;
  }
}

}  // namespace mptrack::mfbp
