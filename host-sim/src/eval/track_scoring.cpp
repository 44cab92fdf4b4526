// Track scores of a run; definitions in docs/algorithms/metrics.md §Track scores.
#include "eval/track_scoring.h"

#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>

#include "eval/amota.h"
#include "mptrack/model/mahalanobis.h"
#include "mptrack/model/polar_measurement.h"

namespace mptrack::sim {

namespace {

constexpr double kTwoPi = 6.283185307179586;

}  // namespace

ScanAssignment match_scan(const scenario::SimScan& scan, const EstimateOut& est, double gate_m,
                          double min_existence, ScoringSolver& solver, const ScanAssignment* previous) {
  std::vector<const TrackOut*> tracks;
  for (const TrackOut& t : est.tracks) {
    if (t.confirmed && t.existence >= min_existence) tracks.push_back(&t);
  }
  ScanAssignment out;
  for (const TrackOut* t : tracks) out[t->id] = kNoTarget;
  if (tracks.empty() || scan.truth.empty()) return out;
  // CLEAR MOT (Bernardin, Stiefelhagen 2008, Sec. 2.1.1): a pair of the
  // previous scan that is still within the gate is kept before the
  // assignment, so two tracks on one unresolved pair do not swap targets
  // on position noise (docs/algorithms/metrics.md §Track scores).
  std::vector<bool> truth_taken(scan.truth.size(), false);
  std::vector<const TrackOut*> free_tracks;
  for (const TrackOut* t : tracks) {
    bool kept = false;
    const auto prev = previous != nullptr ? previous->find(t->id) : ScanAssignment::const_iterator{};
    if (previous != nullptr && prev != previous->end() && prev->second != kNoTarget) {
      for (std::size_t j = 0; j < scan.truth.size() && !kept; ++j) {
        const scenario::TruthState& x = scan.truth[j];
        if (x.target_id != prev->second || truth_taken[j]) continue;
        if (std::hypot(t->px - x.x.px, t->py - x.x.py) < gate_m) {
          out[t->id] = x.target_id;
          truth_taken[j] = true;
          kept = true;
        }
      }
    }
    if (!kept) free_tracks.push_back(t);
  }
  std::vector<std::size_t> free_truths;
  for (std::size_t j = 0; j < scan.truth.size(); ++j) {
    if (!truth_taken[j]) free_truths.push_back(j);
  }
  if (free_tracks.empty() || free_truths.empty()) return out;
  if (solver.resize(free_tracks.size(), free_truths.size()) != Status::kOk) {
    throw std::runtime_error("track scoring: more than 256 tracks or targets in a scan");
  }
  for (std::size_t i = 0; i < free_tracks.size(); ++i) {
    for (std::size_t j = 0; j < free_truths.size(); ++j) {
      const scenario::TruthState& x = scan.truth[free_truths[j]];
      const double d = std::hypot(free_tracks[i]->px - x.x.px, free_tracks[i]->py - x.x.py);
      solver.cost(i, j) = std::min(d, gate_m);
    }
  }
  if (solver.solve() != Status::kOk) throw std::runtime_error("track scoring: assignment failed");
  for (std::size_t i = 0; i < free_tracks.size(); ++i) {
    const std::int32_t j = solver.row_assignment(i);
    if (j >= 0 && solver.cost(i, static_cast<std::size_t>(j)) < gate_m) {
      out[free_tracks[i]->id] = scan.truth[free_truths[static_cast<std::size_t>(j)]].target_id;
    }
  }
  return out;
}

namespace {

struct TrackTally {
  std::uint32_t scans = 0;                       ///< confirmed scans
  std::map<std::uint32_t, std::uint32_t> hits;   ///< target id -> scans assigned to it
};

/// Marks each scored track valid (assigned to its most frequent target for at
/// least half of its confirmed scans) or false; returns id -> valid.
std::map<std::uint32_t, bool> classify_tracks(const std::vector<ScanAssignment>& per_scan,
                                              std::uint32_t min_scans, RunTrackScore& run) {
  std::map<std::uint32_t, TrackTally> tally;
  for (const ScanAssignment& a : per_scan) {
    for (const auto& [track, target] : a) {
      TrackTally& t = tally[track];
      ++t.scans;
      if (target != kNoTarget) ++t.hits[target];
    }
  }
  std::map<std::uint32_t, bool> valid;
  std::map<std::uint32_t, bool> followed;  // target id -> some valid track follows it
  for (const auto& [track, t] : tally) {
    if (t.scans < min_scans) continue;
    ++run.scored_tracks;
    std::uint32_t best_target = kNoTarget, best_hits = 0;
    for (const auto& [target, hits] : t.hits) {
      if (hits > best_hits) best_target = target, best_hits = hits;
    }
    const bool is_valid = 2 * best_hits >= t.scans && best_hits > 0;
    valid[track] = is_valid;
    if (is_valid) {
      ++run.valid_tracks;
      followed[best_target] = true;
    } else {
      ++run.false_tracks;
    }
  }
  run.targets_with_valid_track = static_cast<std::uint32_t>(followed.size());
  return valid;
}

/// Ground range and bearing of a position about the sensor at the origin.
void add_polar_error(const scenario::KinematicState& truth, const TrackOut& track, TargetScore& s) {
  s.abs_range_err_sum_m += std::fabs(std::hypot(track.px, track.py) - std::hypot(truth.px, truth.py));
  const double d = std::atan2(track.py, track.px) - std::atan2(truth.py, truth.px);
  s.abs_bearing_err_sum_rad += std::fabs(std::remainder(d, kTwoPi));
  const double dr = std::hypot(track.px, track.py) - std::hypot(truth.px, truth.py);
  const double dvx = track.vx - truth.vx, dvy = track.vy - truth.vy;
  s.sq_range_err_sum_m2 += dr * dr;
  s.sq_velocity_err_sum_m2ps2 += dvx * dvx + dvy * dvy;
}

/// Follows one target through the run: coverage, first coverage, switches.
struct TargetFollower {
  TargetScore score;
  std::uint32_t last_track = 0;
  bool has_last = false, covered_last_scan = false;

