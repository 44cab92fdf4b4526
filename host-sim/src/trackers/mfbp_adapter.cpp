// mfbp, mfbp-filter and the seed 000 ablations (spec 5.2) on MfbpTracker<double>.
// The scenario supplies region, noise, threshold, Swerling case and scan
// period; mfbp-kce also gets the exact clutter map of every scan (Table III
// with lifetimes and P104 time variation), mfbp-nce the uniform rate.
#include <cstdlib>
#include <string>

#include "mptrack/mfbp/mfbp_tracker.h"
#include "trackers/core_adapter.h"
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

// --mfbp-param NAME=VALUE: the MfbpParams fields a user tunes most
// (mfbp_params.h has units and defaults). init() still validates the result.
std::string apply_mfbp_param(MfbpParams<double>& p, const std::string& kv) {
  const std::size_t eq = kv.find('=');
  if (eq == std::string::npos) return "--mfbp-param " + kv + ": expected NAME=VALUE";
  const std::string name = kv.substr(0, eq);
  const std::string text = kv.substr(eq + 1);
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end == nullptr || *end != '\0') return "--mfbp-param " + name + ": '" + text + "' is not a number";
  const auto count = [v]() { return v < 0.0 ? std::size_t{0} : static_cast<std::size_t>(v); };
  struct Real { const char* name; double MfbpParams<double>::*field; };
  static const Real kReals[] = {
      {"process_noise_var", &MfbpParams<double>::process_noise_var},
      {"manoeuvre_noise_var_max", &MfbpParams<double>::manoeuvre_noise_var_max},
      {"manoeuvre_fading", &MfbpParams<double>::manoeuvre_fading},
      {"unresolved_chi2", &MfbpParams<double>::unresolved_chi2},
      {"gate_chi2", &MfbpParams<double>::gate_chi2},
      {"report_existence_min", &MfbpParams<double>::report_existence_min},
      {"p_survive", &MfbpParams<double>::p_survive},
      {"p_birth", &MfbpParams<double>::p_birth},
      {"confirm_threshold", &MfbpParams<double>::confirm_threshold},
      {"delete_threshold", &MfbpParams<double>::delete_threshold},
      {"pd_no_amplitude", &MfbpParams<double>::pd_no_amplitude},
      {"bp_damping", &MfbpParams<double>::bp_damping},
  };
  for (const Real& r : kReals) {
    if (name == r.name) {
      p.*(r.field) = v;
      return "";
    }
  }
  struct Count { const char* name; std::size_t MfbpParams<double>::*field; };
  static const Count kCounts[] = {
      {"delete_run", &MfbpParams<double>::delete_run},
      {"window_length", &MfbpParams<double>::window_length},
      {"slide", &MfbpParams<double>::slide},
      {"mp_max_iterations", &MfbpParams<double>::mp_max_iterations},
      {"bp_max_iterations", &MfbpParams<double>::bp_max_iterations},
  };
  for (const Count& c : kCounts) {
    if (name == c.name) {
      p.*(c.field) = count();
      return "";
    }
  }
  struct Flag { const char* name; bool MfbpParams<double>::*field; };
  static const Flag kFlags[] = {
      {"unresolved_pooling", &MfbpParams<double>::unresolved_pooling},
      {"association_cavity", &MfbpParams<double>::association_cavity},
      {"late_birth", &MfbpParams<double>::late_birth},
      {"use_amplitude", &MfbpParams<double>::use_amplitude},
      {"use_doppler", &MfbpParams<double>::use_doppler},
  };
  for (const Flag& f : kFlags) {
    if (name == f.name) {
      p.*(f.field) = v != 0.0;
      return "";
    }
  }
  return "--mfbp-param: unknown parameter '" + name + "' (see host-sim/README.md)";
}

class MfbpAdapter final : public CoreTrackerAdapter<Tracker> {
 public:
  explicit MfbpAdapter(std::string variant) : variant_(std::move(variant)) {}

  std::string init(const TrackerSetup& setup) override {
    spec_ = setup.spec;
    scale_ = setup.clutter_scale;
    MfbpParams<double> p = seed000_default_params<double>();
    p.r_min_m = spec_.region.range_min_m;
    p.r_max_m = spec_.region.range_max_m;
    p.az_min_rad = scenario::deg_to_rad(spec_.region.azimuth_min_deg);
    p.az_max_rad = scenario::deg_to_rad(spec_.region.azimuth_max_deg);
    p.scan_period_s = spec_.scan_period_s;
    p.sigma_r_m = spec_.sigma_range_m;
    p.sigma_az_rad = scenario::deg_to_rad(spec_.sigma_azimuth_deg);
    p.amplitude_threshold = spec_.threshold;
    p.swerling = scenario_swerling(spec_);
    p.uniform_rate_per_scan = uniform_rate(spec_, scale_);
    p.uniform_cnr_prior = uniform_cnr(spec_);
    if (variant_ == "mfbp-filter") {
      p.window_length = 1;
      p.slide = 1;
    } else if (variant_ == "mfbp-ki") {
      p.use_amplitude = false;
    } else if (variant_ == "mfbp-nce") {
      p.clutter_mode = ClutterMode::kUniformKnownRate;
    } else if (variant_ == "mfbp-kce") {
      p.clutter_mode = ClutterMode::kKnown;
      p.known_clutter = known_clutter(1);
    } else if (variant_ == "mfbp-st") {
      p.mp_max_iterations = 1;
    } else if (variant_ != "mfbp") {
      return "unknown MF-BP variant " + variant_;
    }
    for (const std::string& kv : setup.mfbp_params) {
      const std::string error = apply_mfbp_param(p, kv);
      if (!error.empty()) return error;
    }
    return init_tracker(p);
  }

 private:
  // Table III map in effect at scan k (components outside their lifetime left out).
  KnownClutter<double> known_clutter(std::uint32_t k) const {
    KnownClutter<double> kc;
    kc.uniform_rate_per_scan = 0.0;
    kc.uniform_cnr = uniform_cnr(spec_);
    for (const auto& c : spec_.clutter) {
      if (!scenario::alive(c.birth_scan, c.death_scan, k)) continue;
      const scenario::ClutterAtScan a = scenario::clutter_at_scan(spec_, c, k);
      if (c.uniform) {
        kc.uniform_rate_per_scan += a.mean_count * scale_;
        continue;
      }
      if (kc.num_components >= kMaxKnownClutterComponents) continue;
      KnownClutterComponent<double>& o = kc.components[kc.num_components++];
      o.rate_per_scan = a.mean_count * scale_;
      o.mean << a.mean_range_m, a.mean_azimuth_rad;
      o.covariance << a.cov_rr, a.cov_ra, a.cov_ra, a.cov_aa;
      o.cnr = a.cnr;
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
