// Data association of one window scan (seed 000 Algorithm 1 line 3): the
// local evidence of evidence.h, loopy BP over it (eqs. (99)-(102),
// association_bp.h), and the storage of the beliefs the MF sweeps consume:
// per track the missed-detection belief a_i0 (the weight 1 - a_i0 of
// eq. (40)), its edges a_ij, the amplitude statistics of eq. (43) and the
// visibility messages of eq. (65)-(66); per scan the target and uniform
// shares of each measurement and the clutter statistics per source
// (eqs. (54)-(55), (62), (69)).
//
// The Associator owns the BP and the per-scan moments scratch; it counts
// BP runs and iterations in the caller's AssociationStats, and gated pairs
// dropped by the per-track list (kMaxGatePairs) or the scan's shared pool
// (kMaxGatePool, mfbp_caps.h) in TrackerCounters::association_cap_hits.
// The edge beliefs of a scan live in its ScanSlot's pool; each track keeps
// an offset and a count there (docs/algorithms/mfbp.md §Evidence and association).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "mptrack/math/detmath.h"
#include "mptrack/mfbp/association_bp.h"
#include "mptrack/mfbp/clutter_slot.h"
#include "mptrack/mfbp/evidence.h"
#include "mptrack/mfbp/mfbp_caps.h"
#include "mptrack/mfbp/model_constants.h"
#include "mptrack/mfbp/nemp.h"
#include "mptrack/mfbp/track_slot.h"
#include "mptrack/mfbp/weaker_clutter.h"
#include "mptrack/mfbp/window_store.h"
#include "mptrack/model/mahalanobis.h"
#include "mptrack/profile.h"
#include "mptrack/track_report.h"

namespace mptrack::mfbp {

/// Association diagnostics since init() (the tracker keeps them next to its
/// counters; an 8-byte member here would pad the tracker on 32-bit targets).
struct AssociationStats {
  std::uint64_t bp_runs = 0;
  std::uint64_t bp_iterations = 0;
};

template <class T, class Caps>
class Associator {
 public:
  static constexpr std::size_t kMaxTargets = Caps::kMaxTargets;
  static constexpr std::size_t kMaxMeas = Caps::kMaxMeasurements;
  static constexpr std::size_t kSources = Caps::kMaxClutterComponents + 1;
  static constexpr std::size_t kMaxGate = kMaxGatePairs<Caps>;
  static constexpr std::size_t kPool = kMaxGatePool<Caps>;
  using Bp = AssociationBp<T, kMaxTargets, kMaxMeas, kSources, kPool>;
  using Tracks = TrackTable<T, Caps>;
  using Scan = ScanSlot<T, Caps>;
  using Sources = ClutterSources<kSources>;
  using TrackList = std::array<std::size_t, kMaxTargets>;

