// Per-scan evaluation of one tracker output against truth, the one evaluator
// of every subcommand: OSPA and GOSPA with its components (seed 000: p = 2,
// c = 631 m; seed 001: p = 1, c = 300 m; seed 004: c = 10 m) on confirmed-track
// positions, NFT and CAR from the OSPA assignment, and the identity CAR
// (scan_evaluator.cpp). Aggregation over runs and scans is in aggregator.h.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include "eval/mahalanobis_ospa.h"
#include "mptrack/metrics/gospa.h"
#include "mptrack/metrics/ospa.h"
#include "mptrack/scenario/generator.h"
#include "tracker_adapter.h"

namespace mptrack::sim {

constexpr double kOspaCutoff_m = 631.0;  ///< seed 000 OSPA/GOSPA cutoff c [m]
constexpr double kOspaOrder = 2.0;       ///< seed 000 OSPA/GOSPA order p
constexpr std::size_t kMaxEvalPoints = 256;

/// A truth the OSPA assignment matched to a confirmed track within c.
struct ObjectError {
  std::uint32_t target_id = 0;
  double distance_m = 0.0;         ///< position error of its track [m]
};

struct ScanMetrics {
  double ospa = 0.0;               ///< [m]
  double gospa = 0.0;              ///< [m]
  double gospa_localisation = 0.0; ///< sum of d^p over matched pairs [m^p]
  double gospa_missed = 0.0;       ///< c^p/2 per missed truth [m^p]
  double gospa_false = 0.0;        ///< c^p/2 per false track [m^p]
  std::uint32_t gospa_num_missed = 0;  ///< truths without a track within c (GOSPA assignment)
  std::uint32_t gospa_num_false = 0;   ///< tracks without a truth within c (GOSPA assignment)
  std::uint32_t truths = 0;        ///< targets alive
  std::uint32_t confirmed = 0;     ///< confirmed tracks reported
  std::uint32_t false_tracks = 0;  ///< confirmed tracks not assigned to a truth within c (NFT)
  std::uint32_t car_total = 0;     ///< truths with a measurement in this scan
  std::uint32_t car_correct = 0;   ///< ... whose matched track picked exactly that measurement
  std::uint32_t car_id_correct = 0;  ///< ... picked by a track labelled with that target (identity CAR)
  std::vector<ObjectError> matched;  ///< truths within c of their OSPA-assigned track (per-object RMSE)
  double ospa_mahalanobis = 0.0;   ///< OSPA with the Mahalanobis base distance (mahalanobis_ospa.h) [-]
};

class ScanEvaluator {
 public:
  /// cutoff_m: OSPA/GOSPA c [m]; order: p. Throws std::runtime_error if the
  /// metric rejects them (p >= 1, c > 0).
  /// mahalanobis: the base covariance, c and p of ScanMetrics::ospa_mahalanobis.
  explicit ScanEvaluator(double cutoff_m = kOspaCutoff_m, double order = kOspaOrder,
                         const MahalanobisOspaParams& mahalanobis = MahalanobisOspaParams{});
  /// Forgets the track labels of the identity CAR; call before each run.
  void begin_run() { labels_.clear(); }
  /// Evaluates the confirmed tracks of `est` against the truth of `scan`.
  /// Scans of one run must come in order (the identity CAR labels tracks).
  /// Throws std::runtime_error if more than kMaxEvalPoints points are given.
  ScanMetrics evaluate(const scenario::SimScan& scan, const EstimateOut& est);
  /// begin_run(), then every scan of a run: result[i] for scans[i], by_scan[i].
  std::vector<ScanMetrics> evaluate_run(const std::vector<scenario::SimScan>& scans,
                                        const std::vector<EstimateOut>& by_scan);

 private:
  void score_car(const scenario::SimScan& scan, const std::vector<const TrackOut*>& tracks, ScanMetrics& m);

  // The metric objects hold a kMaxEvalPoints^2 cost matrix: keep them on the heap.
  std::unique_ptr<OspaMetric<double, kMaxEvalPoints>> ospa_;
  std::unique_ptr<GospaMetric<double, kMaxEvalPoints>> gospa_;
  std::unique_ptr<MahalanobisOspa> mahalanobis_;
  std::map<std::uint32_t, std::uint32_t> labels_;  ///< track id -> target id (identity CAR)
};

}  // namespace mptrack::sim
