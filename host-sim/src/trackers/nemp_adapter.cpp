// mfbp-nn and nemp (seed 003, docs/algorithms/nemp.md) on MfbpTracker<double>:
//   mfbp-nn  the classifier removes every detection with w < 0.5 before MF-BP
//            (the paper's MP-NN; no tracker belief yet, so the MLP sees 0.5);
//   nemp     every detection's features go to MF-BP with the scan and the
//            NEMP rounds fuse them into the association.
// Both need the classifier features of every detection, which the seed 003
// sea scenes' scan source computes once per detection and scan
// (run/sea_source.h), and the trained weights (./run train-classifier);
// without either they refuse with a message instead of running a plain MF-BP.
#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "mptrack/classify/sea_classifier.h"
#include "mptrack/classify/trained_weights.h"
#include "mptrack/mfbp/mfbp_tracker.h"
#include "trackers/core_adapter.h"
#include "trackers/mfbp_param_override.h"
#include "trackers/sea_setup.h"
#include "tracker_registry.h"

namespace mptrack::sim {

namespace {

using Tracker = MfbpTracker<double, DefaultCaps>;
using Nemp = mfbp::NempState<double, DefaultCaps>;
using Evidence = mfbp::ScanEvidence<DefaultCaps::kMaxMeasurements>;
constexpr std::size_t kF = classify::kNumFeatures;

/// `--mfbp-param nemp.NAME=VALUE` (the NempParams fields); other names are
/// MfbpParams' and skipped here.
std::string apply_nemp_params(mfbp::NempParams<double>& np, const std::vector<std::string>& overrides) {
  for (const std::string& kv : overrides) {
    const std::size_t eq = kv.find('=');
    if (kv.rfind("nemp.", 0) != 0 || eq == std::string::npos) continue;
    const std::string name = kv.substr(5, eq - 5);
    const std::string text = kv.substr(eq + 1);
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || end == nullptr || *end != '\0') return "--mfbp-param nemp." + name + ": not a number";
    if (name == "rounds" && v >= 1.0 && v <= 8.0 && v == static_cast<double>(static_cast<std::size_t>(v))) {
      np.rounds = static_cast<std::size_t>(v);
    } else if (name == "nn_reliability") {
      np.nn_reliability = v;
    } else if (name == "nn_log_odds_gain") {
      np.nn_log_odds_gain = v;
    } else if (name == "nn_max_target_prob") {
      np.nn_max_target_prob = v;
    } else if (name == "birth_min_target_prob") {
      np.birth_min_target_prob = v;
    } else if (name == "tentative_min_target_prob") {
      np.tentative_min_target_prob = v;
    } else {
      return "--mfbp-param nemp." + name + ": unknown or out of range (rounds 1..8, nn_reliability, nn_log_odds_gain, nn_max_target_prob, birth_min_target_prob, tentative_min_target_prob)";
    }
  }
  return "";
}

class NempAdapter final : public TrackerAdapter {
 public:
  explicit NempAdapter(std::string variant)
      : variant_(std::move(variant)),
        tracker_(std::make_unique<Tracker>()),
        nemp_(std::make_unique<Nemp>()),
        classifier_(std::make_unique<classify::SeaClassifier>()),
        scan_(std::make_unique<Tracker::ScanType>()),
        evidence_(std::make_unique<Evidence>()) {}

