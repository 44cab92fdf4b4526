// Track-level scores of one run: which confirmed track follows which target
// over the whole run, and what that says about the tracker, the metrics
// tracking papers report beyond OSPA (docs/algorithms/metrics.md §Track
// scores): valid and false tracks (NVT, NFT), track probability of detection
// (TPD), tentative track latency (TTL, the confirmation delay after birth),
// errors in ground range and bearing (AEE), identity switches, fragmentations
// and track breaks. seed 002 Sec. IV-B reports NVT, TPD, NFT, TTL and AEE
// (definitions of Gorji et al., FUSION 2011); seed 003 reports IDS and Frag.
#pragma once

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "mptrack/metrics/assignment.h"

#include "mptrack/scenario/generator.h"
#include "tracker_adapter.h"

namespace mptrack::sim {

/// Where a Gaussian clutter component of the scenario is on one scan, for
/// counting the false tracks that start inside it (docs/algorithms/metrics.md
/// §Track scores). Polar: [range m, azimuth rad]; Cartesian: [x m, y m].
struct ClutterRegion {
  std::uint32_t scan = 0;  ///< 1-based
  bool polar = true;
  double mean0 = 0.0, mean1 = 0.0;
  double cov00 = 0.0, cov01 = 0.0, cov11 = 0.0;
};

/// A false track is "in clutter" if its first confirmed position lies within
/// this squared Mahalanobis distance of a component: the 95 % region of a
/// 2-D Gaussian.
inline constexpr double kClutterRegionChi2 = 5.991;

/// Is (px, py) [m], on the region's scan, inside its kClutterRegionChi2 ellipse?
bool inside_clutter_region(const ClutterRegion& c, double px, double py);

struct TrackScoringParams {
  double gate_m = 0.0;                ///< a track scores a target only within this distance [m]
  std::uint32_t min_track_scans = 1;  ///< shorter confirmed tracks are ignored (seed 002: 5)
  /// CLEAR MOT's matching: a (track, target) pair of the previous scan still
  /// within the gate is kept before the optimal assignment of the rest
  /// (false: every scan assigned afresh, the rule before session 7).
  bool keep_pairs = true;
  /// The scenario's Gaussian clutter components on every scan they exist
  /// (track_scoring_params); empty: no false track counts as in clutter.
  std::vector<ClutterRegion> clutter_regions;
};

/// The scenario's scoring: gate = the OSPA cut-off c of the run; tracks of
/// OTHR scenarios count from 5 confirmed scans (seed 002 Sec. IV-B), others
/// from 1; the regions of its Gaussian clutter components (measurement-level
/// scenarios; OTHR ones have none).
TrackScoringParams track_scoring_params(const scenario::ScenarioSpec& spec, double ospa_cutoff_m);

/// Scans after a target's birth that the settled coverage does not judge
/// (the confirmation delay the issue-18 criterion allows): coverage from
/// birth + 5 on (docs/algorithms/metrics.md §Track scores).
inline constexpr std::uint32_t kSettleScans = 5;

/// One target over one run.
struct TargetScore {
  std::uint32_t target_id = 0;
  std::uint32_t birth_scan = 0;      ///< first scan it is alive (1-based)
  std::uint32_t alive_scans = 0;
  std::uint32_t covered_scans = 0;   ///< scans a scored (non-false) track was assigned to it
  std::int32_t first_covered_scan = -1;  ///< -1: never tracked
  /// The scan after which the tracker first handed out a covering track
  /// (EstimateOut::reported_after_scan of the covered scans, earliest); -1: never.
  std::int32_t first_reported_scan = -1;
  /// The first scan k whose own step() handed out, for scan k, a confirmed
  /// track assigned to it (realtime_estimate in run/run_record.h: a filter's
  /// final estimate, stamped reported_after_scan == k, or a smoother's
  /// provisional one); -1: never.
  std::int32_t first_realtime_scan = -1;
  std::uint32_t id_switches = 0;     ///< its assigned track id changed (from the last one it had)
  std::uint32_t fragmentations = 0;  ///< coverage resumed after an interruption
  std::uint32_t track_breaks = 0;    ///< id changed and the previous track no longer existed
  std::uint32_t settled_scans = 0;   ///< alive scans from birth_scan + kSettleScans on
  std::uint32_t settled_covered_scans = 0;  ///< of those, the scans covered_scans counts
  double abs_range_err_sum_m = 0.0;      ///< sum over covered scans of |ground range error| [m]
  double abs_bearing_err_sum_rad = 0.0;  ///< sum over covered scans of |bearing error| [rad]
  double sq_range_err_sum_m2 = 0.0;      ///< sum over covered scans of (ground range error)^2 [m^2]
  double sq_velocity_err_sum_m2ps2 = 0.0;  ///< sum over covered scans of |velocity error|^2 [m^2/s^2]
};

/// Everything scored in one run.
struct RunTrackScore {
  std::vector<TargetScore> targets;   ///< in order of first appearance
  std::uint32_t scored_tracks = 0;    ///< confirmed for at least min_track_scans scans
  std::uint32_t valid_tracks = 0;     ///< scored tracks assigned to one target for at least half their scans
  std::uint32_t false_tracks = 0;     ///< scored tracks that are not valid (clutter, ghosts)
  std::uint32_t false_tracks_in_clutter = 0;  ///< of those, the ones first confirmed inside a clutter region
  std::uint32_t targets_with_valid_track = 0;  ///< NVT of the run: distinct targets some valid track follows
  double amota = 0.0;                 ///< AMOTA of the run, recall-normalised (eval/amota.h)
  double amota_unscaled = 0.0;        ///< the same, unscaled (AmotaScore::unscaled)
};

/// track id -> target id (kNoTarget: unmatched) for one scan's tracks.
using ScanAssignment = std::map<std::uint32_t, std::uint32_t>;
inline constexpr std::uint32_t kNoTarget = 0xffffffffU;
inline constexpr std::size_t kMaxScored = 256;
using ScoringSolver = AssignmentSolver<double, kMaxScored>;

/// Matches the confirmed tracks of `est` with existence >= min_existence to
/// the truths of `scan`: optimal assignment of cost min(Euclidean distance,
/// gate); pairs at or beyond the gate are dropped (OSPA's cut-off trick,
/// which never trades a within-gate pair for a cheaper out-of-gate one).
/// With `previous` (the last scan's result), each of its pairs whose track
/// and target are both here and closer than the gate is kept first and only
/// the rest are assigned (CLEAR MOT). Throws std::runtime_error if a scan
/// has more than kMaxScored tracks or truths.
ScanAssignment match_scan(const scenario::SimScan& scan, const EstimateOut& est, double gate_m,
                          double min_existence, ScoringSolver& solver, const ScanAssignment* previous = nullptr);

/// Scores a run: scans[k-1] holds the truth of scan k, by_scan[k-1] the
/// tracker's estimate (only confirmed tracks count). Each scan matches
/// confirmed tracks to targets by an optimal assignment of Euclidean
/// distance gated at params.gate_m, keeping the previous scan's pairs that
/// are still within the gate when params.keep_pairs. Throws std::runtime_error if a scan has
/// more than 256 tracks or targets.
/// TargetScore::first_realtime_scan comes from the final estimates that their
/// own step handed out (reported_after_scan == their scan) and from
/// provisional (optional, index scan-1: the provisional estimates steps
/// handed out for their own scan, RunRecord::provisional_by_scan; a stamped
/// entry stands for its scan's final estimate).
RunTrackScore score_run(const std::vector<scenario::SimScan>& scans, const std::vector<EstimateOut>& by_scan,
                        const TrackScoringParams& params, const std::vector<EstimateOut>* provisional = nullptr);

/// Totals over runs; the means scripts read from summary.json.
struct TrackScoreTotals {
  std::uint32_t runs = 0;
  std::uint64_t targets = 0, targets_tracked = 0;  ///< (run, target) pairs, and those ever covered
  std::uint64_t alive_scans = 0, covered_scans = 0;
  std::uint64_t latency_scans = 0;                 ///< sum of first_covered - birth over tracked targets
  std::uint64_t report_latency_scans = 0;          ///< sum of first_reported - birth over tracked targets
  std::uint64_t realtime_latency_scans = 0;        ///< sum of first_realtime - birth over realtime_tracked
  std::uint64_t realtime_tracked = 0;              ///< (run, target) pairs with a first_realtime_scan
  std::uint64_t valid_tracks = 0, false_tracks = 0, targets_with_valid_track = 0;
  std::uint64_t false_tracks_in_clutter = 0;
  std::uint64_t id_switches = 0, fragmentations = 0, track_breaks = 0;
  double abs_range_err_sum_m = 0.0, abs_bearing_err_sum_rad = 0.0;
  double sq_range_err_sum_m2 = 0.0, sq_velocity_err_sum_m2ps2 = 0.0;
  double amota_unscaled_sum = 0.0;                 ///< sum of the runs' unscaled AMOTA
  std::vector<double> amota_per_run;               ///< each run's AMOTA, in run order (amota(), paired comparisons)
  /// Settled coverage (kSettleScans): pooled scans, the worst (run, target)
  /// fraction, and per target id the pooled scans over runs.
  std::uint64_t settled_scans = 0, settled_covered_scans = 0;
  double min_settled_coverage = 1.0;  ///< over (run, target) pairs alive past the settle scans
  std::map<std::uint32_t, std::pair<std::uint64_t, std::uint64_t>> settled_by_target;  ///< id -> (covered, scans)
  /// Per target id over runs: the confirmation delay of the runs it was
  /// tracked in, and the runs it never was (issue 18: a birth inside clutter).
  struct TargetDelay {
    std::uint64_t latency_scans = 0, report_latency_scans = 0, tracked = 0, never_tracked = 0;
    std::uint64_t realtime_latency_scans = 0, realtime_tracked = 0;
  };
  std::map<std::uint32_t, TargetDelay> delay_by_target;

