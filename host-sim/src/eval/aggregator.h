// The one aggregator of the harness: a tracker's run records and per-scan
// metrics over every Monte Carlo run -> Summary (means per evaluation scan,
// step() latency percentiles, step statuses, TrackerCounters sums, the
// checksum of every measurement it was given). summary.json, the compare
// table and Table V all read a Summary.
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "eval/scan_evaluator.h"
#include "eval/track_scoring.h"
#include "mptrack/scenario/generator.h"
#include "mptrack/status.h"
#include "mptrack/track_report.h"
#include "run/run_record.h"

namespace mptrack::sim {

struct LatencyStats {
  double p50_us = 0.0, p99_us = 0.0, max_us = 0.0, mean_us = 0.0;
  std::size_t count = 0;        ///< step() calls measured
};

/// Percentiles by the nearest-rank method on a copy of `samples_us`.
LatencyStats latency_stats(std::vector<double> samples_us);

/// Adds every field of `run` to `sum`.
void add_counters(TrackerCounters& sum, const TrackerCounters& run);

/// FNV-1a over the bit patterns of (range, azimuth, amplitude) of every
/// measurement of `scan`, chained from `h`.
std::uint64_t measurement_checksum(const scenario::SimScan& scan, std::uint64_t h);
inline constexpr std::uint64_t kChecksumSeed = 0xcbf29ce484222325ULL;

/// What a Summary describes; the aggregator fills in the rest.
struct SummaryHeader {
  std::string scenario, tracker;
  std::uint32_t runs = 0, scans = 0;
  std::uint64_t seed = 0;
  double clutter_scale = 1.0;
  std::uint32_t eval_first_scan = 0, eval_last_scan = 0;
  TrackScoringParams scoring;   ///< how track_scores matches tracks to targets
};

struct Summary : SummaryHeader {
  double mean_ospa = 0.0;       ///< over runs x evaluation scans [m]
  double mean_gospa = 0.0;      ///< [m]
  double mean_ospa_mahalanobis = 0.0;  ///< MOSPA with the Mahalanobis base distance (seed 003) [-]
  /// OSPA of the real-time stream (realtime_estimate, run/run_record.h: each
  /// step's estimate of its own scan) over the evaluation scans that have one [m];
  /// mean_ospa for a filter, the provisional output's for a smoother.
  double mean_realtime_ospa = 0.0;
  double realtime_scan_fraction = 0.0;  ///< evaluation scans with a real-time estimate / all of them
  double gospa_localisation = 0.0;  ///< mean per evaluation scan [m^p]
  double gospa_missed = 0.0;        ///< mean per evaluation scan [m^p] = c^p/2 x missed
  double gospa_false = 0.0;         ///< mean per evaluation scan [m^p] = c^p/2 x false
  double missed_per_scan = 0.0;     ///< GOSPA unassigned truths per evaluation scan
  double false_per_scan = 0.0;      ///< GOSPA unassigned tracks per evaluation scan
  double cardinality_error = 0.0;   ///< mean |#confirmed - #truths| per evaluation scan
  double car = 0.0;             ///< car_correct / car_total (0 if no detected truth)
  std::uint64_t car_correct = 0, car_total = 0;
  double car_identity = 0.0;    ///< car_id_correct / car_total (identity CAR, scan_evaluator.cpp)
  std::uint64_t car_id_correct = 0;
  double nft = 0.0;             ///< mean false confirmed tracks per evaluation scan
  double mean_confirmed_tracks = 0.0;   ///< per evaluation scan
  double mean_truths = 0.0;             ///< per evaluation scan
  double tracks_found_per_run = 0.0;    ///< distinct confirmed track ids per run (mean)
  double mean_measurements = 0.0;       ///< per scan given to the tracker
  std::uint64_t eval_scan_count = 0;    ///< runs x evaluation scans
  LatencyStats latency;                 ///< step() of every scan given to the tracker
  std::vector<double> ospa_per_scan;    ///< mean over runs, index scan-1 [m]
  /// Mean OSPA over each run's evaluation scans, in run order [m]: the
  /// per-run values paired_difference() (eval/paired.h) compares across trackers.
  std::vector<double> ospa_per_run;
  /// MOSPA (Mahalanobis base distance) over each run's evaluation scans, in
  /// run order [-]: seed 003's paired comparisons (sea_report.cpp).
  std::vector<double> ospa_mahalanobis_per_run;
  std::vector<double> confirmed_mean_per_scan;  ///< confirmed tracks, mean over runs, index scan-1
  std::vector<double> confirmed_std_per_scan;   ///< ... their standard deviation over runs (population)
  std::vector<double> truths_per_scan;          ///< targets alive, mean over runs, index scan-1
  /// Per (run, target) RMSE of its track's position over the evaluation
  /// scans where the OSPA assignment matched it within c, sorted ascending:
  /// the empirical CDF of seed 004 Fig. 5 [m].
  std::vector<double> object_rmse_m;
  std::uint64_t objects_never_matched = 0;  ///< (run, target) pairs alive but never matched within c
  TrackScoreTotals track_scores;        ///< NVT, TPD, NFT per run, TTL, AEE, IDS, Frag (track_scoring.h)
  std::uint64_t step_errors = 0;        ///< step()/flush() calls returning an error (not kOk, kPartial, kCapacityExceeded)
  std::uint64_t steps_partial = 0;      ///< kPartial: some measurements rejected (see counters)
  std::uint64_t steps_capacity = 0;     ///< kCapacityExceeded: an internal cap was hit (see counters)
  std::uint64_t steps_truncating = 0;   ///< step()/flush() calls whose mixture_truncated grew (RunRecord)
  std::map<std::string, std::uint64_t> step_status;  ///< every step()/flush() status by name
  TrackerCounters counters;             ///< summed over runs
  std::uint64_t measurement_checksum = kChecksumSeed;  ///< of every measurement the tracker was given, in order