  /// Evidence, BP and stored beliefs of window scan k. Returns the largest
  /// change of any stored association belief (the outer loop's test).
  /// Gate pairs dropped by the cap are counted when count_drops is set (the
  /// first MP iteration of a window: the later ones drop the same pairs).
  T associate(std::size_t k, WindowStore<T, Caps>& store, Tracks& tracks,
              const ClutterTable<T, Caps>& cl, const MfbpParams<T>& p, const ModelConstants<T>& mc,
              TrackerCounters& counters, AssociationStats& stats, bool count_drops,
              NempState<T, Caps>* nemp = nullptr) {
    MPTRACK_PROFILE_STAGE(g_mfbp, MfbpStage::kEvidence);
    Scan& s = store.win(k);
    const Sources src = clutter_sources(cl, p);
    (void)bp_.reset(s.count, src.count);
    const T lambda = expected_clutter_count(tracks, k, s.count, p, mc.n_order);
    s.lambda_hat = lambda;
    // With Doppler every clutter source has a uniform radial-velocity
    // density 1 / (2 span) (our choice, docs/algorithms/mfbp.md §Departures).
    const T log_dop_clutter = s.doppler ? -dmath::dlog(T(2) * p.doppler_span_mps) : T(0);
    clutter_evidence(k, s, src, cl, lambda, p, mc, log_dop_clutter);
    if (nemp != nullptr) nemp->apply(k, s.count, bp_);
    compute_moments(k, s, tracks, cl, p, mc, counters);
    TrackList bp_track{};
    std::uint64_t dropped = 0;
    std::size_t nbt = add_targets(k, s, tracks, p, mc, bp_track, dropped);
    if (count_drops) counters.association_cap_hits += dropped;

    MPTRACK_PROFILE_STAGE(g_mfbp, MfbpStage::kBp);
    run_bp(p, counters, stats);
    if (nemp != nullptr) {
      // NEMP rounds (docs/algorithms/nemp.md §NEMP loop): fused clutter
      // messages, then BP again on the same evidence; the moments and the
      // dropped-pair count do not change.
      for (std::size_t r = 0; r < nemp->params().rounds && nemp->update(k, s.count, bp_); ++r) {
        (void)bp_.reset(s.count, src.count);
        clutter_evidence(k, s, src, cl, lambda, p, mc, log_dop_clutter);
        nemp->apply(k, s.count, bp_);
        std::uint64_t dropped_again = 0;
        nbt = add_targets(k, s, tracks, p, mc, bp_track, dropped_again);
        run_bp(p, counters, stats);
      }
    }
    for (auto& t : tracks) {
      if (t.alive && k >= t.first && !t.participates(k)) t.forget_association(k);
    }
    std::array<T, kMaxMeas> new_share{};
    T delta = store_track_beliefs(k, s, tracks, p, mc, bp_track, nbt, new_share);
    delta = store_shares(s, new_share, delta);
    store_clutter_stats(k, s, src, cl, p);
    s.has_beliefs = true;
    return delta;
  }

 private:
  void clutter_evidence(std::size_t k, const Scan& s, const Sources& src, const ClutterTable<T, Caps>& cl,
                        T lambda, const MfbpParams<T>& p, const ModelConstants<T>& mc, T log_dop_clutter) {
    if (p.clutter_mode == ClutterMode::kKnown) {
      known_clutter_evidence(bp_, s, src, p, mc, log_dop_clutter);
    } else {
      estimated_clutter_evidence(bp_, s, k, src, cl, lambda, p, mc, log_dop_clutter);
    }
  }

  void run_bp(const MfbpParams<T>& p, TrackerCounters& counters, AssociationStats& stats) {
    const auto res = bp_.run(p.bp_damping, p.bp_tolerance, p.bp_max_iterations);
    if (!res.converged) ++counters.bp_not_converged;
    stats.bp_iterations += res.iterations;
    ++stats.bp_runs;
  }

  static void track_delta(T a, T b, T& delta) {
    const T dd = a > b ? a - b : b - a;
    delta = dd > delta ? dd : delta;
  }

  /// Predicted measurement moments of every track first, so that
  /// unresolved tracks can share them (couple_unresolved).
  void compute_moments(std::size_t k, const Scan& s, Tracks& tracks, const ClutterTable<T, Caps>& cl,
                       const MfbpParams<T>& p, const ModelConstants<T>& mc, TrackerCounters& counters) {
    for (std::size_t i = 0; i < kMaxTargets; ++i) {
      TrackSlot<T, Caps>& t = tracks[i];
      TrackMoments<T>& mo = moments_[i];
      mo.ok = false;
      t.mate[k] = 0;
      if (!t.participates(k)) continue;
      mo.ok = track_moments(t, k, s, p, mc, counters, mo);
      mo.predictive = mo.ok && p.tentative_predictive_in_clutter && !t.confirmed &&
                      inside_weaker_component(mo.z(0), mo.z(1), t.igs[k].mean(), k, s.time_us, cl, p);
      // Online filter: young tracks in any component confirm by the score
      // (docs/algorithms/mfbp.md §Birth). The mark is sticky, so once set
      // the gate test is not repeated.
      if (mo.ok && !t.predicted_in_component && filter_holds_in_any_component(t, p) &&
          inside_any_component(mo.z(0), mo.z(1), k, s.time_us, cl, p)) {
        t.predicted_in_component = true;
      }
    }
    if (p.tentative_predictive_in_clutter) mark_predictive(tracks, mc, p);
    if (p.unresolved_chi2 > T(0)) {
      couple_unresolved(moments_, tracks, k, p);
    } else {
      for (auto& mo : moments_) mo.z_shared = mo.z;
    }
  }

