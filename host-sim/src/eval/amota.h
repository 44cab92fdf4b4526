// AMOTA of one run (docs/algorithms/metrics.md §AMOTA): MOTA averaged over
// recall thresholds, the "AMOT" seed 003 Sec. IV-A reports after Weng et al.
// (IROS 2020, its ref. [54]). The tracker's confidence is the existence it
// reports for a confirmed track; raising a threshold on it trades recall for
// false tracks, and AMOTA scores the whole trade-off, not one operating point.
#pragma once

#include <cstdint>
#include <vector>

#include "eval/track_scoring.h"

namespace mptrack::sim {

/// Recall thresholds r = 1/L, 2/L, ..., 1 (Weng et al. and nuScenes: L = 40).
inline constexpr std::uint32_t kAmotaRecallPoints = 40;

struct AmotaParams {
  double gate_m = 0.0;                          ///< a track matches a truth only closer than this [m]
  std::uint32_t recall_points = kAmotaRecallPoints;  ///< L
};

/// CLEAR MOT counts of one run at one confidence threshold.
struct MotCounts {
  std::uint64_t truths = 0;  ///< num_gt: target-scans alive
  std::uint64_t tp = 0, fp = 0, fn = 0, ids = 0;
  /// MOTA = 1 - (FP + FN + IDS) / num_gt (CLEAR MOT); 0 without truths.
  double mota() const;
  double recall() const;     ///< TP / num_gt; 0 without truths
};

/// Matches every scan's confirmed tracks with existence >= min_existence
/// (match_scan) and counts: TP matched pairs, FP unmatched tracks, FN
/// unmatched truths, IDS scans where a target's matched track id differs
/// from the last one it was matched to.
MotCounts mot_counts(const std::vector<scenario::SimScan>& scans, const std::vector<EstimateOut>& by_scan,
                     double gate_m, double min_existence, ScoringSolver& solver);

/// AMOTA = (1/L) sum over r of MOTA_r (Weng et al.'s AMOTA, unscaled, so it
/// can be negative as in seed 003 Tables II-III). MOTA_r is MOTA at the
/// highest threshold that keeps ceil(r num_gt) true positives of the
/// all-tracks matching; a recall the tracker never reaches contributes 0
/// (nuScenes' convention). 0 without truths.
double run_amota(const std::vector<scenario::SimScan>& scans, const std::vector<EstimateOut>& by_scan,
                 const AmotaParams& params, ScoringSolver& solver);

}  // namespace mptrack::sim
