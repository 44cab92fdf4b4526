// What one tracker produced on one Monte Carlo run of a scan source: the
// output of the run loop (run_loop.h), the input of the evaluator and the
// aggregator.
#pragma once

#include <cstdint>
#include <vector>

#include "mptrack/status.h"
#include "mptrack/track_report.h"
#include "tracker_adapter.h"

namespace mptrack::sim {

struct RunRecord {
  std::uint32_t run = 0;                 ///< 0-based run number
  std::vector<EstimateOut> by_scan;      ///< index scan-1; an empty estimate where nothing was finalised
  /// index scan-1: the provisional estimate that the step() which consumed
  /// scan k handed out for it (TrackerAdapter::provisional; reported_after_scan
  /// = k), unstamped (0) where it handed out none. With by_scan it makes the
  /// real-time stream (realtime_estimate below).
  std::vector<EstimateOut> provisional_by_scan;
  std::uint32_t provisional_steps = 0;  ///< stamped entries of provisional_by_scan
  std::vector<double> latency_us;        ///< wall time of the step() that consumed scan k (index k-1); 0 if not delivered
  std::vector<std::uint32_t> delivered;  ///< scans handed to the tracker, in order: step i consumed scan delivered[i]
  std::vector<Status> statuses;          ///< every step() status, then flush()'s
  TrackerCounters counters;              ///< the tracker's counters at the end of the run
  /// step()/flush() calls during which mixture_truncated grew (a GM filter's
  /// J_max truncation: counted, not an error status; issue 18 asks for it on
  /// under 1 % of steps).
  std::uint64_t steps_truncating = 0;
};

/// The real-time estimate of scan k (1-based): what the step() that consumed
/// scan k handed out for scan k itself, its provisional estimate or else its
/// final one when that step finalised it (a filter); nullptr if neither (a
/// smoother before its first window). Read from the stamps, nothing copied.
inline const EstimateOut* realtime_estimate(const RunRecord& rec, std::uint32_t k) {
  if (k == 0) return nullptr;
  if (k <= rec.provisional_by_scan.size() && rec.provisional_by_scan[k - 1].reported_after_scan == k) {
    return &rec.provisional_by_scan[k - 1];
  }
  if (k <= rec.by_scan.size() && rec.by_scan[k - 1].reported_after_scan == k) return &rec.by_scan[k - 1];
  return nullptr;
}

/// Puts a tracker's finalised estimates at their scans. A tracker numbers
/// its scans by the steps it was given (EstimateOut::scan = step index + 1),
/// which is the source's scan number only when no scan was skipped; the
/// estimate of step i belongs to scan delivered[i-1]. Estimates outside the
/// delivered steps are dropped.
std::vector<EstimateOut> estimates_by_scan(std::vector<EstimateOut>& finals,
                                           const std::vector<std::uint32_t>& delivered, std::uint32_t num_scans);

}  // namespace mptrack::sim