  /// reported_after: the scan after which scan k's estimate was handed out;
  /// realtime: that estimate is scan k's real-time one (handed out by its own
  /// step, no provisional estimate instead).
  void scan(std::uint32_t k, std::uint32_t reported_after, bool realtime, const scenario::TruthState& truth,
            const TrackOut* track, const ScanAssignment& now) {
    ++score.alive_scans;
    const bool settled = k >= score.birth_scan + kSettleScans;
    if (settled) ++score.settled_scans;
    if (track == nullptr) {
      covered_last_scan = false;
      return;
    }
    ++score.covered_scans;
    if (settled) ++score.settled_covered_scans;
    if (score.first_covered_scan < 0) score.first_covered_scan = static_cast<std::int32_t>(k);
    if (realtime && score.first_realtime_scan < 0) score.first_realtime_scan = static_cast<std::int32_t>(k);
    const auto reported = static_cast<std::int32_t>(reported_after);
    if (score.first_reported_scan < 0 || reported < score.first_reported_scan) score.first_reported_scan = reported;
    if (has_last && track->id != last_track) {
      ++score.id_switches;
      if (now.count(last_track) == 0) ++score.track_breaks;
    }
    if (has_last && !covered_last_scan) ++score.fragmentations;
    last_track = track->id;
    has_last = true;
    covered_last_scan = true;
    add_polar_error(truth.x, *track, score);
  }
};

}  // namespace

bool inside_clutter_region(const ClutterRegion& c, double px, double py) {
  Eigen::Matrix2d cov;
  cov << c.cov00, c.cov01, c.cov01, c.cov11;
  const model::Mahalanobis2<double> gate(cov);
  if (!gate.valid()) return false;
  const double d2 = c.polar ? gate.distance2(std::hypot(px, py) - c.mean0,
                                             model::wrap_angle(std::atan2(py, px) - c.mean1))
                            : gate.distance2(px - c.mean0, py - c.mean1);
  return d2 <= kClutterRegionChi2;
}

TrackScoringParams track_scoring_params(const scenario::ScenarioSpec& spec, double ospa_cutoff_m) {
  TrackScoringParams p;
  p.gate_m = ospa_cutoff_m;
  p.min_track_scans = spec.space == scenario::MeasurementSpace::kOthr ? 5U : 1U;
  if (spec.space == scenario::MeasurementSpace::kOthr) return p;
  const bool polar = spec.space != scenario::MeasurementSpace::kCartesian;
  for (const scenario::ClutterSpec& c : spec.clutter) {
    if (c.uniform) continue;
    for (std::uint32_t k = c.birth_scan; k <= c.death_scan; ++k) {
      const scenario::ClutterAtScan a = scenario::clutter_at_scan(spec, c, k);
      p.clutter_regions.push_back(
          polar ? ClutterRegion{k, true, a.mean_range_m, a.mean_azimuth_rad, a.cov_rr, a.cov_ra, a.cov_aa}
                : ClutterRegion{k, false, a.mean_x_m, a.mean_y_m, a.cov_xx, a.cov_xy, a.cov_yy});
    }
  }
  return p;
}

namespace {

/// False tracks of the run whose first confirmed position lies in a clutter
/// region of that scan.
std::uint32_t count_false_in_clutter(const std::vector<EstimateOut>& by_scan, std::size_t n,
                                     const std::map<std::uint32_t, bool>& valid,
                                     const std::vector<ClutterRegion>& regions) {
  std::set<std::uint32_t> judged;  // false track ids already judged at their first confirmed scan
  std::uint32_t count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    for (const TrackOut& t : by_scan[i].tracks) {
      const auto v = valid.find(t.id);
      if (!t.confirmed || v == valid.end() || v->second || !judged.insert(t.id).second) continue;
      for (const ClutterRegion& r : regions) {
        if (r.scan == i + 1 && inside_clutter_region(r, t.px, t.py)) {
          ++count;
          break;
        }
      }
    }
  }
  return count;
}

/// Lowers TargetScore::first_realtime_scan of every followed target to the
/// first scan of `provisional` on which a confirmed track that the final
/// estimates score as valid (classify_tracks, as coverage requires) is
/// assigned to it (match_scan among those tracks only); a track never handed
/// out final, or false, takes no part.
void mark_first_provisional(const std::vector<scenario::SimScan>& scans, const std::vector<EstimateOut>& provisional,
                         const TrackScoringParams& params, const std::map<std::uint32_t, bool>& valid,
                         ScoringSolver& solver, const std::map<std::uint32_t, std::size_t>& index,
                         std::vector<TargetFollower>& followers) {
  const double all = -std::numeric_limits<double>::infinity();
  const std::size_t n = std::min(scans.size(), provisional.size());
  ScanAssignment previous;
  EstimateOut scored;
  for (std::size_t i = 0; i < n; ++i) {
    scored.tracks.clear();
    for (const TrackOut& t : provisional[i].tracks) {
      const auto v = valid.find(t.id);
      if (v != valid.end() && v->second) scored.tracks.push_back(t);
    }
    previous = match_scan(scans[i], scored, params.gate_m, all, solver, params.keep_pairs ? &previous : nullptr);
    for (const auto& [track_id, target_id] : previous) {
      const auto f = index.find(target_id);
      if (target_id == kNoTarget || f == index.end()) continue;
      TargetScore& score = followers[f->second].score;
      const auto k = static_cast<std::int32_t>(i + 1);
      if (score.first_realtime_scan < 0 || k < score.first_realtime_scan) score.first_realtime_scan = k;
    }
  }
}

}  // namespace

