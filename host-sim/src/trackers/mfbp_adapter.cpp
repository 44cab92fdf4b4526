// mfbp, mfbp-filter and the seed 000 ablations (docs/algorithms/mfbp.md §Clutter chain) on
// MfbpTracker<double>.
// The scenario supplies region, noise, threshold, Swerling case and scan
// period; mfbp-kce also gets the exact clutter map of every scan (Table III
// with lifetimes and seed 000 eq. (104) time variation), mfbp-nce the uniform rate.
#include <algorithm>
#include <cstdlib>
#include <string>

#include "mptrack/mfbp/mfbp_tracker.h"
#include "trackers/core_adapter.h"
#include "trackers/mfbp_param_override.h"
#include "trackers/sea_setup.h"
#include "tracker_registry.h"

namespace mptrack::sim {

namespace {

using Tracker = MfbpTracker<double, DefaultCaps>;

double uniform_rate(const scenario::ScenarioSpec& spec, double scale) {
  double rate = 0.0;
  for (const auto& c : spec.clutter) {
    if (c.uniform) rate += c.mean_count * scale;
  }
  return rate;
}

double uniform_cnr(const scenario::ScenarioSpec& spec) {
  for (const auto& c : spec.clutter) {
    if (c.uniform) return c.cnr;
  }
  return 1.0;
}

class MfbpAdapter final : public CoreTrackerAdapter<Tracker> {
 public:
  explicit MfbpAdapter(std::string variant) : variant_(std::move(variant)) {}

  std::string init(const TrackerSetup& setup) override {
    if (std::string why = polar_scenario_required(setup, variant_); !why.empty()) return why;
    spec_ = setup.spec;
    scale_ = setup.clutter_scale;
    MfbpParams<double> p =
        variant_ == "mfbp-s1" ? every_scan_smoother_params<double>() : seed000_default_params<double>();
    p.region = scenario_region(spec_);
    p.scan_period_s = spec_.scan_period_s;
    set_scenario_noise(spec_, p.noise);
    p.amplitude.threshold = spec_.threshold;
    p.amplitude.swerling = scenario_swerling(spec_);
    p.uniform_rate_per_scan = uniform_rate(spec_, scale_);
    p.uniform_cnr_prior = uniform_cnr(spec_);
    if (variant_ == "mfbp-filter") {
      p.window_length = 1;
      p.slide = 1;
    } else if (variant_ == "mfbp-ki") {
      p.amplitude.use_amplitude = false;
    } else if (variant_ == "mfbp-nce") {
      p.clutter_mode = ClutterMode::kUniformKnownRate;
    } else if (variant_ == "mfbp-kce") {
      std::size_t components = 0;
      for (const auto& c : spec_.clutter) components += c.uniform ? 0 : 1;
      if (components > kMaxKnownClutterComponents) {
        return "mfbp.known_clutter.num_components = " + std::to_string(components) +
               " (the scenario's non-uniform clutter components): must be <= " +
               std::to_string(kMaxKnownClutterComponents) + " (kMaxKnownClutterComponents)";
      }
      p.clutter_mode = ClutterMode::kKnown;
      p.known_clutter = known_clutter(1);
    } else if (variant_ == "mfbp-st") {
      p.mp_max_iterations = 1;
    } else if (variant_ != "mfbp" && variant_ != "mfbp-s1") {
      return "unknown MF-BP variant " + variant_;
    }
    if (setup.sea_scenario) {
      if (variant_ != "mfbp") return variant_ + " does not run on the sea scenes (use mfbp, mfbp-nn or nemp)";
      configure_sea_mfbp(setup, SeaBirths::kBlind, p);
    }
    const std::string error = apply_mfbp_params(p, setup.mfbp_params);
    if (!error.empty()) return error;
    return init_tracker(p, "mfbp");
  }

 private:
  // Table III map for scan k: every non-uniform component with the scan
  // times it exists in (KnownClutterComponent::active_*_us: the tracker
  // evaluates each stored scan against the map, and the window reaches back
  // before k) and its parameters at scan k, or at the nearest scan of its
  // life. The uniform part is the one in effect at k.
  KnownClutter<double> known_clutter(std::uint32_t k) const {
    KnownClutter<double> kc;
    kc.uniform_rate_per_scan = 0.0;
    kc.uniform_cnr = uniform_cnr(spec_);
    for (const auto& c : spec_.clutter) {
      if (c.uniform) {
        if (scenario::alive(c.birth_scan, c.death_scan, k)) {
          kc.uniform_rate_per_scan += scenario::clutter_at_scan(spec_, c, k).mean_count * scale_;
        }
        continue;
      }
      if (kc.num_components >= kMaxKnownClutterComponents) continue;
      const std::uint32_t at = std::min(std::max(k, c.birth_scan), c.death_scan);
      const scenario::ClutterAtScan a = scenario::clutter_at_scan(spec_, c, at);
      KnownClutterComponent<double>& o = kc.components[kc.num_components++];
      o.rate_per_scan = a.mean_count * scale_;
      o.mean << a.mean_range_m, a.mean_azimuth_rad;
      o.covariance << a.cov_rr, a.cov_ra, a.cov_ra, a.cov_aa;
      o.cnr = a.cnr;
      o.active_from_us = scenario::scan_time_us(spec_, c.birth_scan);
      o.active_until_us = scenario::scan_time_us(spec_, c.death_scan);
    }
    return kc;
  }

  void before_step(std::uint32_t scan) override {
    if (variant_ != "mfbp-kce") return;
    // A refused map keeps the previous one; the next step still runs.
    (void)tracker().set_known_clutter(known_clutter(scan));
  }

  std::string variant_;
  scenario::ScenarioSpec spec_;
  double scale_ = 1.0;
};

}  // namespace

std::unique_ptr<TrackerAdapter> make_mfbp_tracker(const std::string& variant) {
  return std::make_unique<MfbpAdapter>(variant);
}

}  // namespace mptrack::sim
