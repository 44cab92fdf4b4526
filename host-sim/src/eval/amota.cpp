// AMOTA of one run; definition and choices in docs/algorithms/metrics.md §AMOTA.
#include "eval/amota.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <map>

namespace mptrack::sim {

double MotCounts::mota() const {
  if (truths == 0) return 0.0;
  return 1.0 - static_cast<double>(fp + fn + ids) / static_cast<double>(truths);
}

double MotCounts::motar() const {
  if (tp == 0) return 0.0;
  return 1.0 - static_cast<double>(fp + ids) / static_cast<double>(tp);
}

double MotCounts::recall() const {
  return truths > 0 ? static_cast<double>(tp) / static_cast<double>(truths) : 0.0;
}

MotCounts mot_counts(const std::vector<scenario::SimScan>& scans, const std::vector<EstimateOut>& by_scan,
                     double gate_m, double min_existence, ScoringSolver& solver) {
  MotCounts c;
  std::map<std::uint32_t, std::uint32_t> last_track;  // target id -> track id it was last matched to
  const std::size_t n = std::min(scans.size(), by_scan.size());
  for (std::size_t i = 0; i < n; ++i) {
    const ScanAssignment a = match_scan(scans[i], by_scan[i], gate_m, min_existence, solver);
    std::uint64_t matched = 0;
    for (const auto& [track, target] : a) {
      if (target == kNoTarget) {
        ++c.fp;
        continue;
      }
      ++matched;
      const auto it = last_track.find(target);
      if (it != last_track.end() && it->second != track) ++c.ids;
      last_track[target] = track;
    }
    c.truths += scans[i].truth.size();
    c.tp += matched;
    c.fn += scans[i].truth.size() - matched;
  }
  return c;
}

namespace {

/// Existence of every true positive of the all-tracks matching, highest first.
std::vector<double> true_positive_scores(const std::vector<scenario::SimScan>& scans,
                                         const std::vector<EstimateOut>& by_scan, double gate_m,
                                         ScoringSolver& solver) {
  std::vector<double> scores;
  const double all = -std::numeric_limits<double>::infinity();
  const std::size_t n = std::min(scans.size(), by_scan.size());
  for (std::size_t i = 0; i < n; ++i) {
    const ScanAssignment a = match_scan(scans[i], by_scan[i], gate_m, all, solver);
    for (const TrackOut& t : by_scan[i].tracks) {
      const auto it = a.find(t.id);
      if (t.confirmed && it != a.end() && it->second != kNoTarget) scores.push_back(t.existence);
    }
  }
  std::sort(scores.begin(), scores.end(), std::greater<double>());
  return scores;
}

}  // namespace

AmotaScore run_amota(const std::vector<scenario::SimScan>& scans, const std::vector<EstimateOut>& by_scan,
                     const AmotaParams& params, ScoringSolver& solver) {
  std::uint64_t truths = 0;
  for (const scenario::SimScan& s : scans) truths += s.truth.size();
  const std::uint64_t L = params.recall_points;
  if (truths == 0 || L == 0) return {};
  const std::vector<double> tp_scores = true_positive_scores(scans, by_scan, params.gate_m, solver);
  std::map<double, MotCounts> counts_at;  // threshold -> counts (ties share a threshold)
  AmotaScore sum;
  for (std::uint64_t i = 1; i <= L; ++i) {
    const std::uint64_t k = (i * truths + L - 1) / L;  // ceil(r num_gt), r = i / L, in integers
    if (k > tp_scores.size()) continue;               // recall r never reached: MOTAR_r = MOTA_r = 0
    const double threshold = tp_scores[k - 1];
    auto it = counts_at.find(threshold);
    if (it == counts_at.end()) {
      it = counts_at.emplace(threshold, mot_counts(scans, by_scan, params.gate_m, threshold, solver)).first;
    }
    sum.normalised += it->second.motar();
    sum.unscaled += it->second.mota();
  }
  return {sum.normalised / static_cast<double>(L), sum.unscaled / static_cast<double>(L)};
}

}  // namespace mptrack::sim