RunTrackScore score_run(const std::vector<scenario::SimScan>& scans, const std::vector<EstimateOut>& by_scan,
                        const TrackScoringParams& params, const std::vector<EstimateOut>* provisional) {
  const std::size_t n = std::min(scans.size(), by_scan.size());
  auto solver = std::make_unique<ScoringSolver>();  // a 256 x 256 cost matrix: heap, not stack
  std::vector<ScanAssignment> per_scan(n);
  // -inf: every confirmed track, whatever existence its tracker reports.
  const double all = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    const ScanAssignment* previous = params.keep_pairs && i > 0 ? &per_scan[i - 1] : nullptr;
    per_scan[i] = match_scan(scans[i], by_scan[i], params.gate_m, all, *solver, previous);
  }

  RunTrackScore run;
  const std::map<std::uint32_t, bool> valid = classify_tracks(per_scan, params.min_track_scans, run);
  run.false_tracks_in_clutter = count_false_in_clutter(by_scan, n, valid, params.clutter_regions);
  std::map<std::uint32_t, std::size_t> index;  // target id -> followers slot
  std::vector<TargetFollower> followers;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t k = static_cast<std::uint32_t>(i + 1);
    for (const scenario::TruthState& truth : scans[i].truth) {
      if (index.count(truth.target_id) == 0) {
        index[truth.target_id] = followers.size();
        followers.emplace_back();
        followers.back().score.target_id = truth.target_id;
        followers.back().score.birth_scan = k;
      }
      const TrackOut* covering = nullptr;
      for (const TrackOut& t : by_scan[i].tracks) {
        const auto a = per_scan[i].find(t.id);
        const auto v = valid.find(t.id);
        if (t.confirmed && a != per_scan[i].end() && a->second == truth.target_id && v != valid.end() && v->second) {
          covering = &t;
        }
      }
      const std::uint32_t reported_after = by_scan[i].reported_after_scan > 0 ? by_scan[i].reported_after_scan : k;
      // Real time: a final estimate its own step handed out, unless that step's provisional one stands for it.
      const bool provisional_here = provisional != nullptr && i < provisional->size() &&
                                    (*provisional)[i].reported_after_scan == k;
      const bool realtime = by_scan[i].reported_after_scan == k && !provisional_here;
      followers[index[truth.target_id]].scan(k, reported_after, realtime, truth, covering, per_scan[i]);
    }
  }
  if (provisional != nullptr) mark_first_provisional(scans, *provisional, params, valid, *solver, index, followers);
  for (const TargetFollower& f : followers) run.targets.push_back(f.score);
  const AmotaScore amota = run_amota(scans, by_scan, AmotaParams{params.gate_m, kAmotaRecallPoints}, *solver);
  run.amota = amota.normalised;
  run.amota_unscaled = amota.unscaled;
  return run;
}

