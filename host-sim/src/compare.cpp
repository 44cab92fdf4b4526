// `mptrack-sim compare`; see compare.h.
#include "compare.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "eval/paired.h"
#include "run/run_loop.h"
#include "run/scan_source.h"
#include "svg_plot.h"
#include "writers.h"

namespace mptrack::sim {

namespace {

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
    cutoff_m = 300.0;  // seed 001 Sec. 5: OSPA p = 1, c = 300 m
    order = 1.0;
  } else if (spec.space == scenario::MeasurementSpace::kOthr) {
    cutoff_m = 20000.0;  // seed 002 gives no c: ours, 4 sigma_r (docs/algorithms/multipath.md §Evaluation)
    order = 2.0;
  } else {
    cutoff_m = kOspaCutoff_m;  // seed 000 Sec. IV-A
    order = kOspaOrder;
  }
}

std::vector<std::string> default_compare_trackers(const scenario::ScenarioSpec& spec) {
  std::vector<std::string> names;
  if (spec.space == scenario::MeasurementSpace::kCartesian) {
    names = {"gmphd", "gmphd-known", "gmcphd", "gmcphd-known", "cbmember", "cbmember-known"};
  } else if (spec.space == scenario::MeasurementSpace::kOthr) {
    names = {"mfbp-multipath", "mfbp-filter"};
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

CompareResult run_compare(const CompareConfig& cfg) {
  MeasurementSource source(cfg.spec, cfg.seed, cfg.clutter_scale);
  const scenario::ScenarioSpec& spec = source.spec();
  LoopConfig loop;
  loop.trackers = cfg.trackers.empty() ? default_compare_trackers(spec) : cfg.trackers;
  loop.runs = cfg.runs;
  loop.seed = cfg.seed;
  loop.clutter_scale = cfg.clutter_scale;
  loop.mfbp_params = cfg.mfbp_params;
  loop.rfs_params = cfg.rfs_params;
  default_ospa(spec, loop.ospa_cutoff_m, loop.ospa_order);
  if (cfg.ospa_cutoff_m > 0.0) loop.ospa_cutoff_m = cfg.ospa_cutoff_m;
  if (cfg.ospa_order > 0.0) loop.ospa_order = cfg.ospa_order;
  loop.progress_label = "compare " + spec.name;
  loop.progress = cfg.progress;

  CompareResult res;
  res.rows = run_loop(source, loop, {});
  static_cast<SummaryHeader&>(res) = res.rows.front();
  res.tracker.clear();
  res.ospa_cutoff_m = loop.ospa_cutoff_m;
  res.ospa_order = loop.ospa_order;
  // Measurements and truths are the same for every tracker (same scans).
  res.mean_measurements = res.rows.front().mean_measurements;
  res.mean_truths = res.rows.front().mean_truths;
  if (!cfg.out_dir.empty()) write_compare_outputs(res, cfg);
  return res;
}

void write_compare_outputs(const CompareResult& res, const CompareConfig& cfg) {
  std::filesystem::create_directories(cfg.out_dir);
  std::ofstream md(cfg.out_dir + "/compare.md");
  md << compare_to_markdown(res);
  std::ofstream js(cfg.out_dir + "/compare.json");
  js << compare_to_json(res).dump(2) << "\n";
  if (!md || !js) throw std::runtime_error(cfg.out_dir + ": cannot write compare.md/compare.json");
  if (!cfg.plot) return;
  std::vector<OspaSeries> series;
  for (const CompareRow& r : res.rows) series.push_back(OspaSeries{r.tracker, r.ospa_per_scan});
  write_ospa_comparison_svg(cfg.out_dir + "/ospa.svg",
                            res.scenario + ": OSPA over time, mean of " + std::to_string(cfg.runs) + " run(s)",
                            series, res.eval_first_scan, res.eval_last_scan, res.ospa_order, res.ospa_cutoff_m);
}

namespace {

// Track scores of one row (eval/track_scoring.h; docs/algorithms/metrics.md
// §Track scores): confirmation delay, breaks, switches, coverage, false tracks.
nlohmann::ordered_json track_scores_json(const TrackScoreTotals& t) {
  return {{"ttl_scans", t.ttl_scans()},
          {"report_delay_scans", t.report_delay_scans()},
          {"realtime_delay_scans", t.realtime_delay_scans()},
          {"track_breaks_per_target", t.per_target(t.track_breaks)},
          {"id_switches_per_target", t.per_target(t.id_switches)},
          {"fragmentations_per_target", t.per_target(t.fragmentations)},
          {"tpd", t.tpd()},
          {"nvt", t.nvt()},
          {"false_tracks_per_run", t.nft()},
          {"false_tracks_in_clutter_per_run", t.nft_in_clutter()},
          {"targets_never_tracked", t.targets - t.targets_tracked},
          {"coverage_from_birth5", t.settled_coverage()},
          {"min_target_coverage_from_birth5", t.settled_scans > 0 ? t.min_settled_coverage : 0.0},
          {"by_target", track_scores_by_target_json(t)}};
}

// The seed 003 Sec. IV-A columns of one row (docs/algorithms/metrics.md
// §AMOTA, §RMSE, §MOSPA with a Mahalanobis base distance).
nlohmann::ordered_json seed003_metrics_json(const CompareRow& x) {
  const TrackScoreTotals& t = x.track_scores;
  return {{"amota", t.amota()},
          {"amota_unscaled", t.amota_unscaled()},
          {"ids", t.per_target(t.id_switches)},
          {"frag", t.per_target(t.fragmentations)},
          {"rmse_range_m", t.rmse_range_m()},
          {"rmse_velocity_mps", t.rmse_velocity_mps()},
          {"mospa_mahalanobis", x.mean_ospa_mahalanobis},
          {"mospa", x.mean_ospa}};
}

std::string seed003_metrics_markdown(const CompareResult& r) {
  std::string s = "\n| tracker | AMOTA | IDS / target | Frag / target | RMSE range [m] | RMSE velocity [m/s] "
                  "| MOSPA (Mahalanobis) | MOSPA [m] |\n|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const CompareRow& x : r.rows) {
    const TrackScoreTotals& t = x.track_scores;
    s += "| " + x.tracker + " | " + fmt("%.3f", t.amota()) + " | " + fmt("%.3f", t.per_target(t.id_switches)) +
         " | " + fmt("%.3f", t.per_target(t.fragmentations)) + " | " + fmt("%.2f", t.rmse_range_m()) + " | " +
         fmt("%.3f", t.rmse_velocity_mps()) + " | " + fmt("%.2f", x.mean_ospa_mahalanobis) + " | " +
         fmt("%.2f", x.mean_ospa) + " |\n";
  }
  s += "\nseed 003 metrics (docs/algorithms/metrics.md): AMOTA = MOTA averaged over 40 recall thresholds of the "
       "track existence (Weng et al.), mean per run; RMSE over target-scans covered by a valid track; MOSPA "
       "(Mahalanobis) = OSPA with base distance in (range, range rate) whitened by the scenario's noise, "
       "p = 2, c = 9.4.\n";
  return s;
}

// Per target id (scenes of at most kMaxTargetColumns targets): where a
// scene has one hard target (a birth inside clutter, a crossing in chaff),
// the pooled means above hide it.
std::string track_scores_by_target_markdown(const CompareResult& r) {
  constexpr std::size_t kMaxTargetColumns = 8;
  if (r.rows.empty()) return "";
  const auto& ids = r.rows.front().track_scores.delay_by_target;
  if (ids.empty() || ids.size() > kMaxTargetColumns) return "";
  std::string s = "\n| tracker |", rule = "|---|";
  for (const auto& [id, d] : ids) {
    s += " target " + std::to_string(id) + ": TTL / report delay / real-time delay [scans] (never) / coverage from birth + 5 |";
    rule += "---:|";
  }
  s += "\n" + rule + "\n";
  for (const CompareRow& x : r.rows) {
    const TrackScoreTotals& t = x.track_scores;
    s += "| " + x.tracker + " |";
    for (const auto& [id, d0] : ids) {
      const auto it = t.delay_by_target.find(id);
      const std::uint64_t never = it == t.delay_by_target.end() ? 0 : it->second.never_tracked;
      s += " " + fmt("%.2f", t.ttl_scans_of(id)) + " / " + fmt("%.2f", t.report_delay_scans_of(id)) + " / " +
           fmt("%.2f", t.realtime_delay_scans_of(id)) + " (" +
           std::to_string(never) + ") / " + fmt("%.3f", t.settled_coverage_of(id)) + " |";
    }
    s += "\n";
  }
  s += "\nPer target over runs: TTL, report delay and real-time delay of the runs it was tracked in, (never) the runs "
       "it was not.\n";
  return s;
}

std::string track_scores_markdown(const CompareResult& r) {
  std::string s = "\n| tracker | TTL [scans] | report delay [scans] | real-time delay [scans] | breaks / target | ID switches / target | TPD | NVT "
                  "| false tracks / run (in clutter) | targets never tracked | coverage from birth + 5 (worst target) |\n"
                  "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const CompareRow& x : r.rows) {
    const TrackScoreTotals& t = x.track_scores;
    s += "| " + x.tracker + " | " + fmt("%.2f", t.ttl_scans()) + " | " + fmt("%.2f", t.report_delay_scans()) + " | " +
         fmt("%.2f", t.realtime_delay_scans()) + " | " +
         fmt("%.3f", t.per_target(t.track_breaks)) +
         " | " + fmt("%.3f", t.per_target(t.id_switches)) + " | " + fmt("%.3f", t.tpd()) + " | " +
         fmt("%.2f", t.nvt()) + " | " + fmt("%.2f", t.nft()) + " (" + fmt("%.2f", t.nft_in_clutter()) + ") | " +
         std::to_string(t.targets - t.targets_tracked) +
         " | " + fmt("%.3f", t.settled_coverage()) + " (" +
         fmt("%.3f", t.settled_scans > 0 ? t.min_settled_coverage : 0.0) + ") |\n";
  }
  s += "\nTrack scores (host-sim/src/eval/track_scoring.h, docs/algorithms/metrics.md): TTL = scans from a "
       "target's birth to the first scan its confirmed track covers, report delay = to the scan after whose step() that "
       "track was first handed out (TTL plus the tracker's output lag: a smoother reports a scan K - s to K - 1 scans "
       "late); real-time delay = to the first scan whose own step() handed out a confirmed track on it (a filter's "
       "estimate, a smoother's provisional one: docs/algorithms/mfbp.md §Provisional output); a break = its track ended and a new ID took over; TPD = "
       "fraction of its alive scans covered by a confirmed track; coverage from birth + 5 = the same over the scans from 5 "
       "after its birth on, pooled (in brackets: the worst target of any run); false tracks in clutter = those first "
       "confirmed inside the 95 % ellipse of a Gaussian clutter component of the scenario.\n";
  return s + track_scores_by_target_markdown(r);
}

// Every row against the first, run by run (eval/paired.h): whether a mean
// OSPA difference is clear of the Monte Carlo noise.
std::string paired_ospa_markdown(const CompareResult& r) {
  if (r.rows.size() < 2 || r.runs < 2) return "";
  const CompareRow& ref = r.rows.front();
  std::string s = "\n| tracker | OSPA - " + ref.tracker + " [m], paired per run: mean +- standard error (runs lower) |\n"
                  "|---|---|\n";
  for (std::size_t i = 1; i < r.rows.size(); ++i) {
    s += "| " + r.rows[i].tracker + " | " +
         paired_difference_text(paired_difference(r.rows[i].ospa_per_run, ref.ospa_per_run), 2) + " |\n";
  }
  s += "\nPaired differences (docs/algorithms/metrics.md §Paired differences): every tracker ran on the same scenes, "
       "so the difference of each run's mean OSPA is taken run by run; a difference within about 2 standard "
       "errors of 0 is Monte Carlo noise.\n";
  return s;
}

// Real-time OSPA of a row, with the share of evaluation scans it covers when not all.
std::string realtime_ospa_cell(const CompareRow& x) {
  std::string c = fmt("%.2f", x.mean_realtime_ospa);
  if (x.realtime_scan_fraction < 0.9995) c += " (" + fmt("%.2f", x.realtime_scan_fraction) + ")";
  return c;
}

}  // namespace

