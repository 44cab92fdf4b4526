// Monte Carlo on the seed 003 sea scenes; see sea_runner.h.
#include "sea_runner.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "mptrack/classify/sea_classifier.h"
#include "mptrack/sea/npy_writer.h"
#include "run/run_outputs.h"
#include "run/sea_source.h"
#include "writers.h"

namespace mptrack::sim {

double SeaTrackErrors::rmse_range_m() const {
  return matched == 0 ? 0.0 : std::sqrt(sum_sq_range_m2 / static_cast<double>(matched));
}
double SeaTrackErrors::rmse_velocity_mps() const {
  return matched == 0 ? 0.0 : std::sqrt(sum_sq_rate_m2ps2 / static_cast<double>(matched));
}

double match_range_std_m(const sea::SeaScenario& s) { return s.range_bin_m; }
double match_rate_std_mps(const sea::SeaScenario& s) { return s.doppler_bin_mps(); }

FeatureExtractor sea_features_for(const std::vector<std::string>& trackers, FeatureExtractor precision) {
  for (const std::string& t : trackers) {
    if (t == "mfbp-nn" || t == "nemp") return precision;
  }
  return FeatureExtractor::kNone;
}

namespace {

/// Range / range-rate errors of each tracker (sea_runner.h), and the plot
/// counts of the scans.
class SeaErrorObserver final : public RunObserver {
 public:
  SeaErrorObserver(std::size_t trackers, double range_std_m, double rate_std_mps)
      : errors(trackers), range_std_m_(range_std_m), rate_std_mps_(rate_std_mps) {}
  void on_run(std::size_t tracker, const std::vector<scenario::SimScan>& scans, const RunRecord& record,
              const std::vector<ScanMetrics>& /*metrics*/) override {
    for (std::size_t k = 0; k < scans.size() && k < record.by_scan.size(); ++k) {
      add_scan(errors[tracker], scans[k], record.by_scan[k], range_std_m_, rate_std_mps_);
      if (tracker != 0) continue;
      ++scans_seen;
      plots += scans[k].measurements.size();
      for (const auto& m : scans[k].measurements) target_plots += m.origin.kind == scenario::OriginKind::kTarget ? 1 : 0;
    }
  }
  std::vector<SeaTrackErrors> errors;
  std::uint64_t scans_seen = 0, plots = 0, target_plots = 0;
  double range_std_m_ = 15.0, rate_std_mps_ = 0.03;

 private:
  // Greedy pairing by the Mahalanobis distance of seed 003's MOSPA (range
  // and range rate, our measurement deviations) within c = 9.4, each
  // confirmed track once.
  static void add_scan(SeaTrackErrors& e, const scenario::SimScan& scan, const EstimateOut& est, double sr,
                       double sv) {
    struct Pair {
      double d;
      std::size_t t, k;
    };
    std::vector<Pair> pairs;
    for (std::size_t t = 0; t < scan.truth.size(); ++t) {
      for (std::size_t k = 0; k < est.tracks.size(); ++k) {
        if (!est.tracks[k].confirmed) continue;
        const double dr = (est.tracks[k].px - scan.truth[t].x.px) / sr;
        const double dv = (est.tracks[k].vx - scan.truth[t].x.vx) / sv;
        const double d = std::sqrt(dr * dr + dv * dv);
        if (d <= kSeaMatchCutoff) pairs.push_back({d, t, k});
      }
    }
    std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) {
      return a.d != b.d ? a.d < b.d : (a.t != b.t ? a.t < b.t : a.k < b.k);
    });
    std::vector<bool> truth_used(scan.truth.size(), false), track_used(est.tracks.size(), false);
    for (const Pair& p : pairs) {
      if (truth_used[p.t] || track_used[p.k]) continue;
      truth_used[p.t] = track_used[p.k] = true;
      const double dr = est.tracks[p.k].px - scan.truth[p.t].x.px;
      const double dv = est.tracks[p.k].vx - scan.truth[p.t].x.vx;
      e.sum_sq_range_m2 += dr * dr;
      e.sum_sq_rate_m2ps2 += dv * dv;
      ++e.matched;
    }
    e.truths += scan.truth.size();
  }
};

LoopConfig sea_loop(const SeaScanSource& source, const std::vector<std::string>& trackers, std::uint32_t runs,
                    std::uint64_t seed, const std::vector<std::string>& mfbp_params, bool progress) {
  LoopConfig loop;
  loop.trackers = trackers;
  loop.runs = runs;
  loop.seed = seed;
  loop.mfbp_params = mfbp_params;
  loop.ospa_cutoff_m = kSeaOspaCutoff_m;
  loop.ospa_order = kSeaOspaOrder;
  char label[96];
  std::snprintf(label, sizeof label, "%s SCR %g dB", source.sea_scenario().name.c_str(), source.sea_scenario().scr_db);
  loop.progress_label = label;
  loop.progress = progress;
  loop.sea_scenario = std::make_shared<const sea::SeaScenario>(source.sea_scenario());
  return loop;
}

