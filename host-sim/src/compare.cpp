// `mptrack-sim compare`; see compare.h.
#include "compare.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>

#include "mptrack/metrics/gospa.h"
#include "mptrack/metrics/ospa.h"
#include "progress.h"
#include "svg_plot.h"
#include "tracker_registry.h"

namespace mptrack::sim {

namespace {

constexpr std::size_t kMaxPoints = 256;
using Position = Eigen::Matrix<double, 2, 1>;

/// Sums of one tracker's per-scan metrics over runs x evaluation scans.
struct Accumulator {
  double ospa = 0.0, gospa = 0.0, loc = 0.0, missed_pow = 0.0, false_pow = 0.0;
  double missed = 0.0, false_n = 0.0, card = 0.0, nft = 0.0, confirmed = 0.0;
  std::uint64_t eval_scans = 0;
  std::vector<double> latency_us;
  std::vector<double> ospa_per_scan;
  std::uint64_t step_errors = 0, steps_not_ok = 0;
  std::uint64_t checksum = kChecksumSeed;
};

/// Per-scan OSPA/GOSPA with the comparison's (c, p), on confirmed tracks.
class Evaluator {
 public:
  Evaluator(double cutoff_m, double order)
      : ospa_(std::make_unique<OspaMetric<double, kMaxPoints>>()),
        gospa_(std::make_unique<GospaMetric<double, kMaxPoints>>()) {
    const MetricParams<double> params{order, cutoff_m};
    if (ospa_->init(params) != Status::kOk || gospa_->init(params) != Status::kOk) {
      throw std::runtime_error("OSPA parameters rejected (need p >= 1, c > 0)");
    }
  }

  /// Adds scan `k`'s metrics; `eval` = inside the evaluation interval.
  double add(const scenario::SimScan& scan, const EstimateOut& est, bool eval, Accumulator& acc) {
    truths_.clear();
    tracks_.clear();
    for (const auto& t : scan.truth) truths_.emplace_back(t.x.px, t.x.py);
    for (const TrackOut& t : est.tracks) {
      if (t.confirmed) tracks_.emplace_back(t.px, t.py);
    }
    if (truths_.size() > kMaxPoints || tracks_.size() > kMaxPoints) {
      throw std::runtime_error("scan " + std::to_string(scan.scan) + ": more than " + std::to_string(kMaxPoints) +
                               " truths or confirmed tracks to evaluate");
    }
    OspaResult<double> o;
    GospaResult<double> g;
    if (ospa_->compute(truths_.data(), truths_.size(), tracks_.data(), tracks_.size(), o) != Status::kOk ||
        gospa_->compute(truths_.data(), truths_.size(), tracks_.data(), tracks_.size(), g) != Status::kOk) {
      throw std::runtime_error("scan " + std::to_string(scan.scan) + ": OSPA failed (non-finite track state?)");
    }
    if (!eval) return o.total;
    const auto& match = ospa_->matching();
    std::size_t false_tracks = 0;
    for (std::size_t j = 0; j < tracks_.size(); ++j) {
      if (!match.estimate_within_cutoff(j)) ++false_tracks;
    }
    ++acc.eval_scans;
    acc.ospa += o.total;
    acc.gospa += g.total;
    acc.loc += g.localisation_pow;
    acc.missed_pow += g.missed_pow;
    acc.false_pow += g.false_pow;
    acc.missed += static_cast<double>(g.num_missed);
    acc.false_n += static_cast<double>(g.num_false);
    const double diff = static_cast<double>(tracks_.size()) - static_cast<double>(truths_.size());
    acc.card += std::fabs(diff);
    acc.nft += static_cast<double>(false_tracks);
    acc.confirmed += static_cast<double>(tracks_.size());
    return o.total;
  }

 private:
  std::unique_ptr<OspaMetric<double, kMaxPoints>> ospa_;
  std::unique_ptr<GospaMetric<double, kMaxPoints>> gospa_;
  std::vector<Position> truths_, tracks_;
};

std::string fmt(const char* f, double x) {
  char b[64];
  std::snprintf(b, sizeof b, f, x);
  return b;
}

std::string hex64(std::uint64_t h) {
  char b[24];
  std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(h));
  return b;
}

}  // namespace

