// The seed 003 sea scenes in the harness (host-sim/src/run/sea_source.h,
// sea_runner.h, trackers/sea_beliefs.h): scans carry one patch (and, with
// the trained classifier, one feature vector) per measurement, --scr sets
// every target's SCR, and MP, MP-NN and NEMP run end to end on the same
// measurements. Scenes are shortened to a few scans to keep the test fast.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "mptrack/classify/sea_classifier.h"
#include "mptrack/classify/trained_weights.h"
#include "mptrack/seaclutter/sea_caps.h"
#include "run/sea_source.h"
#include "sea_runner.h"
#include "trackers/sea_beliefs.h"

namespace {

mptrack::sea::SeaScenario short_scene(const char* name, double scr_db, std::uint32_t scans) {
  mptrack::sea::SeaScenario s;
  REQUIRE(mptrack::sea::builtin_sea_scenario(name, s));
  s.scr_db = scr_db;
  s.num_scans = scans;
  return s;
}

}  // namespace

TEST_CASE("sea source: one patch per measurement, truth on the boresight axis, the scenario's SCR") {
  mptrack::sim::SeaScanSource src(short_scene("seed003-sea-a", 6.0, 2), 1, mptrack::sim::FeatureExtractor::kNone, 0);
  src.begin_run(0);
  REQUIRE(src.scans().size() == 2);
  const auto& s = src.scans()[1];
  CHECK(s.scan == 2);
  CHECK(s.time_us == 10256000u);  // scan 2 starts at 10 s; the CPI centre is 256 ms later
  CHECK(s.has_doppler);
  REQUIRE(!s.measurements.empty());
  CHECK(s.measurements.size() <= mptrack::seaclutter::SeaClutterCaps::kMaxPlots);
  CHECK(s.patch_size == 5u * 512u);
  CHECK(s.patches.size() == s.measurements.size() * s.patch_size);
  CHECK(s.features.empty());
  REQUIRE(s.truth.size() == 4);  // sea state A has 4 targets
  for (const auto& t : s.truth) {
    CHECK(t.x.py == 0.0);
    CHECK(t.snr == doctest::Approx(std::pow(10.0, 0.6)));
  }
  for (const auto& m : s.measurements) CHECK(m.azimuth_rad == 0.0);
}

TEST_CASE("sea source: the same run gives the same scans at a second begin_run") {
  mptrack::sim::SeaScanSource src(short_scene("seed003-sea-b", 0.0, 2), 5, mptrack::sim::FeatureExtractor::kNone, 0);
  src.begin_run(3);
  const auto first = src.scans();
  src.begin_run(3);
  REQUIRE(first.size() == src.scans().size());
  for (std::size_t k = 0; k < first.size(); ++k) {
    REQUIRE(first[k].measurements.size() == src.scans()[k].measurements.size());
    CHECK(first[k].patches == src.scans()[k].patches);
  }
}

TEST_CASE("sea source: features once per detection, equal to the classifier's on the patch") {
  if (!mptrack::classify::kHaveTrainedWeights) return;
  mptrack::sim::SeaScanSource src(short_scene("seed003-sea-a", 0.0, 1), 1, mptrack::sim::FeatureExtractor::kFloat, 0);
  src.begin_run(0);
  const auto& s = src.scans()[0];
  REQUIRE(s.feature_size == mptrack::classify::kNumFeatures);
  REQUIRE(s.features.size() == s.measurements.size() * s.feature_size);
  auto clf = std::make_unique<mptrack::classify::SeaClassifier>();
  REQUIRE(clf->init(mptrack::classify::trained_weights()) == mptrack::Status::kOk);
  std::vector<float> patch(s.patch_size);
  const std::size_t j = s.measurements.size() - 1;
  for (std::size_t i = 0; i < s.patch_size; ++i) patch[i] = s.patches[j * s.patch_size + i];
  mptrack::classify::Features f{};
  REQUIRE(clf->features(patch.data(), f) == mptrack::Status::kOk);
  for (std::size_t i = 0; i < f.size(); ++i) CHECK(f[i] == s.features[j * s.feature_size + i]);
}

TEST_CASE("sea compare: MP, MP-NN and NEMP run on identical measurements") {
  if (!mptrack::classify::kHaveTrainedWeights) return;
  mptrack::sim::SeaCompareConfig cfg;
  cfg.scenario = short_scene("seed003-sea-a", 10.0, 4);
  cfg.scr_db = {10.0};
  cfg.runs = 1;
  cfg.progress = false;
  const auto r = mptrack::sim::run_sea_compare(cfg);
  REQUIRE(r.size() == 1);
  REQUIRE(r[0].size() == 3);
  for (const auto& row : r[0]) {
    CHECK(row.base.step_errors == 0);
    CHECK(row.base.measurement_checksum == r[0][0].base.measurement_checksum);
    CHECK(row.scr_db == 10.0);
    CHECK(row.errors.truths == 16);  // 4 targets x 4 scans
  }
  CHECK(r[0][0].base.tracker == "mfbp");
  CHECK(r[0][2].base.tracker == "nemp");
}