  void add(const RunTrackScore& run);
  double nvt() const;                ///< targets with a valid track, mean per run
  double nft() const;                ///< false tracks, mean per run
  double nft_in_clutter() const;     ///< false tracks first confirmed inside a Gaussian clutter component, per run
  double tpd() const;                ///< covered / alive target-scans
  double ttl_scans() const;          ///< mean scans from birth to first coverage (tracked targets)
  /// Mean scans from birth to the scan after which the first covering track
  /// was handed out: ttl_scans() plus the output lag (tracked targets).
  double report_delay_scans() const;
  /// Mean scans from birth to the first scan whose own step() handed out a
  /// confirmed track on the target (first_realtime_scan; targets it happened for):
  /// ttl_scans() for a filter, a smoother's delay through its provisional output.
  double realtime_delay_scans() const;
  double aee_range_m() const;        ///< mean |ground range error| over covered target-scans [m]
  double aee_bearing_rad() const;    ///< mean |bearing error| over covered target-scans [rad]
  double per_target(std::uint64_t count) const;  ///< count / targets (0 if none)
  double rmse_range_m() const;       ///< RMS ground range error over covered target-scans [m]
  double rmse_velocity_mps() const;  ///< RMS of |velocity error| over covered target-scans [m/s]
  double amota() const;              ///< AMOTA, mean over runs (seed 003 Sec. IV-A)
  double amota_unscaled() const;     ///< unscaled AMOTA, mean over runs
  double settled_coverage() const;   ///< settled covered / settled alive target-scans (pooled)
  double settled_coverage_of(std::uint32_t target_id) const;  ///< the same for one target id over runs
  double ttl_scans_of(std::uint32_t target_id) const;  ///< ttl_scans() of one target id over runs (0 if never tracked)
  double report_delay_scans_of(std::uint32_t target_id) const;  ///< the same for report_delay_scans()
  double realtime_delay_scans_of(std::uint32_t target_id) const;  ///< the same for realtime_delay_scans()
};

}  // namespace mptrack::sim