void default_ospa(const scenario::ScenarioSpec& spec, double& cutoff_m, double& order) {
  if (spec.space == scenario::MeasurementSpace::kCartesian) {
    cutoff_m = 300.0;  // seed 001 section 6: OSPA p = 1, c = 300 m
    order = 1.0;
  } else {
    cutoff_m = kOspaCutoff_m;  // seed 000 spec 5.1
    order = kOspaOrder;
  }
}

std::vector<std::string> default_compare_trackers(const scenario::ScenarioSpec& spec) {
  std::vector<std::string> names;
  if (spec.space == scenario::MeasurementSpace::kCartesian) {
    names = {"gmphd", "gmphd-known", "gmcphd", "gmcphd-known", "cbmember", "cbmember-known"};
  } else {
    names = {"mfbp", "mfbp-filter", "gmphd", "gmcphd", "cbmember", "gmcphd-known", "gnn"};
  }
  return names;
}

std::vector<std::string> parse_tracker_list(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    const std::size_t end = comma == std::string::npos ? text.size() : comma;
    const std::string item = text.substr(start, end - start);
    if (item.empty()) throw std::runtime_error("--trackers: empty name in '" + text + "'");
    out.push_back(item);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
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

CompareResult run_compare(const CompareConfig& cfg) {
  const scenario::ScenarioSpec& spec = cfg.spec;
  const std::string spec_error = scenario::validate(spec);
  if (!spec_error.empty()) throw std::runtime_error("scenario " + spec.name + ": " + spec_error);
  if (cfg.runs < 1) throw std::runtime_error("--runs must be >= 1");
  const std::vector<std::string> names = cfg.trackers.empty() ? default_compare_trackers(spec) : cfg.trackers;
  if (names.empty()) throw std::runtime_error("no tracker to compare");
  for (const std::string& n : names) {
    std::string error;
    if (!make_tracker(n, error)) throw std::runtime_error(error);
  }

  CompareResult res;
  res.scenario = spec.name;
  res.runs = cfg.runs;
  res.scans = spec.num_scans;
  res.seed = cfg.seed;
  res.clutter_scale = cfg.clutter_scale;
  default_ospa(spec, res.ospa_cutoff_m, res.ospa_order);
  if (cfg.ospa_cutoff_m > 0.0) res.ospa_cutoff_m = cfg.ospa_cutoff_m;
  if (cfg.ospa_order > 0.0) res.ospa_order = cfg.ospa_order;
  res.eval_first_scan = spec.eval_first_scan;
  res.eval_last_scan = spec.eval_last_scan;

  Evaluator evaluator(res.ospa_cutoff_m, res.ospa_order);
  std::vector<Accumulator> acc(names.size());
  for (Accumulator& a : acc) a.ospa_per_scan.assign(spec.num_scans, 0.0);
  double measurements_sum = 0.0, truths_sum = 0.0;
  std::uint64_t truth_scans = 0;

  Progress progress("compare " + spec.name,
                    static_cast<std::uint64_t>(cfg.runs) * spec.num_scans * (names.size() + 1), cfg.progress);
  for (std::uint32_t run = 0; run < cfg.runs; ++run) {
    // One measurement set per run, shared by every tracker.
    scenario::Generator gen;
    scenario::GeneratorOptions options;
    options.clutter_scale = cfg.clutter_scale;
    if (gen.init(spec, cfg.seed, run, options) != Status::kOk) throw std::runtime_error(gen.error());
    std::vector<scenario::SimScan> scans(spec.num_scans);
    for (std::uint32_t k = 1; k <= spec.num_scans; ++k) {
      if (gen.generate(k, scans[k - 1]) != Status::kOk) {
        throw std::runtime_error("generator failed at scan " + std::to_string(k));
      }
      measurements_sum += static_cast<double>(scans[k - 1].measurements.size());
      if (k >= spec.eval_first_scan && k <= spec.eval_last_scan) {
        truths_sum += static_cast<double>(scans[k - 1].truth.size());
        ++truth_scans;
      }
      progress.tick();
    }

    for (std::size_t t = 0; t < names.size(); ++t) {
      Accumulator& a = acc[t];
      std::string error;
      std::unique_ptr<TrackerAdapter> tracker = make_tracker(names[t], error);
      TrackerSetup setup;
      setup.spec = spec;
      setup.clutter_scale = cfg.clutter_scale;
      setup.mfbp_params = cfg.mfbp_params;
      error = tracker->init(setup);
      if (!error.empty()) throw std::runtime_error("tracker " + names[t] + ": " + error);
      std::vector<EstimateOut> finals;
      const auto count = [&a](Status st) {
        if (st == Status::kOk) return;
        ++a.steps_not_ok;
        if (st != Status::kPartial && st != Status::kCapacityExceeded) ++a.step_errors;
      };
      for (std::uint32_t k = 1; k <= spec.num_scans; ++k) {
        const scenario::SimScan& s = scans[k - 1];
        a.checksum = measurement_checksum(s, a.checksum);
        const auto t0 = std::chrono::steady_clock::now();
        const Status st = tracker->step(s, finals);
        const auto t1 = std::chrono::steady_clock::now();
        a.latency_us.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count());
        count(st);
        progress.tick();
      }
      count(tracker->flush(finals));

      std::vector<EstimateOut> by_scan(spec.num_scans);
      for (std::uint32_t k = 1; k <= spec.num_scans; ++k) by_scan[k - 1].scan = k;
      for (EstimateOut& e : finals) {
        if (e.scan >= 1 && e.scan <= spec.num_scans) by_scan[e.scan - 1] = std::move(e);
      }
      for (std::uint32_t k = 1; k <= spec.num_scans; ++k) {
        const bool eval = k >= spec.eval_first_scan && k <= spec.eval_last_scan;
        const double ospa = evaluator.add(scans[k - 1], by_scan[k - 1], eval, a);
        a.ospa_per_scan[k - 1] += ospa / static_cast<double>(cfg.runs);
      }
    }
  }
  progress.finish();

  res.mean_measurements = measurements_sum / (static_cast<double>(cfg.runs) * spec.num_scans);
  res.mean_truths = truth_scans > 0 ? truths_sum / static_cast<double>(truth_scans) : 0.0;
  for (std::size_t t = 0; t < names.size(); ++t) {
    Accumulator& a = acc[t];
    const double n = a.eval_scans > 0 ? static_cast<double>(a.eval_scans) : 1.0;
    CompareRow r;
    r.tracker = names[t];
    r.mean_ospa = a.ospa / n;
    r.mean_gospa = a.gospa / n;
    r.gospa_localisation = a.loc / n;
    r.gospa_missed = a.missed_pow / n;
    r.gospa_false = a.false_pow / n;
    r.missed_per_scan = a.missed / n;
    r.false_per_scan = a.false_n / n;
    r.cardinality_error = a.card / n;
    r.nft = a.nft / n;
    r.mean_confirmed = a.confirmed / n;
    r.latency = latency_stats(std::move(a.latency_us));
    r.step_errors = a.step_errors;
    r.steps_not_ok = a.steps_not_ok;
    r.measurement_checksum = a.checksum;
    r.ospa_per_scan = std::move(a.ospa_per_scan);
    res.rows.push_back(std::move(r));
  }

  if (!cfg.out_dir.empty()) {
    std::filesystem::create_directories(cfg.out_dir);
    std::ofstream md(cfg.out_dir + "/compare.md");
    md << compare_to_markdown(res);
    std::ofstream js(cfg.out_dir + "/compare.json");
    js << compare_to_json(res).dump(2) << "\n";
    if (!md || !js) throw std::runtime_error(cfg.out_dir + ": cannot write compare.md/compare.json");
    if (cfg.plot) {
      std::vector<OspaSeries> series;
      for (const CompareRow& r : res.rows) series.push_back(OspaSeries{r.tracker, r.ospa_per_scan});
      write_ospa_comparison_svg(cfg.out_dir + "/ospa.svg",
                                spec.name + ": OSPA over time, mean of " + std::to_string(cfg.runs) + " run(s)",
                                series, spec.eval_first_scan, spec.eval_last_scan, res.ospa_order,
                                res.ospa_cutoff_m);
    }
  }
  return res;
}