namespace {

/// A sea scene's plots (with patches) as the dataset hands them to the
/// belief recorder; origin[k][j] is true for a target-originated plot.
struct RecordedScene {
  mptrack::sea::ScenePlots scene;
  std::vector<std::vector<bool>> origin;
  mptrack::sea::SeaScenario scenario;
};

RecordedScene record_scene(double scr_db, std::uint32_t scans) {
  RecordedScene r;
  mptrack::sim::SeaScanSource src(short_scene("seed003-sea-a", scr_db, scans), 1, mptrack::sim::FeatureExtractor::kNone, 0);
  src.begin_run(0);
  r.scenario = src.sea_scenario();
  for (const auto& s : src.scans()) {
    r.scene.time_s.push_back(static_cast<double>(s.time_us) * 1e-6);
    r.scene.plots.emplace_back();
    r.scene.patches.push_back(s.patches);
    r.origin.emplace_back();
    for (const auto& m : s.measurements) {
      mptrack::seaclutter::SeaPlot p;
      p.range_m = static_cast<float>(m.range_m);
      p.range_rate_mps = static_cast<float>(m.doppler_mps);
      p.amplitude = static_cast<float>(m.amplitude);
      r.scene.plots.back().push_back(p);
      r.origin.back().push_back(m.origin.kind == mptrack::scenario::OriginKind::kTarget);
    }
  }
  return r;
}

/// Mean belief over the clutter plots of a scene.
double mean_clutter_belief(const mptrack::sea::SceneBeliefs& b, const RecordedScene& r) {
  double sum = 0.0;
  int n = 0;
  for (std::size_t k = 0; k < b.size(); ++k) {
    for (std::size_t j = 0; j < b[k].size(); ++j) {
      if (r.origin[k][j]) continue;
      sum += static_cast<double>(b[k][j]);
      ++n;
    }
  }
  return n > 0 ? sum / n : 0.0;
}

void check_one_probability_per_plot(const mptrack::sea::SceneBeliefs& b, const mptrack::sea::ScenePlots& scene) {
  REQUIRE(b.size() == scene.plots.size());
  bool informative = false;
  for (std::size_t k = 0; k < b.size(); ++k) {
    REQUIRE(b[k].size() == scene.plots[k].size());
    for (float x : b[k]) {
      CHECK(x >= 0.0f);
      CHECK(x <= 1.0f);
      informative = informative || x != 0.5f;
    }
  }
  CHECK(informative);  // the tracker associated something: not the placeholder everywhere
}

}  // namespace

TEST_CASE("MF-BP beliefs of a scene: one per plot, probabilities") {
  if (!mptrack::sim::sea_beliefs_available()) return;
  const RecordedScene r = record_scene(10.0, 4);
  check_one_probability_per_plot(
      mptrack::sim::scene_beliefs(mptrack::sim::BeliefSource::kMfbp, r.scenario, r.scene), r.scene);
}

TEST_CASE("NEMP beliefs of a scene: one per plot, lower on clutter than plain MF-BP's") {
  if (!mptrack::sim::sea_beliefs_available()) return;
  const RecordedScene r = record_scene(10.0, 6);
  const auto nemp = mptrack::sim::scene_beliefs(mptrack::sim::BeliefSource::kNemp, r.scenario, r.scene);
  check_one_probability_per_plot(nemp, r.scene);
  // The classifier's clutter messages and birth veto keep clutter plots out
  // of tracks, which plain MF-BP's blind births at window 4 pair up.
  const auto mfbp = mptrack::sim::scene_beliefs(mptrack::sim::BeliefSource::kMfbp, r.scenario, r.scene);
  MESSAGE("mean clutter belief: NEMP " << mean_clutter_belief(nemp, r) << ", MF-BP " << mean_clutter_belief(mfbp, r));
  CHECK(mean_clutter_belief(nemp, r) < mean_clutter_belief(mfbp, r));
}

TEST_CASE("NEMP beliefs need the scene's patches") {
  if (!mptrack::sim::sea_beliefs_available()) return;
  RecordedScene r = record_scene(10.0, 2);
  r.scene.patches.clear();
  CHECK_THROWS_AS((void)mptrack::sim::scene_beliefs(mptrack::sim::BeliefSource::kNemp, r.scenario, r.scene),
                  std::runtime_error);
}

TEST_CASE("sea source: --classifier int8 features are the int8 g_M's on the detector's codes") {
  if (!mptrack::classify::kHaveTrainedQ8Weights) return;
  mptrack::sim::SeaScanSource src(short_scene("seed003-sea-a", 0.0, 1), 1, mptrack::sim::FeatureExtractor::kInt8, 0);
  src.begin_run(0);
  const auto& s = src.scans()[0];
  REQUIRE(s.features.size() == s.measurements.size() * s.feature_size);
  auto q = std::make_unique<mptrack::classify::SeaFeaturesQ8>();
  REQUIRE(q->init(mptrack::classify::trained_q8_weights()) == mptrack::Status::kOk);
  std::vector<std::uint8_t> codes(s.patch_size);
  const std::size_t j = s.measurements.size() - 1;
  for (std::size_t i = 0; i < s.patch_size; ++i) codes[i] = static_cast<std::uint8_t>(s.patches[j * s.patch_size + i]);
  mptrack::classify::Features f{};
  REQUIRE(q->features(codes.data(), f) == mptrack::Status::kOk);
  for (std::size_t i = 0; i < f.size(); ++i) CHECK(f[i] == s.features[j * s.feature_size + i]);
}