void TrackScoreTotals::add(const RunTrackScore& run) {
  ++runs;
  valid_tracks += run.valid_tracks;
  false_tracks += run.false_tracks;
  false_tracks_in_clutter += run.false_tracks_in_clutter;
  targets_with_valid_track += run.targets_with_valid_track;
  for (const TargetScore& t : run.targets) {
    ++targets;
    alive_scans += t.alive_scans;
    covered_scans += t.covered_scans;
    TargetDelay& delay = delay_by_target[t.target_id];
    if (t.first_covered_scan >= 0) {
      const std::uint64_t latency = static_cast<std::uint64_t>(t.first_covered_scan) - t.birth_scan;
      const std::uint64_t reported = static_cast<std::uint64_t>(t.first_reported_scan) - t.birth_scan;
      ++targets_tracked;
      latency_scans += latency;
      report_latency_scans += reported;
      ++delay.tracked;
      delay.latency_scans += latency;
      delay.report_latency_scans += reported;
    } else {
      ++delay.never_tracked;
    }
    if (t.first_realtime_scan >= 0) {
      const std::uint64_t realtime = static_cast<std::uint64_t>(t.first_realtime_scan) - t.birth_scan;
      ++realtime_tracked;
      realtime_latency_scans += realtime;
      ++delay.realtime_tracked;
      delay.realtime_latency_scans += realtime;
    }
    id_switches += t.id_switches;
    fragmentations += t.fragmentations;
    track_breaks += t.track_breaks;
    abs_range_err_sum_m += t.abs_range_err_sum_m;
    abs_bearing_err_sum_rad += t.abs_bearing_err_sum_rad;
    sq_range_err_sum_m2 += t.sq_range_err_sum_m2;
    sq_velocity_err_sum_m2ps2 += t.sq_velocity_err_sum_m2ps2;
    if (t.settled_scans == 0) continue;
    settled_scans += t.settled_scans;
    settled_covered_scans += t.settled_covered_scans;
    auto& by_id = settled_by_target[t.target_id];
    by_id.first += t.settled_covered_scans;
    by_id.second += t.settled_scans;
    const double f = static_cast<double>(t.settled_covered_scans) / static_cast<double>(t.settled_scans);
    if (f < min_settled_coverage) min_settled_coverage = f;
  }
  amota_per_run.push_back(run.amota);
  amota_unscaled_sum += run.amota_unscaled;
}

