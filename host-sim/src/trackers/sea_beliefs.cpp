// MF-BP / NEMP association beliefs of a sea scene; see sea_beliefs.h.
#include "trackers/sea_beliefs.h"

#include <cmath>
#include <memory>
#include <stdexcept>
#include <vector>

#include "mptrack/classify/sea_classifier.h"
#include "mptrack/classify/trained_weights.h"
#include "mptrack/mfbp/mfbp_tracker.h"
#include "run/sea_source.h"
#include "trackers/sea_setup.h"

namespace mptrack::sim {

namespace {

using Tracker = MfbpTracker<double, DefaultCaps>;
using Nemp = mfbp::NempState<double, DefaultCaps>;
using Evidence = mfbp::ScanEvidence<DefaultCaps::kMaxMeasurements>;

void drain(Nemp& nemp, const sea::ScenePlots& scene, sea::SceneBeliefs& out) {
  for (std::size_t f = 0; f < nemp.finalised_scans() && out.size() < scene.plots.size(); ++f) {
    const std::size_t n = scene.plots[out.size()].size();
    std::vector<float> row(n, 0.5f);
    for (std::size_t j = 0; j < n && j < DefaultCaps::kMaxMeasurements; ++j) row[j] = nemp.finalised_belief(f, j);
    out.push_back(std::move(row));
  }
  nemp.clear_finalised();
}

/// The classifier features of every plot of scan k into `evidence`
/// (kNemp), or "has a patch" only (kMfbp: reliability 0 never reads them).
void fill_evidence(BeliefSource source, classify::SeaClassifier& classifier, const sea::ScenePlots& scene,
                   std::size_t k, Evidence& evidence) {
  evidence.has_patch.fill(true);
  if (source != BeliefSource::kNemp) return;
  constexpr std::size_t kCodes = classify::kPatchSize;
  if (k >= scene.patches.size() || scene.patches[k].size() != scene.plots[k].size() * kCodes) {
    throw std::runtime_error("NEMP belief recorder: the scene carries no patches");
  }
  std::vector<float> patch(kCodes);
  for (std::size_t j = 0; j < scene.plots[k].size() && j < DefaultCaps::kMaxMeasurements; ++j) {
    for (std::size_t i = 0; i < kCodes; ++i) patch[i] = static_cast<float>(scene.patches[k][j * kCodes + i]);
    if (classifier.features(patch.data(), evidence.features[j]) != Status::kOk) {
      throw std::runtime_error("NEMP belief recorder: classifier features failed");
    }
  }
}

}  // namespace

bool sea_beliefs_available() { return classify::kHaveTrainedWeights; }

sea::SceneBeliefs scene_beliefs(BeliefSource source, const sea::SeaScenario& scenario, const sea::ScenePlots& scene) {
  TrackerSetup setup;
  setup.spec = sea_spec_view(scenario);
  setup.sea_scenario = std::make_shared<const sea::SeaScenario>(scenario);
  MfbpParams<double> p = seed000_default_params<double>();
  configure_sea_mfbp(setup, SeaBirths::kClassified, p);  // the window NEMP runs with
  auto tracker = std::make_unique<Tracker>();
  auto classifier = std::make_unique<classify::SeaClassifier>();
  auto nemp = std::make_unique<Nemp>();
  auto evidence = std::make_unique<Evidence>();
  auto scan = std::make_unique<Tracker::ScanType>();
  mfbp::NempParams<double> np = sea_nemp_params();
  if (source == BeliefSource::kMfbp) {
    np = mfbp::NempParams<double>{};
    np.rounds = 1;
    np.nn_reliability = 0.0;  // BetP = p_FG: the rounds leave MF-BP's association as it is
  }
  if (tracker->init(p) != Status::kOk || classifier->init(classify::trained_weights()) != Status::kOk ||
      nemp->init(classifier.get(), np) != Status::kOk || tracker->attach_nemp(nemp.get()) != Status::kOk) {
    throw std::runtime_error("belief recorder: init failed (trained classifier weights needed)");
  }
  sea::SceneBeliefs out;
  for (std::size_t k = 0; k < scene.plots.size(); ++k) {
    scan->time_us = static_cast<std::uint64_t>(std::llround(scene.time_s[k] * 1e6));
    scan->has_doppler = true;
    scan->measurements.clear();
    for (const seaclutter::SeaPlot& x : scene.plots[k]) {
      Measurement<double> m;
      m.range_m = x.range_m;
      m.azimuth_rad = 0.0;
      m.amplitude = x.amplitude;
      m.doppler_mps = x.range_rate_mps;
      (void)scan->measurements.push_back(m);  // at most 64 plots: below the cap
    }
    fill_evidence(source, *classifier, scene, k, *evidence);
    (void)tracker->step(*scan, *evidence);
    drain(*nemp, scene, out);
  }
  (void)tracker->flush();
  drain(*nemp, scene, out);
  return out;
}

}  // namespace mptrack::sim