nlohmann::ordered_json compare_to_json(const CompareResult& r) {
  using json = nlohmann::ordered_json;
  json rows = json::array();
  for (const CompareRow& x : r.rows) {
    rows.push_back({{"tracker", x.tracker},
                    {"mean_ospa", x.mean_ospa},
                    {"realtime_ospa", x.mean_realtime_ospa},
                    {"realtime_scan_fraction", x.realtime_scan_fraction},
                    {"mean_gospa", x.mean_gospa},
                    {"gospa_localisation", x.gospa_localisation},
                    {"gospa_missed", x.gospa_missed},
                    {"gospa_false", x.gospa_false},
                    {"missed_per_scan", x.missed_per_scan},
                    {"false_per_scan", x.false_per_scan},
                    {"cardinality_error", x.cardinality_error},
                    {"nft", x.nft},
                    {"mean_confirmed", x.mean_confirmed_tracks},
                    {"latency_us",
                     {{"p50", x.latency.p50_us},
                      {"p99", x.latency.p99_us},
                      {"max", x.latency.max_us},
                      {"mean", x.latency.mean_us},
                      {"samples", x.latency.count}}},
                    {"step_errors", x.step_errors},
                    {"steps_not_ok", x.steps_not_ok()},
                    {"steps_mixture_truncated", x.steps_truncating},
                    {"measurement_checksum", hex64(x.measurement_checksum)},
                    {"track_scores", track_scores_json(x.track_scores)},
                    {"seed003_metrics", seed003_metrics_json(x)},
                    {"ospa_per_scan", x.ospa_per_scan},
                    {"ospa_per_run", x.ospa_per_run}});
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
  s += "| tracker | OSPA [m] | real-time OSPA [m] | GOSPA [m] | GOSPA loc [m^" + p + "] | GOSPA missed [m^" + p + "] | GOSPA false [m^" +
       p + "] | card. error | NFT | latency p50 [us] | p99 [us] | max [us] | errors | checksum |\n";
  s += "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
  for (const CompareRow& x : r.rows) {
    s += "| " + x.tracker + " | " + fmt("%.2f", x.mean_ospa) + " | " + realtime_ospa_cell(x) + " | " +
         fmt("%.2f", x.mean_gospa) + " | " +
         fmt("%.4g", x.gospa_localisation) + " | " + fmt("%.4g", x.gospa_missed) + " | " +
         fmt("%.4g", x.gospa_false) + " | " + fmt("%.3f", x.cardinality_error) + " | " + fmt("%.3f", x.nft) +
         " | " + fmt("%.1f", x.latency.p50_us) + " | " + fmt("%.1f", x.latency.p99_us) + " | " +
         fmt("%.1f", x.latency.max_us) + " | " + std::to_string(x.step_errors) + " | " +
         hex64(x.measurement_checksum).substr(0, 8) + " |\n";
  }
  s += "\nColumns: means per evaluation scan over all runs. Real-time OSPA: of each step's estimate of its own scan "
       "(a smoother's provisional one, docs/algorithms/mfbp.md §Provisional output), over the scans that have one "
       "(in brackets, their share where it is not all). GOSPA components sum to GOSPA^p per scan "
       "(missed/false = c^p/2 per unassigned truth/track). card. error = |#confirmed - #targets|; NFT = confirmed "
       "tracks with no target within c. Latency: wall time of one step() on this host (a smoother's p50 is a "
       "buffering step). errors: steps returning an error status.\n";
  s += paired_ospa_markdown(r);
  s += track_scores_markdown(r);
  s += seed003_metrics_markdown(r);
  return s;
}

}  // namespace mptrack::sim
