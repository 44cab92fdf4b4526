// Per-scan evaluation of one tracker output against truth (seed 000 spec 5.1):
// OSPA and GOSPA (p = 2, c = 631 m) on confirmed-track positions, CAR and NFT
// from the OSPA assignment, and the identity CAR (metrics.cpp). Aggregation
// over runs and scans is in runner.h.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>

#include "mptrack/metrics/gospa.h"
#include "mptrack/metrics/ospa.h"
#include "mptrack/scenario/generator.h"
#include "tracker_adapter.h"

namespace mptrack::sim {

constexpr double kOspaCutoff_m = 631.0;  ///< spec 5.1
constexpr double kOspaOrder = 2.0;       ///< spec 5.1
constexpr std::size_t kMaxEvalPoints = 256;

struct ScanMetrics {
  double ospa = 0.0;               ///< [m]
  double gospa = 0.0;              ///< [m]
  std::uint32_t truths = 0;        ///< targets alive
  std::uint32_t confirmed = 0;     ///< confirmed tracks reported
  std::uint32_t false_tracks = 0;  ///< confirmed tracks not assigned to a truth within c (NFT)
  std::uint32_t car_total = 0;     ///< truths with a measurement in this scan
  std::uint32_t car_correct = 0;   ///< ... whose matched track picked exactly that measurement
  std::uint32_t car_id_correct = 0;  ///< ... picked by a track labelled with that target (identity CAR)
};

class ScanEvaluator {
 public:
  /// cutoff_m: OSPA/GOSPA c [m] (seed 000: 631 m; seed 004: 10 m).
  explicit ScanEvaluator(double cutoff_m = kOspaCutoff_m);
  /// Forgets the track labels of the identity CAR; call before each run.
  void begin_run() { labels_.clear(); }
  /// Evaluates the confirmed tracks of `est` against the truth of `scan`.
  /// Scans of one run must come in order (the identity CAR labels tracks).
  /// Throws std::runtime_error if more than kMaxEvalPoints points are given.
  ScanMetrics evaluate(const scenario::SimScan& scan, const EstimateOut& est);

 private:
  // The metric objects hold a kMaxEvalPoints^2 cost matrix: keep them on the heap.
  std::unique_ptr<OspaMetric<double, kMaxEvalPoints>> ospa_;
  std::unique_ptr<GospaMetric<double, kMaxEvalPoints>> gospa_;
  std::map<std::uint32_t, std::uint32_t> labels_;  ///< track id -> target id (identity CAR)
};

}  // namespace mptrack::sim
