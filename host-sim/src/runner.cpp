// Monte Carlo runner; see runner.h.
#include "runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>
#include <stdexcept>

#include "mptrack/scenario/generator.h"
#include "progress.h"
#include "svg_plot.h"
#include "tracker_registry.h"
#include "writers.h"

namespace mptrack::sim {

LatencyStats latency_stats(std::vector<double> v) {
  LatencyStats s;
  s.count = v.size();
  if (v.empty()) return s;
  std::sort(v.begin(), v.end());
  // Nearest rank: the smallest value with at least q of the samples at or below it.
  const auto rank = [&](double q) {
    const double r = std::ceil(q * static_cast<double>(v.size()));
    const std::size_t i = r < 1.0 ? 0 : static_cast<std::size_t>(r) - 1;
    return v[std::min(i, v.size() - 1)];
  };
  s.p50_us = rank(0.50);
  s.p99_us = rank(0.99);
  s.max_us = v.back();
  double sum = 0.0;
  for (double x : v) sum += x;
  s.mean_us = sum / static_cast<double>(v.size());
  return s;
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

void Summary::add_counters(const TrackerCounters& run) {
  counters.scans += run.scans;
  counters.scans_rejected += run.scans_rejected;
  counters.measurements_in += run.measurements_in;
  counters.measurements_invalid += run.measurements_invalid;
  counters.measurements_over_cap += run.measurements_over_cap;
  counters.tracks_born += run.tracks_born;
  counters.tracks_confirmed += run.tracks_confirmed;
  counters.tracks_deleted += run.tracks_deleted;
  counters.track_cap_hits += run.track_cap_hits;
  counters.clutter_born += run.clutter_born;
  counters.clutter_deleted += run.clutter_deleted;
  counters.clutter_cap_hits += run.clutter_cap_hits;
  counters.bp_not_converged += run.bp_not_converged;
  counters.numerical_repairs += run.numerical_repairs;
}

Summary run_monte_carlo(const RunConfig& cfg) {
  const scenario::ScenarioSpec& spec = cfg.spec;
  const std::string spec_error = scenario::validate(spec);
  if (!spec_error.empty()) throw std::runtime_error("scenario " + spec.name + ": " + spec_error);
  if (cfg.runs < 1) throw std::runtime_error("--runs must be >= 1");
  {
    std::string error;
    if (!make_tracker(cfg.tracker, error)) throw std::runtime_error(error);
  }

  Summary sum;
  sum.scenario = spec.name;
  sum.tracker = cfg.tracker;
  sum.runs = cfg.runs;
  sum.scans = spec.num_scans;
  sum.seed = cfg.seed;
  sum.clutter_scale = cfg.clutter_scale;
  sum.eval_first_scan = spec.eval_first_scan;
  sum.eval_last_scan = spec.eval_last_scan;
  sum.ospa_per_scan.assign(spec.num_scans, 0.0);

  std::unique_ptr<CsvWriters> csv;
  if (!cfg.out_dir.empty()) csv = std::make_unique<CsvWriters>(cfg.out_dir);

  ScanEvaluator evaluator;
  std::vector<double> all_latency;
  double ospa_sum = 0.0, gospa_sum = 0.0, nft_sum = 0.0, confirmed_sum = 0.0, truths_sum = 0.0;
  double measurements_sum = 0.0;
  std::uint64_t eval_scans = 0;
  double tracks_found_sum = 0.0;

  std::vector<scenario::SimScan> plot_scans;
  std::vector<EstimateOut> plot_estimates;

  Progress progress(spec.name + " " + cfg.tracker, static_cast<std::uint64_t>(cfg.runs) * spec.num_scans,
                    cfg.progress);
  for (std::uint32_t run = 0; run < cfg.runs; ++run) {
    evaluator.begin_run();
    scenario::Generator gen;
    scenario::GeneratorOptions options;
    options.clutter_scale = cfg.clutter_scale;
    if (gen.init(spec, cfg.seed, run, options) != Status::kOk) throw std::runtime_error(gen.error());
    std::string error;
    std::unique_ptr<TrackerAdapter> tracker = make_tracker(cfg.tracker, error);
    TrackerSetup setup;
    setup.spec = spec;
    setup.clutter_scale = cfg.clutter_scale;
    setup.mfbp_params = cfg.mfbp_params;
    error = tracker->init(setup);
    if (!error.empty()) throw std::runtime_error("tracker " + cfg.tracker + ": " + error);

    std::vector<scenario::SimScan> scans(spec.num_scans);
    std::vector<EstimateOut> finals;
    std::vector<double> latency(spec.num_scans, 0.0);
    for (std::uint32_t k = 1; k <= spec.num_scans; ++k) {
      scenario::SimScan& s = scans[k - 1];
      if (gen.generate(k, s) != Status::kOk) throw std::runtime_error("generator failed at scan " + std::to_string(k));
      measurements_sum += static_cast<double>(s.measurements.size());
      const auto t0 = std::chrono::steady_clock::now();
      const Status st = tracker->step(s, finals);
      const auto t1 = std::chrono::steady_clock::now();
      latency[k - 1] = std::chrono::duration<double, std::micro>(t1 - t0).count();
      sum.count_status(st);
      progress.tick();
    }
    sum.count_status(tracker->flush(finals));
    sum.add_counters(tracker->counters());
    all_latency.insert(all_latency.end(), latency.begin(), latency.end());

    std::vector<EstimateOut> by_scan(spec.num_scans);
    for (std::uint32_t k = 1; k <= spec.num_scans; ++k) by_scan[k - 1].scan = k;
    for (EstimateOut& e : finals) {
      if (e.scan >= 1 && e.scan <= spec.num_scans) by_scan[e.scan - 1] = std::move(e);
    }

    std::vector<ScanMetrics> metrics(spec.num_scans);
    std::set<std::uint32_t> found;
    for (std::uint32_t k = 1; k <= spec.num_scans; ++k) {
      const ScanMetrics m = evaluator.evaluate(scans[k - 1], by_scan[k - 1]);
      metrics[k - 1] = m;
      sum.ospa_per_scan[k - 1] += m.ospa / static_cast<double>(cfg.runs);
      for (const TrackOut& t : by_scan[k - 1].tracks) {
        if (t.confirmed) found.insert(t.id);
      }
      if (k < spec.eval_first_scan || k > spec.eval_last_scan) continue;
      ++eval_scans;
      ospa_sum += m.ospa;
      gospa_sum += m.gospa;
      nft_sum += m.false_tracks;
      confirmed_sum += m.confirmed;
      truths_sum += m.truths;
      sum.car_correct += m.car_correct;
      sum.car_total += m.car_total;
      sum.car_id_correct += m.car_id_correct;
    }
    tracks_found_sum += static_cast<double>(found.size());

    if (csv && (cfg.csv_runs < 0 || static_cast<std::int64_t>(run) < cfg.csv_runs)) {
      csv->write_run(run, spec, scans, by_scan, metrics, latency);
    }
    if (run == 0) {
      plot_scans = std::move(scans);
      plot_estimates = std::move(by_scan);
    }
  }
  progress.finish();

  const double n_eval = eval_scans > 0 ? static_cast<double>(eval_scans) : 1.0;
  sum.mean_ospa = ospa_sum / n_eval;
  sum.mean_gospa = gospa_sum / n_eval;
  sum.nft = nft_sum / n_eval;
  sum.mean_confirmed_tracks = confirmed_sum / n_eval;
  sum.mean_truths = truths_sum / n_eval;
  sum.car = sum.car_total > 0 ? static_cast<double>(sum.car_correct) / static_cast<double>(sum.car_total) : 0.0;
  sum.car_identity =
      sum.car_total > 0 ? static_cast<double>(sum.car_id_correct) / static_cast<double>(sum.car_total) : 0.0;
  sum.tracks_found_per_run = tracks_found_sum / static_cast<double>(cfg.runs);
  sum.mean_measurements = measurements_sum / (static_cast<double>(cfg.runs) * spec.num_scans);
  sum.latency = latency_stats(all_latency);

  if (!cfg.out_dir.empty()) {
    write_summary_json(sum, cfg.out_dir + "/summary.json");
    if (cfg.plot) {
      write_plot_svg(cfg.out_dir + "/plot.svg", spec, plot_scans, plot_estimates, sum.ospa_per_scan,
                     spec.name + " / " + cfg.tracker + " (run 0; OSPA mean of " + std::to_string(cfg.runs) +
                         " runs)");
    }
  }
  return sum;
}

}  // namespace mptrack::sim
