// The harness aggregator; see aggregator.h.
#include "eval/aggregator.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace mptrack::sim {

namespace {

/// Nearest rank on sorted, non-empty v: the smallest value with at least q
/// of the samples at or below it.
double nearest_rank(const std::vector<double>& v, double q) {
  const double r = std::ceil(q * static_cast<double>(v.size()));
  const std::size_t i = r < 1.0 ? 0 : static_cast<std::size_t>(r) - 1;
  return v[std::min(i, v.size() - 1)];
}

}  // namespace

LatencyStats latency_stats(std::vector<double> v) {
  LatencyStats s;
  s.count = v.size();
  if (v.empty()) return s;
  std::sort(v.begin(), v.end());
  s.p50_us = nearest_rank(v, 0.50);
  s.p99_us = nearest_rank(v, 0.99);
  s.max_us = v.back();
  double sum = 0.0;
  for (double x : v) sum += x;
  s.mean_us = sum / static_cast<double>(v.size());
  return s;
}

void add_counters(TrackerCounters& sum, const TrackerCounters& run) {
  for_each_counter([&](const char*, std::uint64_t TrackerCounters::*field) { sum.*field += run.*field; });
}

std::uint64_t measurement_checksum(const scenario::SimScan& scan, std::uint64_t h) {
  const auto mix = [&h](double v) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    for (int i = 0; i < 8; ++i) {
      h ^= (bits >> (8 * i)) & 0xffU;
      h *= 0x100000001b3ULL;  // FNV-1a 64-bit prime
    }
  };
  for (const scenario::SimMeasurement& m : scan.measurements) {
    mix(m.range_m);
    mix(m.azimuth_rad);
    mix(m.amplitude);
  }
  return h;
}

double Summary::object_rmse_quantile(double q) const {
  return object_rmse_m.empty() ? 0.0 : nearest_rank(object_rmse_m, q);
}

void Summary::count_status(Status st) {
  ++step_status[to_string(st)];
  if (st == Status::kPartial) {
    ++steps_partial;
  } else if (st == Status::kCapacityExceeded) {
    ++steps_capacity;
  } else if (st != Status::kOk) {
    ++step_errors;
  }
}

Aggregator::Aggregator(const SummaryHeader& h) {
  static_cast<SummaryHeader&>(sum_) = h;
  sum_.ospa_per_scan.assign(h.scans, 0.0);
  sum_.confirmed_mean_per_scan.assign(h.scans, 0.0);
  sum_.confirmed_std_per_scan.assign(h.scans, 0.0);
  sum_.truths_per_scan.assign(h.scans, 0.0);
  confirmed_sq_.assign(h.scans, 0.0);
}

void Aggregator::add_run(const std::vector<scenario::SimScan>& scans, const RunRecord& rec,
                         const std::vector<ScanMetrics>& metrics, const std::vector<ScanMetrics>* provisional) {
  add_realtime(rec, metrics, provisional);
  for (const std::uint32_t k : rec.delivered) {
    const scenario::SimScan& s = scans[k - 1];
    measurements_ += static_cast<double>(s.measurements.size());
    sum_.measurement_checksum = measurement_checksum(s, sum_.measurement_checksum);
    latency_us_.push_back(rec.latency_us[k - 1]);
  }
  delivered_ += rec.delivered.size();
  for (const Status st : rec.statuses) sum_.count_status(st);
  sum_.steps_truncating += rec.steps_truncating;
  add_counters(sum_.counters, rec.counters);

  std::set<std::uint32_t> found;
  double run_ospa = 0.0, run_ospa_mahalanobis = 0.0;
  std::uint32_t run_eval_scans = 0;
  for (std::uint32_t k = 1; k <= sum_.scans; ++k) {
    const ScanMetrics& m = metrics[k - 1];
    sum_.ospa_per_scan[k - 1] += m.ospa / static_cast<double>(sum_.runs);
    const double confirmed = static_cast<double>(m.confirmed);
    sum_.confirmed_mean_per_scan[k - 1] += confirmed;  // sums here, means in summary()
    confirmed_sq_[k - 1] += confirmed * confirmed;
    sum_.truths_per_scan[k - 1] += static_cast<double>(m.truths);
    for (const TrackOut& t : rec.by_scan[k - 1].tracks) {
      if (t.confirmed) found.insert(t.id);
    }
    if (k >= sum_.eval_first_scan && k <= sum_.eval_last_scan) {
      add_eval_scan(m);
      run_ospa += m.ospa;
      run_ospa_mahalanobis += m.ospa_mahalanobis;
      ++run_eval_scans;
    }
  }
  const auto run_mean = [run_eval_scans](double sum) {
    return run_eval_scans > 0 ? sum / static_cast<double>(run_eval_scans) : 0.0;
  };
  sum_.ospa_per_run.push_back(run_mean(run_ospa));
  sum_.ospa_mahalanobis_per_run.push_back(run_mean(run_ospa_mahalanobis));
  tracks_found_ += static_cast<double>(found.size());
  add_object_errors(scans, metrics);
  sum_.track_scores.add(score_run(scans, rec.by_scan, sum_.scoring, &rec.provisional_by_scan));
}

