// The Monte Carlo loop; see run_loop.h.
#include "run/run_loop.h"

#include <chrono>
#include <stdexcept>
#include <utility>

#include "progress.h"
#include "tracker_registry.h"

namespace mptrack::sim {

namespace {

TrackerFactory factory_of(const LoopConfig& cfg) { return cfg.factory != nullptr ? cfg.factory : &make_tracker; }

std::unique_ptr<TrackerAdapter> make_initialised(const LoopConfig& cfg, const std::string& name,
                                                 const scenario::ScenarioSpec& spec) {
  std::string error;
  std::unique_ptr<TrackerAdapter> tracker = factory_of(cfg)(name, error);
  if (!tracker) throw std::runtime_error(error);
  TrackerSetup setup;
  setup.spec = spec;
  setup.clutter_scale = cfg.clutter_scale;
  setup.mfbp_params = cfg.mfbp_params;
  setup.rfs_params = cfg.rfs_params;
  setup.raw_scenario = cfg.raw_scenario;
  setup.sea_scenario = cfg.sea_scenario;
  error = tracker->init(setup);
  if (!error.empty()) throw std::runtime_error("tracker " + name + ": " + error);
  return tracker;
}

}  // namespace

std::vector<EstimateOut> estimates_by_scan(std::vector<EstimateOut>& finals,
                                           const std::vector<std::uint32_t>& delivered, std::uint32_t num_scans) {
  std::vector<EstimateOut> by_scan(num_scans);
  for (std::uint32_t k = 1; k <= num_scans; ++k) by_scan[k - 1].scan = k;
  for (EstimateOut& e : finals) {
    if (e.scan < 1 || e.scan > delivered.size()) continue;
    const std::uint32_t scan = delivered[e.scan - 1];
    e.scan = scan;
    by_scan[scan - 1] = std::move(e);
  }
  return by_scan;
}

LoopConfig one_tracker_loop(const TrackerRunOptions& o, const std::string& scenario_name) {
  LoopConfig loop;
  loop.trackers = {o.tracker};
  loop.runs = o.runs;
  loop.seed = o.seed;
  loop.mfbp_params = o.mfbp_params;
  loop.rfs_params = o.rfs_params;
  loop.progress_label = scenario_name + " " + o.tracker;
  loop.progress = o.progress;
  return loop;
}

void check_loop_config(const LoopConfig& cfg) {
  if (cfg.runs < 1) throw std::runtime_error("--runs must be >= 1");
  if (cfg.trackers.empty()) throw std::runtime_error("no tracker to compare");
  for (const std::string& name : cfg.trackers) {
    std::string error;
    if (!factory_of(cfg)(name, error)) throw std::runtime_error(error);
  }
}

namespace {

/// The provisional estimate of the step's own scan (tracker numbering: the
/// step count), if the tracker handed one out, stamped with the source scan
/// and appended to provisionals.
void keep_provisional(const TrackerAdapter& tracker, std::uint32_t step_scan, std::uint32_t source_scan,
                      std::vector<EstimateOut>& provisionals) {
  EstimateOut p;
  if (!tracker.provisional(p) || p.scan != step_scan) return;
  p.reported_after_scan = source_scan;
  provisionals.push_back(std::move(p));
}

}  // namespace

RunRecord run_tracker(ScanSource& source, TrackerAdapter& tracker, std::uint32_t run, Progress* progress) {
  const std::uint32_t n = source.num_scans();
  RunRecord rec;
  rec.run = run;
  rec.latency_us.assign(n, 0.0);
  std::vector<EstimateOut> finals;
  std::vector<EstimateOut> provisionals;  // at most one per step: that step's own scan
  const FrameInput input = tracker.frame_input();
  // A step()/flush() during which the mixture truncation count grew (RunRecord::steps_truncating).
  std::uint64_t truncated = tracker.counters().mixture_truncated;
  const auto count_truncation = [&] {
    const std::uint64_t now = tracker.counters().mixture_truncated;
    if (now > truncated) ++rec.steps_truncating;
    truncated = now;
  };
  // The estimates a call appended were handed out after `scan`.
  const auto stamp = [&finals](std::size_t from, std::uint32_t scan) {
    for (std::size_t i = from; i < finals.size(); ++i) finals[i].reported_after_scan = scan;
  };
  source.deliver([&](const scenario::SimScan& s, const RawFrame* frame) {
    rec.delivered.push_back(s.scan);
    const std::size_t before = finals.size();
    const auto t0 = std::chrono::steady_clock::now();
    const Status st = frame != nullptr ? tracker.step_frame(*frame, s, finals) : tracker.step(s, finals);
    const auto t1 = std::chrono::steady_clock::now();
    stamp(before, s.scan);
    keep_provisional(tracker, static_cast<std::uint32_t>(rec.delivered.size()), s.scan, provisionals);
    count_truncation();
    const double us = std::chrono::duration<double, std::micro>(t1 - t0).count();
    rec.latency_us[s.scan - 1] = us;
    rec.statuses.push_back(st);
    if (progress != nullptr) progress->tick();
    return us;
  }, input);
  const std::size_t before_flush = finals.size();
  rec.statuses.push_back(tracker.flush(finals));
  stamp(before_flush, rec.delivered.empty() ? 0U : rec.delivered.back());
  count_truncation();
  rec.counters = tracker.counters();
  rec.by_scan = estimates_by_scan(finals, rec.delivered, n);
  rec.provisional_steps = static_cast<std::uint32_t>(provisionals.size());
  rec.provisional_by_scan = estimates_by_scan(provisionals, rec.delivered, n);
  return rec;
}

std::vector<Summary> run_loop(ScanSource& source, const LoopConfig& cfg, const std::vector<RunObserver*>& observers) {
  check_loop_config(cfg);
  const scenario::ScenarioSpec& spec = source.spec();
  ScanEvaluator evaluator(cfg.ospa_cutoff_m, cfg.ospa_order, mahalanobis_ospa_params(spec));
  std::vector<Aggregator> aggregators;
  for (const std::string& name : cfg.trackers) {
    aggregators.emplace_back(SummaryHeader{spec.name, name, cfg.runs, spec.num_scans, cfg.seed, cfg.clutter_scale,
                                           spec.eval_first_scan, spec.eval_last_scan,
                                           track_scoring_params(spec, cfg.ospa_cutoff_m)});
  }
  Progress progress(cfg.progress_label,
                    static_cast<std::uint64_t>(cfg.runs) * spec.num_scans * cfg.trackers.size(), cfg.progress);
  for (std::uint32_t run = 0; run < cfg.runs; ++run) {
    source.begin_run(run);
    for (std::size_t t = 0; t < cfg.trackers.size(); ++t) {
      std::unique_ptr<TrackerAdapter> tracker = make_initialised(cfg, cfg.trackers[t], spec);
      const RunRecord rec = run_tracker(source, *tracker, run, &progress);
      const std::vector<ScanMetrics> metrics = evaluator.evaluate_run(source.scans(), rec.by_scan);
      // Only a tracker that handed out provisional estimates has a real-time stream to evaluate apart.
      const std::vector<ScanMetrics> provisional =
          rec.provisional_steps > 0 ? evaluator.evaluate_run(source.scans(), rec.provisional_by_scan)
                                    : std::vector<ScanMetrics>{};
      aggregators[t].add_run(source.scans(), rec, metrics, rec.provisional_steps > 0 ? &provisional : nullptr);
      for (RunObserver* o : observers) o->on_run(t, source.scans(), rec, metrics);
    }
  }
  progress.finish();
  std::vector<Summary> out;
  for (const Aggregator& a : aggregators) out.push_back(a.summary());
  return out;
}

}  // namespace mptrack::sim
