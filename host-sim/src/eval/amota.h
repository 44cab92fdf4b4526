// AMOTA of one run (docs/algorithms/metrics.md §AMOTA): recall-normalised MOTA
// averaged over recall thresholds, the "AMOT" seed 003 Sec. IV-A reports after
// Weng et al. (IROS 2020, its ref. [54]) and nuScenes. The tracker's confidence
// is the existence it reports for a confirmed track; raising a threshold on it
// trades recall for false tracks, and AMOTA scores the whole trade-off, not
// one operating point.
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
  /// Recall-normalised MOTA (Weng et al.'s sMOTA, nuScenes' MOTAR, without
  /// their clip at 0): 1 - (IDS + FP + FN - (1 - r') num_gt) / (r' num_gt)
  /// at the achieved recall r' = TP / num_gt, which is 1 - (IDS + FP) / TP.
  /// 0 without true positives.
  double motar() const;
  double recall() const;     ///< TP / num_gt; 0 without truths
};

/// AMOTA of one run in both forms.
struct AmotaScore {
  /// (1/L) sum over r of MOTAR_r: 1 for a perfect tracker, negative when
  /// false tracks and switches outnumber true positives. The paper's AMOT.
  double normalised = 0.0;
  /// (1/L) sum over r of MOTA_r (Weng et al.'s unscaled AMOTA). MOTA_r <= r
  /// when the threshold keeps exactly r num_gt true positives, so this is at
  /// most (L + 1) / 2L (0.51) for trackers whose confidences differ, and up
  /// to 1 for one whose confidences tie: kept for comparison with sessions
  /// before 2026-12-06 only.
  double unscaled = 0.0;
};

/// Matches every scan's confirmed tracks with existence >= min_existence
/// (match_scan) and counts: TP matched pairs, FP unmatched tracks, FN
/// unmatched truths, IDS scans where a target's matched track id differs
/// from the last one it was matched to.
MotCounts mot_counts(const std::vector<scenario::SimScan>& scans, const std::vector<EstimateOut>& by_scan,
                     double gate_m, double min_existence, ScoringSolver& solver);

/// AMOTA over r = 1/L..1 of MOTAR_r (and of MOTA_r, unscaled), each counted
/// at the highest threshold that keeps ceil(r num_gt) true positives of the
/// all-tracks matching; a recall the tracker never reaches contributes 0
/// (nuScenes' convention). Not clipped at 0, so it can be negative as in
/// seed 003 Tables II-III. 0 without truths.
AmotaScore run_amota(const std::vector<scenario::SimScan>& scans, const std::vector<EstimateOut>& by_scan,
                 const AmotaParams& params, ScoringSolver& solver);

}  // namespace mptrack::sim
