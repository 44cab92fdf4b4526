// Seed 003 sea scenes as a scan source; see sea_source.h.
#include "run/sea_source.h"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "mptrack/classify/sea_classifier.h"
#include "mptrack/classify/sea_features_q8.h"
#include "mptrack/classify/trained_weights.h"
#include "mptrack/scenario/generator.h"
#include "mptrack/scenario/rng.h"
#include "mptrack/sea/sea_dataset.h"
#include "mptrack/seaclutter/sea_detector.h"

namespace mptrack::sim {

namespace {

using Detector = seaclutter::SeaDetector<seaclutter::SeaClutterCaps>;
constexpr std::size_t kPatchCodes = seaclutter::SeaClutterCaps::kPatchRangeBins * seaclutter::SeaClutterCaps::kDopplerBins;
static_assert(kPatchCodes == classify::kPatchSize, "the classifier reads the detector's 5 x 512 patch");

}  // namespace

struct SeaScanSource::Chain {
  Detector detector;
  classify::SeaClassifier classifier;
  classify::SeaFeaturesQ8 classifier_q8;
  FeatureExtractor features = FeatureExtractor::kNone;
  std::array<float, kPatchCodes> patch{};
};

scenario::ScenarioSpec sea_spec_view(const sea::SeaScenario& s) {
  scenario::ScenarioSpec spec;
  spec.name = s.name;
  spec.description = s.description;
  spec.num_scans = s.num_scans;
  spec.scan_period_s = s.scan_period_s;
  spec.eval_first_scan = 1;
  spec.eval_last_scan = s.num_scans;
  // Bin m is centred at m * range_bin_m; a positive lower bound (the region
  // is polar), half a bin past the last bin.
  spec.region.range_min_m = 1.0;
  spec.region.range_max_m = (static_cast<double>(s.range_bins) - 0.5) * s.range_bin_m;
  spec.region.azimuth_min_deg = -1.0;
  spec.region.azimuth_max_deg = 1.0;
  spec.sigma_range_m = s.range_bin_m;  // seed 003 eq. (4): R = diag(15^2 m^2, .)
  spec.sigma_azimuth_deg = 0.5;        // every plot is at azimuth 0: any positive value
  // The range-rate half of R: one Doppler bin, as the trackers assume
  // (trackers/sea_setup.h). The Mahalanobis MOSPA whitens with both halves
  // (docs/algorithms/metrics.md); the field is named for OTHR, its first user.
  spec.othr.sigma_range_rate_mps = s.doppler_bin_mps();
  spec.threshold = 1.0;                // unused (the sea trackers run without amplitude)
  spec.space = scenario::MeasurementSpace::kPolar;
  return spec;
}

bool is_sea_scenario(const std::string& name) {
  sea::SeaScenario s;
  return sea::builtin_sea_scenario(name, s);
}

SeaScanSource::SeaScanSource(const sea::SeaScenario& scenario, std::uint64_t seed, FeatureExtractor features,
                             std::uint32_t map_scan)
    : sea_(scenario), spec_(sea_spec_view(scenario)), seed_(seed), map_scan_(map_scan),
      chain_(std::make_unique<Chain>()) {
  const std::string error = sea_.validate();
  if (!error.empty()) throw std::runtime_error("sea scenario " + sea_.name + ": invalid " + error);
  if (sea_.range_bins != Detector::kRange) throw std::runtime_error("sea scenario: range_bins must be 96");
  if (chain_->detector.init(sea::detector_params_for(sea_)) != Status::kOk) {
    throw std::runtime_error("sea detector: invalid parameters");
  }
  if (features == FeatureExtractor::kFloat &&
      (!classify::kHaveTrainedWeights || chain_->classifier.init(classify::trained_weights()) != Status::kOk)) {
    throw std::runtime_error("the classifier needs trained weights (./run train-classifier)");
  }
  if (features == FeatureExtractor::kInt8 &&
      (!classify::kHaveTrainedQ8Weights || chain_->classifier_q8.init(classify::trained_q8_weights()) != Status::kOk)) {
    throw std::runtime_error("--classifier int8 needs the quantised weights (./run quantise-classifier)");
  }
  chain_->features = features;
}

SeaScanSource::~SeaScanSource() = default;

double SeaScanSource::feature_us_per_detection() const {
  return feature_count_ == 0 ? 0.0 : feature_us_ / static_cast<double>(feature_count_);
}

void SeaScanSource::begin_run(std::uint32_t run) {
  // Run r is the scene of seed derive_seed(seed, r), as in the dataset
  // (sea_dataset.cpp): the same clutter and trajectories at every SCR.
  sea::SeaSceneGenerator gen(sea_, scenario::derive_seed(seed_, run));
  scans_.assign(sea_.num_scans, scenario::SimScan{});
  sea::SeaScan scan;
  for (std::uint32_t k = 1; gen.next(scan) && k <= sea_.num_scans; ++k) {
    const Status st = chain_->detector.process(scan.re.data(), scan.im.data());
    if (st != Status::kOk && st != Status::kPartial) throw std::runtime_error("sea detector failed");
    fill_scan(scan, scans_[k - 1]);
    if (run == 0 && k == map_scan_) {
      const auto& m = chain_->detector.map();
      map_.scan = k;
      map_.range_bins = static_cast<std::uint32_t>(Detector::kRange);
      map_.doppler_bins = static_cast<std::uint32_t>(Detector::kDoppler);
      map_.power_db.assign(Detector::kRange * Detector::kDoppler, 0.0f);
      for (std::size_t r = 0; r < Detector::kRange; ++r) {
        for (std::size_t d = 0; d < Detector::kDoppler; ++d) {
          const double p = static_cast<double>(m.power(r, d));
          map_.power_db[r * Detector::kDoppler + d] = static_cast<float>(10.0 * std::log10(p > 1e-30 ? p : 1e-30));
        }
      }
    }
  }
}

void SeaScanSource::fill_scan(const sea::SeaScan& in, scenario::SimScan& out) {
  const Detector& det = chain_->detector;
  const std::uint32_t k = in.index + 1;
  out = scenario::SimScan{};
  out.scan = k;
  // The tracker's time is the CPI centre, where the truth is given.
  const double t_s = in.time_s + 0.5 * static_cast<double>(sea_.pulses) / sea_.prf_hz;
  out.time_us = static_cast<std::uint64_t>(std::llround(t_s * 1e6));
  out.has_doppler = true;
  for (const sea::SeaTruth& t : in.truth) {
    scenario::TruthState ts;
    ts.target_id = t.id;
    ts.x.px = t.range_m;
    ts.x.vx = t.range_rate_mps;
    ts.snr = std::pow(10.0, sea_.scr_db / 10.0);
    ts.in_region = true;
    out.truth.push_back(ts);
  }
  out.patch_size = kPatchCodes;
  if (chain_->features != FeatureExtractor::kNone) out.feature_size = classify::kNumFeatures;
  const sea::LabelRule rule;
  for (std::size_t j = 0; j < det.num_plots(); ++j) {
    const seaclutter::SeaPlot& p = det.plot(j);
    scenario::SimMeasurement m;
    m.range_m = p.range_m;
    m.azimuth_rad = 0.0;
    m.amplitude = p.amplitude;
    m.doppler_mps = p.range_rate_mps;
    m.x_m = p.range_m;
    const int t = sea::label_plot(p.range_m, p.doppler_bin, in.truth, rule);
    if (t >= 0) {
      m.origin = {scenario::OriginKind::kTarget, in.truth[static_cast<std::size_t>(t)].id};
      scenario::TruthState& ts = out.truth[static_cast<std::size_t>(t)];
      if (!ts.detected) ts.measurement_index = static_cast<std::int32_t>(j);
      ts.detected = true;
    }
    out.measurements.push_back(m);
    const auto& patch = det.patch(p.patch_index);
    out.patches.insert(out.patches.end(), patch.begin(), patch.end());
    if (chain_->features == FeatureExtractor::kNone) continue;
    classify::Features f{};
    Status st = Status::kOk;
    const auto t0 = std::chrono::steady_clock::now();
    if (chain_->features == FeatureExtractor::kInt8) {
      st = chain_->classifier_q8.features(patch.data(), f);
    } else {
      for (std::size_t i = 0; i < kPatchCodes; ++i) chain_->patch[i] = static_cast<float>(patch[i]);
      st = chain_->classifier.features(chain_->patch.data(), f);
    }
    feature_us_ += std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
    ++feature_count_;
    if (st != Status::kOk) throw std::runtime_error("classifier features failed");
    out.features.insert(out.features.end(), f.begin(), f.end());
  }
}

void SeaScanSource::deliver(const ScanStep& step, FrameInput /*input: always detections*/) {
  for (const scenario::SimScan& s : scans_) step(s, nullptr);
}

}  // namespace mptrack::sim