  /// Young tracks inside weaker clutter (docs/algorithms/mfbp.md §Birth):
  /// a candidate whose predicted measurement lies in the gate of a
  /// confirmed track (gate_chi2 under Sz_a + Sz_b + R) keeps eq. (79): the
  /// predictive density is for starting a target no track holds, not for a
  /// second track on a held one, which would take part of that track's
  /// detections (chaff-crossing: more breaks). The rest are marked
  /// (TrackSlot::predictive_evidence, for the confirmation threshold).
  void mark_predictive(Tracks& tracks, const ModelConstants<T>& mc, const MfbpParams<T>& p) {
    // The confirmed tracks with moments, in slot order (the only ones tested).
    std::array<std::uint16_t, kMaxTargets> held{};
    std::size_t n_held = 0;
    for (std::size_t b = 0; b < kMaxTargets; ++b) {
      if (moments_[b].ok && tracks[b].confirmed) held[n_held++] = static_cast<std::uint16_t>(b);
    }
    for (std::size_t a = 0; a < kMaxTargets; ++a) {
      TrackMoments<T>& ma = moments_[a];
      if (!ma.predictive) continue;
      for (std::size_t q = 0; q < n_held && ma.predictive; ++q) {
        const std::size_t b = held[q];
        const TrackMoments<T>& mb = moments_[b];
        if (b == a) continue;
        const model::Mahalanobis2<T> dist(ma.Sz + mb.Sz + mc.R);
        if (!dist.valid()) continue;
        const Vec2<T> e(mb.z(0) - ma.z(0), model::wrap_angle(mb.z(1) - ma.z(1)));
        if (!(dist.distance2(e) > p.gate_chi2)) ma.predictive = false;
      }
      if (ma.predictive) tracks[a].predictive_evidence = true;
    }
  }

  /// Gated target evidence into the BP; bp_track[b] = the track of BP target b.
  /// Every track keeps up to kMaxGate pairs (the most likely) from the
  /// scan's pool of kPool; if their sum does not fit, the lists are cut
  /// to a common quota (pool_quotas) and gated again, so the pairs dropped
  /// are the least likely ones of the tracks that gate the most
  /// (docs/algorithms/mfbp.md §Evidence and association).
  std::size_t add_targets(std::size_t k, const Scan& s, const Tracks& tracks, const MfbpParams<T>& p,
                          const ModelConstants<T>& mc, TrackList& bp_track, std::uint64_t& dropped_pairs) {
    std::size_t used = 0;
    std::size_t nbt = gate_tracks(k, s, tracks, p, mc, bp_track, false, used, dropped_pairs);
    if (used > kPool) {
      pool_quotas(nbt);
      used = 0;
      nbt = gate_tracks(k, s, tracks, p, mc, bp_track, true, used, dropped_pairs);
    }
    std::size_t b = 0;
    for (std::size_t i = 0; i < nbt; ++i) {
      if (bp_.add_target(theta0_[i]) != Status::kOk) continue;
      for (std::size_t e = begin_[i]; e < std::size_t{begin_[i]} + size_[i]; ++e) {
        (void)bp_.add_edge(scratch_meas_[e], scratch_v_[e]);
      }
      bp_track[b++] = bp_track[i];
    }
    return b;
  }

