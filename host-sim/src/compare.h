// `mptrack-sim compare`: every selected tracker on identical measurement
// sets, side by side (seed 001 baselines).
//
// The run loop (run/run_loop.h) with several trackers: per run r the scans
// are generated ONCE (stream derive_seed(seed, r, k)) and the same SimScan
// objects are fed to every tracker, so the trackers cannot see different
// data; a 64-bit checksum of every measurement handed to each tracker is kept
// per tracker to prove it (all rows must carry the same one).
//
// Metrics per evaluation scan, averaged over runs x evaluation scans:
// OSPA, GOSPA and its three components (localisation / missed / false, in
// m^p, mean GOSPA^p = loc + missed + false), cardinality error |#confirmed -
// #truths|, NFT (confirmed tracks with no truth within c), and the wall time
// of each step() (p50/p99/max over all scans of all runs).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "mptrack/scenario/generator.h"
#include "mptrack/scenario/scenario_spec.h"
#include "eval/aggregator.h"

namespace mptrack::sim {

struct CompareConfig {
  scenario::ScenarioSpec spec;
  std::vector<std::string> trackers;  ///< empty = default_compare_trackers(spec)
  std::uint32_t runs = 1;
  std::uint64_t seed = 1;
  double clutter_scale = 1.0;
  std::vector<std::string> mfbp_params;  ///< MfbpParams overrides "name=value" (MF-BP trackers)
  std::vector<std::string> rfs_params;   ///< RfsFilterParams overrides "name=value" (gmphd, gmcphd, cbmember)
  double ospa_cutoff_m = 0.0;         ///< c [m]; 0 = the scenario's (see default_ospa())
  double ospa_order = 0.0;            ///< p; 0 = the scenario's
  std::string out_dir;                ///< "" = write nothing
  bool plot = true;                   ///< DIR/ospa.svg
  bool progress = true;
};

/// One tracker's row of the table: its aggregator summary (the columns are
/// the means per evaluation scan, latency, step_errors, steps_not_ok(),
/// measurement_checksum and ospa_per_scan).
using CompareRow = Summary;

/// The table: what was run (SummaryHeader; `tracker` is empty, one per row)
/// and one row per tracker.
struct CompareResult : SummaryHeader {
  double ospa_cutoff_m = 0.0, ospa_order = 0.0;
  double mean_measurements = 0.0;     ///< per scan
  double mean_truths = 0.0;           ///< per evaluation scan
  std::vector<CompareRow> rows;       ///< in tracker order
};

/// OSPA/GOSPA (c, p) of a scenario: seed 001 (Cartesian) c = 300 m, p = 1
/// (seed 001 Sec. 5); otherwise seed 000 Sec. IV-A, c = 631 m, p = 2.
void default_ospa(const scenario::ScenarioSpec& spec, double& cutoff_m, double& order);

/// Default tracker list: the built trackers among mfbp, mfbp-filter, gmphd,
/// gmcphd, cbmember (+ their -known fixed-clutter variants), gnn. Cartesian
/// scenarios: only the IGGM filters (estimated vs known clutter), since
/// MF-BP and GNN model a polar sensor.
std::vector<std::string> default_compare_trackers(const scenario::ScenarioSpec& spec);

/// "a,b,c" -> {a, b, c}; empty items are errors (throws std::runtime_error).
std::vector<std::string> parse_tracker_list(const std::string& text);

/// Runs the comparison; writes DIR/compare.md, DIR/compare.json and
/// DIR/ospa.svg when out_dir is set. Throws std::runtime_error on a bad
/// configuration (unknown tracker, invalid scenario).
CompareResult run_compare(const CompareConfig& config);

/// DIR/compare.md, DIR/compare.json and (cfg.plot) DIR/ospa.svg.
void write_compare_outputs(const CompareResult& result, const CompareConfig& config);

nlohmann::ordered_json compare_to_json(const CompareResult& r);
std::string compare_to_markdown(const CompareResult& r);

}  // namespace mptrack::sim