void Aggregator::add_realtime(const RunRecord& rec, const std::vector<ScanMetrics>& metrics,
                              const std::vector<ScanMetrics>* provisional) {
  for (std::uint32_t k = sum_.eval_first_scan; k <= sum_.eval_last_scan && k <= metrics.size(); ++k) {
    const EstimateOut* e = realtime_estimate(rec, k);
    if (e == nullptr) continue;  // no estimate of scan k in time
    const bool is_provisional = k <= rec.provisional_by_scan.size() && e == &rec.provisional_by_scan[k - 1];
    if (is_provisional && (provisional == nullptr || k > provisional->size())) continue;  // not evaluated
    realtime_ospa_ += is_provisional ? (*provisional)[k - 1].ospa : metrics[k - 1].ospa;
    ++realtime_scans_;
  }
}

void Aggregator::add_object_errors(const std::vector<scenario::SimScan>& scans,
                                   const std::vector<ScanMetrics>& metrics) {
  struct Tally {
    double sum_d2 = 0.0;
    std::uint32_t n = 0;
  };
  std::map<std::uint32_t, Tally> objects;  // target id -> matched errors of this run
  for (std::uint32_t k = sum_.eval_first_scan; k <= sum_.eval_last_scan && k <= sum_.scans; ++k) {
    for (const scenario::TruthState& t : scans[k - 1].truth) objects[t.target_id];
    for (const ObjectError& e : metrics[k - 1].matched) {
      Tally& tally = objects[e.target_id];
      tally.sum_d2 += e.distance_m * e.distance_m;
      ++tally.n;
    }
  }
  for (const auto& [id, tally] : objects) {
    if (tally.n == 0) {
      ++sum_.objects_never_matched;
    } else {
      sum_.object_rmse_m.push_back(std::sqrt(tally.sum_d2 / static_cast<double>(tally.n)));
    }
  }
}

void Aggregator::add_eval_scan(const ScanMetrics& m) {
  ++sum_.eval_scan_count;
  ospa_ += m.ospa;
  gospa_ += m.gospa;
  ospa_mahalanobis_ += m.ospa_mahalanobis;
  loc_ += m.gospa_localisation;
  missed_pow_ += m.gospa_missed;
  false_pow_ += m.gospa_false;
  missed_ += static_cast<double>(m.gospa_num_missed);
  false_n_ += static_cast<double>(m.gospa_num_false);
  card_ += std::fabs(static_cast<double>(m.confirmed) - static_cast<double>(m.truths));
  nft_ += m.false_tracks;
  confirmed_ += m.confirmed;
  truths_ += m.truths;
  sum_.car_correct += m.car_correct;
  sum_.car_total += m.car_total;
  sum_.car_id_correct += m.car_id_correct;
}

Summary Aggregator::summary() const {
  Summary s = sum_;
  const double n = s.eval_scan_count > 0 ? static_cast<double>(s.eval_scan_count) : 1.0;
  s.mean_ospa = ospa_ / n;
  s.mean_gospa = gospa_ / n;
  s.mean_ospa_mahalanobis = ospa_mahalanobis_ / n;
  s.mean_realtime_ospa = realtime_scans_ > 0 ? realtime_ospa_ / static_cast<double>(realtime_scans_) : 0.0;
  s.realtime_scan_fraction = static_cast<double>(realtime_scans_) / n;
  s.gospa_localisation = loc_ / n;
  s.gospa_missed = missed_pow_ / n;
  s.gospa_false = false_pow_ / n;
  s.missed_per_scan = missed_ / n;
  s.false_per_scan = false_n_ / n;
  s.cardinality_error = card_ / n;
  s.nft = nft_ / n;
  s.mean_confirmed_tracks = confirmed_ / n;
  s.mean_truths = truths_ / n;
  s.car = s.car_total > 0 ? static_cast<double>(s.car_correct) / static_cast<double>(s.car_total) : 0.0;
  s.car_identity = s.car_total > 0 ? static_cast<double>(s.car_id_correct) / static_cast<double>(s.car_total) : 0.0;
  s.tracks_found_per_run = s.runs > 0 ? tracks_found_ / static_cast<double>(s.runs) : 0.0;
  s.mean_measurements = delivered_ > 0 ? measurements_ / static_cast<double>(delivered_) : 0.0;
  s.latency = latency_stats(latency_us_);
  const double runs = s.runs > 0 ? static_cast<double>(s.runs) : 1.0;
  for (std::size_t k = 0; k < s.confirmed_mean_per_scan.size(); ++k) {
    const double mean = s.confirmed_mean_per_scan[k] / runs;
    s.confirmed_mean_per_scan[k] = mean;
    s.confirmed_std_per_scan[k] = std::sqrt(std::max(0.0, confirmed_sq_[k] / runs - mean * mean));
    s.truths_per_scan[k] /= runs;
  }
  std::sort(s.object_rmse_m.begin(), s.object_rmse_m.end());
  return s;
}

}  // namespace mptrack::sim