  std::string init(const TrackerSetup& setup) override {
    if (!classify::kHaveTrainedWeights) {
      return variant_ + " needs the trained classifier weights "
                        "(core/include/mptrack/classify/generated/sea_classifier_weights.h): ./run train-classifier";
    }
    if (classifier_->init(classify::trained_weights()) != Status::kOk) return "classifier weights refused";
    if (!setup.sea_scenario) {
      return variant_ + " needs the range-Doppler patches of a seed003-sea scenario (seed003-sea-a, seed003-sea-b, seed003-sea-c)";
    }
    const scenario::ScenarioSpec& spec = setup.spec;
    MfbpParams<double> p = seed000_default_params<double>();
    p.region = scenario_region(spec);
    p.scan_period_s = spec.scan_period_s;
    set_scenario_noise(spec, p.noise);
    p.amplitude.threshold = spec.threshold;
    p.amplitude.swerling = scenario_swerling(spec);
    if (setup.sea_scenario) configure_sea_mfbp(setup, SeaBirths::kClassified, p);
    const std::string error = apply_mfbp_params(p, setup.mfbp_params);
    if (!error.empty()) return error;
    if (tracker_->init(p) != Status::kOk) return "MF-BP init failed";
    if (variant_ == "nemp") {
      mfbp::NempParams<double> np = sea_nemp_params();
      const std::string nemp_error = apply_nemp_params(np, setup.mfbp_params);
      if (!nemp_error.empty()) return nemp_error;
      if (nemp_->init(classifier_.get(), np) != Status::kOk) return "NEMP init failed (nemp.* parameters out of range?)";
      if (tracker_->attach_nemp(nemp_.get()) != Status::kOk) return "NEMP attach failed";
    }
    return "";
  }

  Status step(const scenario::SimScan& scan, std::vector<EstimateOut>& out) override {
    const Status conv = scenario::to_scan(scan, *scan_);
    // The features were computed once per detection by the scan source
    // (run/sea_source.h) and are shared by every tracker of the run.
    if (scan.feature_size != classify::kNumFeatures || scan.features.size() != scan.measurements.size() * kF) {
      std::fprintf(stderr, "%s: scan %u carries no classifier features (use a seed003-sea scenario)\n",
                   variant_.c_str(), scan.scan);
      return Status::kInvalidInput;
    }
    for (std::size_t j = 0; j < scan_->measurements.size(); ++j) {
      std::copy_n(scan.features.begin() + static_cast<std::ptrdiff_t>(j * kF), kF, evidence_->features[j].begin());
      evidence_->has_patch[j] = true;
    }
    Status st = Status::kOk;
    if (variant_ == "nemp") {
      st = tracker_->step(*scan_, *evidence_);
    } else {
      remove_clutter_detections();
      st = tracker_->step(*scan_);
    }
    for (const auto& e : tracker_->outputs()) out.push_back(to_estimate_out(e));
    return st != Status::kOk ? st : conv;
  }

  Status flush(std::vector<EstimateOut>& out) override {
    const Status st = tracker_->flush();
    for (const auto& e : tracker_->outputs()) out.push_back(to_estimate_out(e));
    return st;
  }

  TrackerCounters counters() const override { return tracker_->counters(); }

  bool provisional(EstimateOut& out) const override {
    if (!tracker_->has_provisional()) return false;
    out = to_estimate_out(tracker_->provisional());
    return true;
  }

 private:
  /// mfbp-nn: keeps the detections the classifier calls targets (w >= 0.5
  /// with an uninformative tracker belief), in order.
  void remove_clutter_detections() {
    auto& m = scan_->measurements;
    Tracker::ScanType kept;
    kept.time_us = scan_->time_us;
    kept.has_doppler = scan_->has_doppler;
    for (std::size_t j = 0; j < m.size(); ++j) {
      if (!evidence_->has_patch[j]) continue;
      if (classifier_->target_probability(evidence_->features[j], 0.5f) >= 0.5f) (void)kept.measurements.push_back(m[j]);
    }
    *scan_ = kept;
  }

  std::string variant_;
  std::unique_ptr<Tracker> tracker_;
  std::unique_ptr<Nemp> nemp_;
  std::unique_ptr<classify::SeaClassifier> classifier_;
  std::unique_ptr<Tracker::ScanType> scan_;
  std::unique_ptr<Evidence> evidence_;
};

}  // namespace

std::unique_ptr<TrackerAdapter> make_nemp_tracker(const std::string& variant) {
  return std::make_unique<NempAdapter>(variant);
}

}  // namespace mptrack::sim
