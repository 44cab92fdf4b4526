// mfbp-multipath: the multipath MF-BP tracker (seed 002) on
// MultipathMfbpTracker<float, LargeCaps> (LargeCaps: 1024 detections per
// scan, for Nc = 400), configured from an OTHR scenario: its paths (heights
// and pd), baseline, slant-coordinate region, noise and clutter rate.
#include <cstdlib>
#include <string>
#include <vector>

#include "mptrack/multipath/multipath_tracker.h"
#include "trackers/core_adapter.h"
#include "tracker_registry.h"

namespace mptrack::sim {

namespace {

using Tracker = MultipathMfbpTracker<float, LargeCaps>;

/// The harness reports the smoothed estimate 3 scans late (48 s at the
/// scenario's 16 s period; docs/algorithms/multipath.md §Fixed-lag smoother).
constexpr std::uint32_t kDefaultLagScans = 3;

/// `--mfbp-param smoothing_lag_scans=N` (0 = the filter's estimate at once).
std::string apply_overrides(const std::vector<std::string>& overrides, MultipathParams<float>& p) {
  for (const std::string& kv : overrides) {
    const std::size_t eq = kv.find('=');
    const std::string name = kv.substr(0, eq);
    if (eq == std::string::npos || name != "smoothing_lag_scans") {
      return "mfbp-multipath: unknown parameter \"" + kv + "\" (known: smoothing_lag_scans=N)";
    }
    char* end = nullptr;
    const unsigned long v = std::strtoul(kv.c_str() + eq + 1, &end, 10);
    if (end == kv.c_str() + eq + 1 || *end != '\0' || v > Tracker::kMaxLag) {
      return "mfbp-multipath: smoothing_lag_scans = " + kv.substr(eq + 1) + ": must be an integer in [0, " +
             std::to_string(Tracker::kMaxLag) + "] (Caps::kMaxSmoothingLag)";
    }
    p.smoothing_lag_scans = static_cast<std::uint32_t>(v);
  }
  return "";
}

class MultipathAdapter final : public CoreTrackerAdapter<Tracker> {
 public:
  std::string init(const TrackerSetup& setup) override {
    const scenario::ScenarioSpec& s = setup.spec;
    if (s.space != scenario::MeasurementSpace::kOthr) {
      return "mfbp-multipath needs an OTHR scenario (measurement_space \"othr\", e.g. seed002-othr)";
    }
    MultipathParams<float> p;
    p.num_paths = static_cast<std::uint32_t>(s.othr.paths.size());
    for (std::size_t i = 0; i < s.othr.paths.size() && i < p.paths.size(); ++i) {
      const scenario::OthrPathSpec& ps = s.othr.paths[i];
      p.paths[i] = {static_cast<float>(ps.tx_height_km), static_cast<float>(ps.rx_height_km)};
      // pd 1 is a valid scenario but not a valid model (ln(1 - pd)): just below.
      p.pd[i] = static_cast<float>(ps.pd < 0.999 ? ps.pd : 0.999);
    }
    p.baseline_km = static_cast<float>(s.othr.baseline_km);
    const PolarRegion<double> r = scenario_region(s);
    p.region = {static_cast<float>(r.range_min_m), static_cast<float>(r.range_max_m),
                static_cast<float>(r.azimuth_min_rad), static_cast<float>(r.azimuth_max_rad)};
    p.range_rate_span_mps = static_cast<float>(s.othr.range_rate_max_mps);
    p.noise.range_std_m = static_cast<float>(s.sigma_range_m);
    p.noise.azimuth_std_rad = static_cast<float>(scenario::deg_to_rad(s.sigma_azimuth_deg));
    p.noise.doppler_std_mps = static_cast<float>(s.othr.sigma_range_rate_mps);
    double clutter = 0.0;  // the known uniform rate, as the paper's JDT-VB assumes
    for (const scenario::ClutterSpec& c : s.clutter) clutter += c.mean_count * setup.clutter_scale;
    p.clutter_mean_count = static_cast<float>(clutter > 1.0 ? clutter : 1.0);
    p.max_gap_s = static_cast<float>(4.0 * s.scan_period_s);
    p.smoothing_lag_scans = kDefaultLagScans;
    const std::string error = apply_overrides(setup.mfbp_params, p);
    if (!error.empty()) return error;
    return init_tracker(p, "multipath");
  }
};

}  // namespace

std::unique_ptr<TrackerAdapter> make_multipath_tracker() { return std::make_unique<MultipathAdapter>(); }

}  // namespace mptrack::sim