  /// The q-quantile of object_rmse_m by nearest rank (0 if empty) [m].
  double object_rmse_quantile(double q) const;
  /// Tallies one step()/flush() status into step_status and the three counts.
  void count_status(Status st);
  /// step()/flush() calls that returned anything but kOk.
  std::uint64_t steps_not_ok() const { return step_errors + steps_partial + steps_capacity; }
};

class Aggregator {
 public:
  explicit Aggregator(const SummaryHeader& header);
  /// Adds one run: its scans (truth and measurements), the tracker's record
  /// and the evaluator's metrics of every scan (index scan-1).
  /// provisional: the evaluator's metrics of record.provisional_by_scan
  /// (index scan-1), or nullptr if the tracker handed out none.
  void add_run(const std::vector<scenario::SimScan>& scans, const RunRecord& record,
               const std::vector<ScanMetrics>& metrics, const std::vector<ScanMetrics>* provisional = nullptr);
  /// Means over everything added so far.
  Summary summary() const;

 private:
  void add_eval_scan(const ScanMetrics& m);
  void add_realtime(const RunRecord& record, const std::vector<ScanMetrics>& metrics,
                    const std::vector<ScanMetrics>* provisional);
  void add_object_errors(const std::vector<scenario::SimScan>& scans, const std::vector<ScanMetrics>& metrics);

  Summary sum_;  ///< header, tallies and counts; means are formed in summary()
  double ospa_ = 0.0, gospa_ = 0.0, loc_ = 0.0, missed_pow_ = 0.0, false_pow_ = 0.0;
  double missed_ = 0.0, false_n_ = 0.0, card_ = 0.0, nft_ = 0.0, confirmed_ = 0.0, truths_ = 0.0;
  double measurements_ = 0.0, tracks_found_ = 0.0;
  double ospa_mahalanobis_ = 0.0;
  double realtime_ospa_ = 0.0;           ///< sum over evaluation scans with a real-time estimate
  std::uint64_t realtime_scans_ = 0;     ///< those scans
  std::uint64_t delivered_ = 0;
  std::vector<double> latency_us_;
  std::vector<double> confirmed_sq_;  ///< sum over runs of confirmed^2, index scan-1
};

}  // namespace mptrack::sim