  /// One gating pass: per gated track its missed evidence, its list (in
  /// measurement order) in the scratch pool from begin_[b] and its size.
  /// use_quota: lists are cut to quota_[b]; otherwise to kMaxGate, and
  /// `used` past kPool tells the caller the pool is short (only the lists
  /// that fit are written). dropped_pairs: gated pairs not kept.
  std::size_t gate_tracks(std::size_t k, const Scan& s, const Tracks& tracks, const MfbpParams<T>& p,
                          const ModelConstants<T>& mc, TrackList& bp_track, bool use_quota, std::size_t& used,
                          std::uint64_t& dropped_pairs) {
    std::size_t nbt = 0;
    std::uint64_t dropped_total = 0;
    for (std::size_t i = 0; i < kMaxTargets; ++i) {
      const TrackSlot<T, Caps>& t = tracks[i];
      const TrackMoments<T>& mo = moments_[i];
      if (!mo.ok) continue;
      const model::Mahalanobis2<T> gate(mo.Sz + mc.R);
      if (!gate.valid()) continue;
      const T pd = detection_prob(p, mc.n_order, t.igs[k]);
      GateList<T, kMaxGate> list;
      if (use_quota) list.cap = quota_[nbt];
      dropped_total += target_evidence(t, mo, gate, s, k, p, mc, list);
      theta0_[nbt] = missed_evidence(pd, t.extr[k], p.pd_invisible);
      size_[nbt] = static_cast<std::uint16_t>(list.size);
      if (used + list.size <= kPool) {
        begin_[nbt] = static_cast<std::uint16_t>(used);
        const auto order = list.measurement_order();
        for (std::size_t a = 0; a < list.size; ++a) {
          scratch_meas_[used + a] = list.j[order[a]];
          scratch_v_[used + a] = list.v[order[a]];
        }
      }
      used += list.size;
      bp_track[nbt++] = i;
    }
    if (use_quota || used <= kPool) dropped_pairs += dropped_total;
    return nbt;
  }

  /// Per-track quotas when the lists of the first pass (size_) overflow
  /// the pool: the largest q with sum_b min(size_b, q) <= kPool (water
  /// filling), the rest of the pool one pair each to the first tracks
  /// still above q (slot order, deterministic).
  void pool_quotas(std::size_t nbt) {
    std::size_t q = 0;
    for (std::size_t lo = 0, hi = kMaxGate; lo <= hi && hi > 0;) {
      const std::size_t mid = (lo + hi) / 2;
      std::size_t sum = 0;
      for (std::size_t b = 0; b < nbt; ++b) sum += size_[b] < mid ? size_[b] : mid;
      if (sum <= kPool) {
        q = mid;
        lo = mid + 1;
      } else {
        hi = mid - 1;
      }
    }
    std::size_t left = kPool;
    for (std::size_t b = 0; b < nbt; ++b) {
      quota_[b] = static_cast<std::uint16_t>(size_[b] < q ? size_[b] : q);
      left -= quota_[b];
    }
    for (std::size_t b = 0; b < nbt && left > 0; ++b) {
      if (size_[b] > q) {
        ++quota_[b];
        --left;
      }
    }
  }

  /// Missed and edge beliefs, amplitude statistics and visibility messages
  /// of every track in the BP; new_share[j] += its edge beliefs.
  T store_track_beliefs(std::size_t k, Scan& s, Tracks& tracks, const MfbpParams<T>& p,
                        const ModelConstants<T>& mc, const TrackList& bp_track, std::size_t nbt,
                        std::array<T, kMaxMeas>& new_share) {
    const T d = p.amplitude.threshold;
    T delta = T(0);
    std::size_t used = 0;
    for (std::size_t i = 0, b = 0; i < kMaxTargets; ++i) {
      if (b < nbt && bp_track[b] == i) {
        store_beliefs(k, s, tracks[i], b++, p, mc, d, used, new_share, delta);
      } else {
        keep_stale_edges(k, s, tracks[i], used);
      }
    }
    for (std::size_t e = 0; e < used; ++e) {
      s.edge_meas[e] = scratch_meas_[e];
      s.edge_w[e] = scratch_v_[e];
    }
    return delta;
  }

  /// A track in the scan (moments or gate failed on this pass) that is not
  /// in the BP keeps its previous beliefs; its edges move to the new pool
  /// (as many as fit: the BP's own edges never exceed kPool, these may).
  void keep_stale_edges(std::size_t k, const Scan& s, TrackSlot<T, Caps>& t, std::size_t& used) {
    if (!t.alive || !t.participates(k) || t.n_edges[k] == 0) return;
    std::size_t n = t.n_edges[k];
    if (n > kPool - used) n = kPool - used;
    for (std::size_t a = 0; a < n; ++a) {
      scratch_meas_[used + a] = s.edge_meas[t.edge_begin[k] + a];
      scratch_v_[used + a] = s.edge_w[t.edge_begin[k] + a];
    }
    t.edge_begin[k] = static_cast<std::uint16_t>(used);
    t.n_edges[k] = static_cast<std::uint8_t>(n);
    used += n;
  }