nlohmann::ordered_json compare_to_json(const CompareResult& r) {
  using json = nlohmann::ordered_json;
  json rows = json::array();
  for (const CompareRow& x : r.rows) {
    rows.push_back({{"tracker", x.tracker},
                    {"mean_ospa", x.mean_ospa},
                    {"mean_gospa", x.mean_gospa},
                    {"gospa_localisation", x.gospa_localisation},
                    {"gospa_missed", x.gospa_missed},
                    {"gospa_false", x.gospa_false},
                    {"missed_per_scan", x.missed_per_scan},
                    {"false_per_scan", x.false_per_scan},
                    {"cardinality_error", x.cardinality_error},
                    {"nft", x.nft},
                    {"mean_confirmed", x.mean_confirmed},
                    {"latency_us",
                     {{"p50", x.latency.p50_us},
                      {"p99", x.latency.p99_us},
                      {"max", x.latency.max_us},
                      {"mean", x.latency.mean_us},
                      {"samples", x.latency.count}}},
                    {"step_errors", x.step_errors},
                    {"steps_not_ok", x.steps_not_ok},
                    {"measurement_checksum", hex64(x.measurement_checksum)},
                    {"ospa_per_scan", x.ospa_per_scan}});
  }
  return json{{"scenario", r.scenario},
              {"runs", r.runs},
              {"scans", r.scans},
              {"seed", r.seed},
              {"clutter_scale", r.clutter_scale},
              {"ospa", {{"order_p", r.ospa_order}, {"cutoff_m", r.ospa_cutoff_m}}},
              {"eval_scans", {r.eval_first_scan, r.eval_last_scan}},
              {"mean_measurements_per_scan", r.mean_measurements},
              {"mean_truths_per_scan", r.mean_truths},
              {"rows", rows}};
}

