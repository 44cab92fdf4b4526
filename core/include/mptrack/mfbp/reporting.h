// The estimate of one finalised scan (docs/algorithms/mfbp.md
// §Confirmation and reporting): every confirmed track with its smoothed
// state (eq. (35)), covariance, visibility b_s (eq. (64)) and SNR (eq. (43)),
// and every clutter source with its expected count M_tau,k = M_k E[pi_tau]
// (eq. (69)), its spatial mean and covariance (eq. (50)) and CNR (eq. (62));
// with known clutter, the given map.
// One missed scan is tolerated before a confirmed track stops being reported
// (report_existence_min; our choice, docs/algorithms/mfbp.md §Departures).
// The same report of the window's newest scan, before it is final, is the
// smoother's provisional (lag 0) output, predicted to the scans that arrive
// before the next window (docs/algorithms/mfbp.md §Provisional output).
#pragma once

#include <cstddef>
#include <cstdint>

#include "mptrack/mfbp/clutter_slot.h"
#include "mptrack/mfbp/mfbp_params.h"
#include "mptrack/mfbp/model_constants.h"
#include "mptrack/mfbp/target_filter.h"
#include "mptrack/mfbp/track_slot.h"
#include "mptrack/mfbp/window_store.h"
#include "mptrack/track_report.h"

namespace mptrack::mfbp {

/// A final report of scan k (report_scan) or the provisional one of the
/// window's newest scan (report_provisional).
enum class ReportKind { kFinal, kProvisional };

/// Confirmed tracks on window scan k. A final report updates each one's
/// vis_emitted, the b_s of its last final scan; a provisional one changes
/// nothing and takes the b_s of window scan k - 1 as the previous scan's.
template <class T, class Caps, class Estimate>
void report_tracks(Estimate& est, std::size_t k, const ScanSlot<T, Caps>& s, TrackTable<T, Caps>& tracks,
                   const MfbpParams<T>& p, ReportKind kind = ReportKind::kFinal) {
  for (auto& t : tracks) {
    if (!t.alive || k < t.first || !t.confirmed) continue;
    T vis_prev = t.vis_emitted;
    if (kind == ReportKind::kFinal) {
      t.vis_emitted = t.vis[k];
    } else {
      vis_prev = k > t.first ? t.vis[k - 1] : T(0);
    }
    if (t.vis[k] < p.report_existence_min && vis_prev < p.report_existence_min) continue;
    TrackReport<T> r;
    r.id = t.id;
    r.state = t.xs[k];
    r.covariance = t.Ps[k].get();
    r.existence = t.vis[k];
    r.snr = p.amplitude.use_amplitude ? t.igs[k].snr() : T(0);
    r.confirmed = true;
    r.measurement_index = t.best[k] >= 0 ? static_cast<std::int32_t>(s.orig_index[static_cast<std::size_t>(t.best[k])]) : -1;
    (void)est.tracks.push_back(r);  // cannot overflow: one report per track slot
  }
}

/// The known clutter map at the estimate's time (the uniform report u is
/// filled in but for its counts).
template <class T, class Estimate>
void report_known_clutter(Estimate& est, ClutterReport<T> u, const MfbpParams<T>& p, std::size_t max_comp) {
  u.expected_count = p.known_clutter.uniform_rate_per_scan;
  u.cnr = p.known_clutter.uniform_cnr;
  (void)est.clutter.push_back(u);
  const std::size_t nk = known_components(p, max_comp);
  for (std::size_t c = 0; c < nk; ++c) {
    const auto& comp = p.known_clutter.components[c];
    if (!comp.exists_at(est.time_us)) continue;
    ClutterReport<T> r;
    r.id = static_cast<std::uint32_t>(c + 1);
    r.mean = comp.mean;
    r.covariance = comp.covariance;
    r.expected_count = comp.rate_per_scan;
    r.cnr = comp.cnr;
    (void)est.clutter.push_back(r);
  }
}

/// The clutter beliefs on window scan k.
template <class T, class Caps, class Estimate>
void report_clutter_beliefs(Estimate& est, ClutterReport<T> u, std::size_t k, const ClutterTable<T, Caps>& cl,
                            const MfbpParams<T>& p) {
  u.expected_count = estimate_clutter(p) ? cl.component_count(k, 0) : p.uniform_rate_per_scan;
  u.cnr = cl.uniform.igs[k].snr();
  (void)est.clutter.push_back(u);
  if (!estimate_clutter(p)) return;
  for (std::size_t c = 0; c < ClutterTable<T, Caps>::kMaxComp; ++c) {
    const CompSlot<T, Caps>& cs = cl.comps[c];
    if (!cs.alive) continue;
    ClutterReport<T> r;
    r.id = cs.id;
    r.mean = cs.nws[k].mu;
    r.covariance = cs.nws[k].expected_covariance();
    r.expected_count = cl.component_count(k, c + 1);
    r.cnr = cs.igs[k].snr();
    (void)est.clutter.push_back(r);
  }
}

/// Fills est (in place: a ScanEstimate is kilobytes, too big for the
/// stack) for window scan k, scan number scan_index: finalised (kFinal) or
/// the provisional estimate of the newest scan (kProvisional).
template <class T, class Caps, class Estimate>
void report_scan(Estimate& est, std::size_t k, std::uint64_t scan_index, const WindowStore<T, Caps>& store,
                 TrackTable<T, Caps>& tracks, const ClutterTable<T, Caps>& cl, const MfbpParams<T>& p,
                 ReportKind kind = ReportKind::kFinal) {
  est.tracks.clear();
  est.clutter.clear();
  est.time_us = store.win(k).time_us;
  est.scan_index = static_cast<std::uint32_t>(scan_index);
  report_tracks(est, k, store.win(k), tracks, p, kind);
  ClutterReport<T> u;
  u.id = 0;
  u.uniform = true;
  u.mean = Vec2<T>(T(0.5) * (p.region.range_min_m + p.region.range_max_m),
                   T(0.5) * (p.region.azimuth_min_rad + p.region.azimuth_max_rad));
  u.covariance.setZero();
  if (p.clutter_mode == ClutterMode::kKnown) {
    report_known_clutter(est, u, p, Caps::kMaxClutterComponents);
  } else {
    report_clutter_beliefs(est, u, k, cl, p);
  }
}

/// The provisional estimate est predicted to time_us, scan number
/// scan_index, on a step that processed no window (docs/algorithms/mfbp.md
/// §Provisional output): every track's state and covariance by the CV model
/// with acceleration variance q (cv_predict, SPD guard included; a repair is
/// not counted, this is output only), no measurement; existence, SNR and the
/// clutter map as the last window left them.
template <class T, class Estimate>
void coast_report(Estimate& est, std::uint64_t time_us, std::uint64_t scan_index, T q) {
  const T dt = dt_s<T>(est.time_us, time_us);
  for (auto& r : est.tracks) {
    static_cast<void>(cv_predict(r.state, r.covariance, dt, q));
    r.measurement_index = -1;
  }
  est.time_us = time_us;
  est.scan_index = static_cast<std::uint32_t>(scan_index);
}

}  // namespace mptrack::mfbp