  /// BP target i's missed and edge beliefs into track t (edges into the
  /// scratch pool from `used`).
  void store_beliefs(std::size_t k, const Scan& s, TrackSlot<T, Caps>& t, std::size_t i, const MfbpParams<T>& p,
                     const ModelConstants<T>& mc, T d, std::size_t& used, std::array<T, kMaxMeas>& new_share,
                     T& delta) {
    {
      const T missed = bp_.missed_belief(i);
      track_delta(missed, t.missed[k], delta);
      t.missed[k] = missed;
      std::size_t ne = 0;
      T best_w = missed;
      std::int32_t best_j = -1;
      AmplitudeStats<T> as{};
      t.edge_begin[k] = static_cast<std::uint16_t>(used);
      for (std::size_t e = bp_.edge_begin(i); e < bp_.edge_end(i); ++e) {
        const std::size_t j = bp_.edge_meas(e);
        const T a = bp_.edge_belief(e);
        scratch_meas_[used + ne] = static_cast<std::uint16_t>(j);
        scratch_v_[used + ne] = a;
        ++ne;
        new_share[j] += a;
        as.w += a;
        as.s += a * (s.amp[j] * s.amp[j] - d * d);
        if (a > best_w) {
          best_w = a;
          best_j = static_cast<std::int32_t>(j);
        }
      }
      used += ne;
      t.n_edges[k] = static_cast<std::uint8_t>(ne);
      t.best[k] = best_j;
      t.amp[k] = as;
      store_visibility_messages(t, k, bp_.lambda(i), detection_prob(p, mc.n_order, t.igs[k]), p.pd_invisible);
    }
  }

  /// Visibility messages xi(s) from the association (eq. (65)-(66)), normalised.
  static void store_visibility_messages(TrackSlot<T, Caps>& t, std::size_t k, T lam, T pd, T eps) {
    T x1 = T(1) - pd + pd * lam;
    T x0 = T(1) - eps + eps * lam;
    const T z = x1 + x0;
    t.xi1[k] = x1 / z;
    t.xi0[k] = x0 / z;
  }

  /// Target and uniform-clutter shares of every measurement.
  T store_shares(Scan& s, const std::array<T, kMaxMeas>& new_share, T delta) const {
    for (std::size_t j = 0; j < s.count; ++j) {
      track_delta(new_share[j], s.target_share[j], delta);
      s.target_share[j] = new_share[j];
      const T u = bp_.clutter_belief(0, j);
      track_delta(u, s.uniform_share[j], delta);
      s.uniform_share[j] = u;
    }
    return delta;
  }

  /// Clutter statistics per source slot for the clutter chain.
  void store_clutter_stats(std::size_t k, Scan& s, const Sources& src, const ClutterTable<T, Caps>& cl,
                           const MfbpParams<T>& p) const {
    const T d = p.amplitude.threshold;
    s.clear_source_stats();
    for (std::size_t q = 0; q < src.count; ++q) {
      const std::size_t slot = src.slot[q];
      NwStats<T> st{};
      if (slot > 0 && estimate_clutter(p)) st.ref = cl.comps[slot - 1].nws[k].mu;
      AmplitudeStats<T> as{};
      for (std::size_t j = 0; j < s.count; ++j) {
        const T a = bp_.clutter_belief(q, j);
        if (!(a > T(0))) continue;
        if (slot > 0) st.add(Vec2<T>(s.r[j], s.az[j]), a);
        as.w += a;
        as.s += a * (s.amp[j] * s.amp[j] - d * d);
      }
      s.nw_stats[slot] = st;
      s.amp_stats[slot] = as;
    }
  }

  std::array<TrackMoments<T>, kMaxTargets> moments_{};
  Bp bp_{};
  // Per BP target of the scan being associated: missed evidence, list
  // offset and size in the scratch pool, quota when the pool is short.
  std::array<T, kMaxTargets> theta0_{};
  std::array<std::uint16_t, kMaxTargets> begin_{}, size_{}, quota_{};
  // Scratch pool: the gated lists (log evidence) before the BP, the new
  // edge beliefs of the scan after it (copied into ScanSlot::edge_*).
  std::array<std::uint16_t, kPool> scratch_meas_{};
  std::array<T, kPool> scratch_v_{};
};

}  // namespace mptrack::mfbp