std::vector<SeaSummary> finish(const std::vector<Summary>& base, const SeaScanSource& source,
                               const SeaErrorObserver& obs) {
  std::vector<SeaSummary> out(base.size());
  const double n = obs.scans_seen > 0 ? static_cast<double>(obs.scans_seen) : 1.0;
  for (std::size_t t = 0; t < base.size(); ++t) {
    out[t].base = base[t];
    out[t].scr_db = source.sea_scenario().scr_db;
    out[t].errors = obs.errors[t];
    out[t].plots_per_scan = static_cast<double>(obs.plots) / n;
    out[t].target_plots_per_scan = static_cast<double>(obs.target_plots) / n;
    out[t].feature_us_per_detection = source.feature_us_per_detection();
  }
  return out;
}

/// DIR/rd_map.npy (float32 [range][Doppler] dB), DIR/rd_map.json and
/// DIR/sea_detections.csv (run 0: every plot with its Doppler, origin and
/// classifier output at an uninformative belief) for host-sim/plots/sea_rd_map.py.
void write_map_files(const std::string& dir, const SeaScanSource& source, const std::vector<scenario::SimScan>& run0) {
  const sea::SeaScenario& s = source.sea_scenario();
  const SeaMapSnapshot& m = source.map_snapshot();
  if (m.scan != 0) {
    sea::write_npy(dir + "/rd_map.npy", m.power_db, {m.range_bins, m.doppler_bins});
  }
  std::ofstream js(dir + "/rd_map.json");
  js << nlohmann::ordered_json{{"scenario", s.name},
                               {"scr_db", s.scr_db},
                               {"scan", m.scan},
                               {"range_bins", s.range_bins},
                               {"range_bin_m", s.range_bin_m},
                               {"doppler_bins", s.pulses},
                               {"doppler_bin_hz", s.doppler_bin_hz()},
                               {"prf_hz", s.prf_hz},
                               {"wavelength_m", s.wavelength_m()},
                               {"map", "rd_map.npy: float32 (range_bins, doppler_bins), 10 log10 power, "
                                       "Doppler bin d is (d - doppler_bins/2) * doppler_bin_hz"}}
            .dump(2)
     << "\n";
  std::ofstream csv(dir + "/sea_detections.csv");
  csv << "run,scan,index,range_m,doppler_hz,range_rate_mps,amplitude,target_id\n";
  for (const scenario::SimScan& sc : run0) {
    for (std::size_t j = 0; j < sc.measurements.size(); ++j) {
      const scenario::SimMeasurement& x = sc.measurements[j];
      const double dop_hz = -2.0 * x.doppler_mps / s.wavelength_m();
      char line[160];
      std::snprintf(line, sizeof line, "0,%u,%zu,%.3f,%.4f,%.5f,%.4f,%u\n", sc.scan, j, x.range_m, dop_hz,
                    x.doppler_mps, x.amplitude, x.origin.kind == scenario::OriginKind::kTarget ? x.origin.id : 0U);
      csv << line;
    }
  }
  if (!js || !csv) throw std::runtime_error(dir + ": cannot write the range-Doppler map files");
}

}  // namespace

SeaSummary run_sea_monte_carlo(const SeaRunConfig& cfg) {
  const std::vector<std::string> trackers{cfg.tracker};
  SeaScanSource source(cfg.scenario, cfg.seed, sea_features_for(trackers, cfg.classifier), cfg.map_scan);
  LoopConfig loop = sea_loop(source, trackers, cfg.runs, cfg.seed, cfg.mfbp_params, cfg.progress);
  check_loop_config(loop);  // before the output directory is created
  RunOutputs outputs(cfg, source.spec());
  SeaErrorObserver errors(1, match_range_std_m(cfg.scenario), match_rate_std_mps(cfg.scenario));
  FirstRunKeeper first;
  std::vector<RunObserver*> observers = outputs.observers();
  observers.push_back(&errors);
  observers.push_back(&first);
  const SeaSummary sum = finish(run_loop(source, loop, observers), source, errors).front();
  if (!cfg.out_dir.empty()) {
    std::ofstream f(cfg.out_dir + "/summary.json");
    if (!f) throw std::runtime_error(cfg.out_dir + "/summary.json: cannot write");
    f << sea_summary_to_json(sum).dump(2) << "\n";
    write_map_files(cfg.out_dir, source, first.scans);
  }
  outputs.write_detections();
  char title[160];
  std::snprintf(title, sizeof title, "%s SCR %g dB / %s (run 0; OSPA mean of %u runs)", cfg.scenario.name.c_str(),
                cfg.scenario.scr_db, cfg.tracker.c_str(), cfg.runs);
  outputs.write_plot(sum.base.ospa_per_scan, title, kSeaOspaOrder, kSeaOspaCutoff_m);
  return sum;
}

std::vector<std::vector<SeaSummary>> run_sea_compare(const SeaCompareConfig& cfg) {
  const std::vector<std::string> trackers =
      cfg.trackers.empty() ? std::vector<std::string>{"mfbp", "mfbp-nn", "nemp"} : cfg.trackers;
  std::vector<std::vector<SeaSummary>> out;
  for (double scr : cfg.scr_db) {
    sea::SeaScenario sc = cfg.scenario;
    sc.scr_db = scr;
    SeaScanSource source(sc, cfg.seed, sea_features_for(trackers, cfg.classifier), 0);
    const LoopConfig loop = sea_loop(source, trackers, cfg.runs, cfg.seed, cfg.mfbp_params, cfg.progress);
    SeaErrorObserver errors(trackers.size(), match_range_std_m(sc), match_rate_std_mps(sc));
    out.push_back(finish(run_loop(source, loop, {&errors}), source, errors));
  }
  return out;
}

}  // namespace mptrack::sim