std::string compare_to_markdown(const CompareResult& r) {
  std::string p = fmt("%g", r.ospa_order);
  std::string s = "# " + r.scenario + ": tracker comparison\n\n";
  s += std::to_string(r.runs) + " run(s) x " + std::to_string(r.scans) + " scans, seed " + std::to_string(r.seed) +
       ", evaluated scans " + std::to_string(r.eval_first_scan) + ".." + std::to_string(r.eval_last_scan) +
       "; OSPA/GOSPA p = " + p + ", c = " + fmt("%g", r.ospa_cutoff_m) + " m on confirmed tracks; " +
       fmt("%.1f", r.mean_measurements) + " measurements and " + fmt("%.2f", r.mean_truths) +
       " targets per scan. Every tracker got the same measurements (checksum column).\n\n";
  s += "| tracker | OSPA [m] | GOSPA [m] | GOSPA loc [m^" + p + "] | GOSPA missed [m^" + p + "] | GOSPA false [m^" +
       p + "] | card. error | NFT | latency p50 [us] | p99 [us] | max [us] | errors | checksum |\n";
  s += "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
  for (const CompareRow& x : r.rows) {
    s += "| " + x.tracker + " | " + fmt("%.2f", x.mean_ospa) + " | " + fmt("%.2f", x.mean_gospa) + " | " +
         fmt("%.4g", x.gospa_localisation) + " | " + fmt("%.4g", x.gospa_missed) + " | " +
         fmt("%.4g", x.gospa_false) + " | " + fmt("%.3f", x.cardinality_error) + " | " + fmt("%.3f", x.nft) +
         " | " + fmt("%.1f", x.latency.p50_us) + " | " + fmt("%.1f", x.latency.p99_us) + " | " +
         fmt("%.1f", x.latency.max_us) + " | " + std::to_string(x.step_errors) + " | " +
         hex64(x.measurement_checksum).substr(0, 8) + " |\n";
  }
  s += "\nColumns: means per evaluation scan over all runs. GOSPA components sum to GOSPA^p per scan "
       "(missed/false = c^p/2 per unassigned truth/track). card. error = |#confirmed - #targets|; NFT = confirmed "
       "tracks with no target within c. Latency: wall time of one step() on this host (a smoother's p50 is a "
       "buffering step). errors: steps returning an error status.\n";
  return s;
}

}  // namespace mptrack::sim
