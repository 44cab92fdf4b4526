// Dataset builder (docs/algorithms/sea_clutter.md §Dataset).
#include "mptrack/sea/sea_dataset.h"

#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "mptrack/scenario/rng.h"
#include "mptrack/sea/npy_writer.h"
#include "mptrack/seaclutter/sea_detector.h"

namespace mptrack::sea {

int label_plot(double range_m, double doppler_bin, const std::vector<SeaTruth>& truth, const LabelRule& rule) {
  for (std::size_t i = 0; i < truth.size(); ++i) {
    if (std::fabs(range_m - truth[i].range_m) <= rule.max_range_m &&
        std::fabs(doppler_bin - truth[i].doppler_bin) <= rule.max_doppler_bins) {
      return static_cast<int>(i);
    }
  }
  return -1;
}

seaclutter::SeaDetectorParams detector_params_for(const SeaScenario& s) {
  seaclutter::SeaDetectorParams p;
  p.carrier_hz = s.carrier_hz;
  p.prf_hz = s.prf_hz;
  p.range_bin_m = s.range_bin_m;
  return p;
}

namespace {

struct Columns {
  std::vector<std::uint8_t> patches, labels;
  std::vector<float> scr_db, belief, plot;
  std::vector<std::int32_t> scene, run, scan, target;
};

constexpr std::size_t kPlotColumns = 7;  // range_m, doppler_hz, range_rate_mps, amplitude, range_bin, doppler_bin, cells

void write_meta(const DatasetConfig& c, const DatasetCounts& n, std::size_t rows) {
  const std::string path = c.out_dir + "/meta.json";
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (f == nullptr) throw std::runtime_error("cannot write " + path);
  std::fprintf(f,
               "{\n  \"format\": \"mptrack-sea-dataset/1\",\n  \"scenario\": \"%s\",\n  \"seed\": %llu,\n"
               "  \"runs\": %u,\n  \"run_offset\": %u,\n  \"scr_min_db\": %g,\n  \"scr_max_db\": %g,\n"
               "  \"scr_step_db\": %g,\n  \"beliefs\": \"%s\",\n  \"rows\": %zu,\n  \"target_rows\": %llu,\n  \"scenes\": %llu,\n"
               "  \"scans\": %llu,\n  \"truth_detected\": %llu,\n  \"truth_total\": %llu,\n"
               "  \"partial_scans\": %llu,\n  \"clusters\": %llu,\n  \"cfar_detections\": %llu,\n"
               "  \"label_rule\": {\"max_range_m\": %g, \"max_doppler_bins\": %g},\n"
               "  \"detector\": {\"cfar\": \"CA along range\", \"pfa\": %g, \"guard\": %zu, \"training_per_side\": %zu,"
               " \"eps_range_bins\": %zu, \"eps_doppler_bins\": %zu, \"min_points\": %zu,"
               " \"patch_floor_db\": %g, \"patch_span_db\": %g},\n"
               "  \"files\": {\"patches.npy\": \"uint8 (N, 5, 512) [range][doppler], code = floor((10 log10(P/median)"
               " - floor_db) * 255 / span_db) clipped\", \"labels.npy\": \"uint8 (N,) 1 = target\","
               " \"scr_db.npy\": \"float32 (N,)\", \"scene.npy\": \"int32 (N,) scr_index * runs + run index\","
               " \"run.npy\": \"int32 (N,)\", \"scan.npy\": \"int32 (N,)\", \"target.npy\": \"int32 (N,) target index or -1\","
               " \"belief.npy\": \"float32 (N,) tracker association belief P(target-originated), source under beliefs, 0.5 if none\","
               " \"plot.npy\": \"float32 (N, 7) range_m, doppler_hz, range_rate_mps, amplitude, range_bin,"
               " doppler_bin, cells\"}\n}\n",
               c.scenario.name.c_str(), static_cast<unsigned long long>(c.seed), c.runs, c.run_offset, c.scr_min_db,
               c.scr_max_db, c.scr_step_db, c.beliefs ? c.beliefs_source.c_str() : "placeholder 0.5", rows, static_cast<unsigned long long>(n.targets),
               static_cast<unsigned long long>(n.scenes), static_cast<unsigned long long>(n.scans),
               static_cast<unsigned long long>(n.truth_detected), static_cast<unsigned long long>(n.truth_total),
               static_cast<unsigned long long>(n.partial_scans), static_cast<unsigned long long>(n.clusters),
               static_cast<unsigned long long>(n.detections), c.label.max_range_m, c.label.max_doppler_bins,
               c.detector.cfar.pfa, c.detector.cfar.guard_cells, c.detector.cfar.training_cells,
               c.detector.eps_range_bins, c.detector.eps_doppler_bins, c.detector.min_points,
               c.detector.patch_floor_db, c.detector.patch_span_db);
  std::fclose(f);
}

void write_columns(const DatasetConfig& c, const Columns& col) {
  const std::uint64_t n = col.labels.size();
  const std::string d = c.out_dir + "/";
  write_npy(d + "patches.npy", col.patches, {n, 5, 512});
  write_npy(d + "labels.npy", col.labels, {n});
  write_npy(d + "scr_db.npy", col.scr_db, {n});
  write_npy(d + "scene.npy", col.scene, {n});
  write_npy(d + "run.npy", col.run, {n});
  write_npy(d + "scan.npy", col.scan, {n});
  write_npy(d + "target.npy", col.target, {n});
  write_npy(d + "belief.npy", col.belief, {n});
  write_npy(d + "plot.npy", col.plot, {n, kPlotColumns});
}

/// Writes a scene's tracker beliefs over its rows (placed scan by scan,
/// plot by plot from first_row).
void fill_beliefs(const SceneBeliefs& b, const ScenePlots& scene, std::size_t first_row, std::vector<float>& out) {
  std::size_t row = first_row;
  for (std::size_t k = 0; k < scene.plots.size(); ++k) {
    for (std::size_t j = 0; j < scene.plots[k].size(); ++j, ++row) {
      if (k < b.size() && j < b[k].size()) out[row] = b[k][j];
    }
  }
}

}  // namespace

DatasetCounts build_dataset(const DatasetConfig& config) {
  using Detector = seaclutter::SeaDetector<seaclutter::SeaClutterCaps>;
  static_assert(seaclutter::SeaClutterCaps::kPatchRangeBins == 5 && seaclutter::SeaClutterCaps::kDopplerBins == 512,
                "dataset layout is 5 x 512");
  auto det = std::make_unique<Detector>();
  if (det->init(config.detector) != Status::kOk) throw std::invalid_argument("invalid detector parameters");
  if (config.scenario.range_bins != Detector::kRange) throw std::invalid_argument("scenario range_bins != 96");
  if (!(config.scr_step_db > 0.0)) throw std::invalid_argument("--scr-step must be > 0");
  Columns col;
  DatasetCounts n;
  const int levels = static_cast<int>(std::floor((config.scr_max_db - config.scr_min_db) / config.scr_step_db + 1e-9)) + 1;
  for (int li = 0; li < levels; ++li) {
    SeaScenario sc = config.scenario;
    sc.scr_db = config.scr_min_db + li * config.scr_step_db;
    for (std::uint32_t r = 0; r < config.runs; ++r) {
      const std::uint32_t run = config.run_offset + r;
      // The same clutter and trajectories at every SCR (the paper injects
      // targets into fixed clutter recordings); runs differ.
      SeaSceneGenerator gen(sc, scenario::derive_seed(config.seed, run));
      SeaScan scan;
      ++n.scenes;
      const std::size_t first_row = col.labels.size();
      ScenePlots scene;
      while (gen.next(scan)) {
        scene.time_s.push_back(scan.time_s + 0.5 * static_cast<double>(sc.pulses) / sc.prf_hz);
        scene.plots.emplace_back();
        scene.patches.emplace_back();
        ++n.scans;
        const Status st = det->process(scan.re.data(), scan.im.data());
        if (st == Status::kPartial) ++n.partial_scans;
        else if (st != Status::kOk) throw std::runtime_error("detector failed");
        std::vector<bool> seen(scan.truth.size(), false);
        for (std::size_t j = 0; j < det->num_plots(); ++j) {
          const seaclutter::SeaPlot& p = det->plot(j);
          scene.plots.back().push_back(p);
          const int t = label_plot(static_cast<double>(p.range_m), static_cast<double>(p.doppler_bin), scan.truth,
                                   config.label);
          if (t >= 0) seen[static_cast<std::size_t>(t)] = true;
          const auto& patch = det->patch(j);
          col.patches.insert(col.patches.end(), patch.begin(), patch.end());
          scene.patches.back().insert(scene.patches.back().end(), patch.begin(), patch.end());
          col.labels.push_back(t >= 0 ? 1 : 0);
          col.target.push_back(t);
          col.scr_db.push_back(static_cast<float>(sc.scr_db));
          col.scene.push_back(static_cast<std::int32_t>(static_cast<std::uint32_t>(li) * config.runs + r));
          col.run.push_back(static_cast<std::int32_t>(run));
          col.scan.push_back(static_cast<std::int32_t>(scan.index));
          col.belief.push_back(0.5f);
          const float row[kPlotColumns] = {p.range_m, p.doppler_hz, p.range_rate_mps, p.amplitude,
                                           p.range_bin, p.doppler_bin, static_cast<float>(p.cells)};
          col.plot.insert(col.plot.end(), row, row + kPlotColumns);
          n.targets += t >= 0 ? 1 : 0;
        }
        n.plots += det->num_plots();
        n.clusters += det->clusters();
        n.detections += det->detections();
        n.truth_total += scan.truth.size();
        for (bool s : seen) n.truth_detected += s ? 1 : 0;
      }
      if (config.beliefs) fill_beliefs(config.beliefs(sc, scene), scene, first_row, col.belief);
    }
  }
  if (!config.out_dir.empty()) {
    write_columns(config, col);
    write_meta(config, n, col.labels.size());
  }
  return n;
}

}  // namespace mptrack::sea