namespace {
double ratio(double num, std::uint64_t den) { return den > 0 ? num / static_cast<double>(den) : 0.0; }
}  // namespace

double TrackScoreTotals::nvt() const { return ratio(static_cast<double>(targets_with_valid_track), runs); }
double TrackScoreTotals::nft() const { return ratio(static_cast<double>(false_tracks), runs); }
double TrackScoreTotals::nft_in_clutter() const {
  return ratio(static_cast<double>(false_tracks_in_clutter), runs);
}
double TrackScoreTotals::tpd() const { return ratio(static_cast<double>(covered_scans), alive_scans); }
double TrackScoreTotals::ttl_scans() const { return ratio(static_cast<double>(latency_scans), targets_tracked); }
double TrackScoreTotals::report_delay_scans() const {
  return ratio(static_cast<double>(report_latency_scans), targets_tracked);
}
double TrackScoreTotals::realtime_delay_scans() const {
  return ratio(static_cast<double>(realtime_latency_scans), realtime_tracked);
}
double TrackScoreTotals::aee_range_m() const { return ratio(abs_range_err_sum_m, covered_scans); }
double TrackScoreTotals::aee_bearing_rad() const { return ratio(abs_bearing_err_sum_rad, covered_scans); }
double TrackScoreTotals::per_target(std::uint64_t count) const { return ratio(static_cast<double>(count), targets); }
double TrackScoreTotals::rmse_range_m() const { return std::sqrt(ratio(sq_range_err_sum_m2, covered_scans)); }
double TrackScoreTotals::rmse_velocity_mps() const { return std::sqrt(ratio(sq_velocity_err_sum_m2ps2, covered_scans)); }
double TrackScoreTotals::amota() const {
  double sum = 0.0;  // in run order, as the runs were added
  for (const double a : amota_per_run) sum += a;
  return ratio(sum, runs);
}
double TrackScoreTotals::amota_unscaled() const { return ratio(amota_unscaled_sum, runs); }
double TrackScoreTotals::settled_coverage() const {
  return ratio(static_cast<double>(settled_covered_scans), settled_scans);
}
double TrackScoreTotals::ttl_scans_of(std::uint32_t target_id) const {
  const auto it = delay_by_target.find(target_id);
  return it == delay_by_target.end() ? 0.0 : ratio(static_cast<double>(it->second.latency_scans), it->second.tracked);
}
double TrackScoreTotals::report_delay_scans_of(std::uint32_t target_id) const {
  const auto it = delay_by_target.find(target_id);
  return it == delay_by_target.end() ? 0.0
                                     : ratio(static_cast<double>(it->second.report_latency_scans), it->second.tracked);
}
double TrackScoreTotals::realtime_delay_scans_of(std::uint32_t target_id) const {
  const auto it = delay_by_target.find(target_id);
  return it == delay_by_target.end() ? 0.0
                                     : ratio(static_cast<double>(it->second.realtime_latency_scans),
                                             it->second.realtime_tracked);
}
double TrackScoreTotals::settled_coverage_of(std::uint32_t target_id) const {
  const auto it = settled_by_target.find(target_id);
  return it == settled_by_target.end() ? 0.0 : ratio(static_cast<double>(it->second.first), it->second.second);
}

}  // namespace mptrack::sim
