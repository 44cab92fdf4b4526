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
  /// index scan-1: what the step() that consumed scan k handed out for scan k
  /// itself, its final estimate (a filter) or its provisional one (a
  /// smoother; TrackerAdapter::provisional); empty where it handed out
  /// neither (a smoother's step that only stored its scan).
  std::vector<EstimateOut> realtime_by_scan;
  /// Steps whose realtime_by_scan entry was a provisional estimate (0: the
  /// real-time stream is the final one, as for every filter).
  std::uint32_t provisional_steps = 0;
  std::vector<double> latency_us;        ///< wall time of the step() that consumed scan k (index k-1); 0 if not delivered
  std::vector<std::uint32_t> delivered;  ///< scans handed to the tracker, in order: step i consumed scan delivered[i]
  std::vector<Status> statuses;          ///< every step() status, then flush()'s
  TrackerCounters counters;              ///< the tracker's counters at the end of the run
  /// step()/flush() calls during which mixture_truncated grew (a GM filter's
  /// J_max truncation: counted, not an error status; issue 18 asks for it on
  /// under 1 % of steps).
  std::uint64_t steps_truncating = 0;
};

/// Puts a tracker's finalised estimates at their scans. A tracker numbers
/// its scans by the steps it was given (EstimateOut::scan = step index + 1),
/// which is the source's scan number only when no scan was skipped; the
/// estimate of step i belongs to scan delivered[i-1]. Estimates outside the
/// delivered steps are dropped.
std::vector<EstimateOut> estimates_by_scan(std::vector<EstimateOut>& finals,
                                           const std::vector<std::uint32_t>& delivered, std::uint32_t num_scans);

}  // namespace mptrack::sim
