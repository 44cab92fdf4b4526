// mfbp-multipath: the multipath MF-BP tracker (seed 002) on
// MultipathMfbpTracker<float, LargeCaps> (LargeCaps: 1024 detections per
// scan, for Nc = 400), configured from an OTHR scenario: its paths (heights
// and pd), baseline, slant-coordinate region, noise and clutter rate.
#include <cstdlib>
#include <string>
#include <vector>

#include "mptrack/multipath/multipath_tracker.h"
#include "trackers/core_adapter.h"
#include "trackers/othr_setup.h"
#include "tracker_registry.h"

namespace mptrack::sim {

namespace {

using Tracker = MultipathMfbpTracker<float, LargeCaps>;

/// The harness reports the smoothed estimate 3 scans late (48 s at the
/// scenario's 16 s period; docs/algorithms/multipath.md §Fixed-lag smoother).
constexpr std::uint32_t kDefaultLagScans = 3;

/// `--mfbp-param smoothing_lag_scans=N` (0 = the filter's estimate at once),
/// `--mfbp-param bearing_psd_rad2ps3=Q` (the bearing axis's white-noise PSD).
std::string apply_overrides(const std::vector<std::string>& overrides, MultipathParams<float>& p) {
  for (const std::string& kv : overrides) {
    const std::size_t eq = kv.find('=');
    const std::string name = kv.substr(0, eq);
    if (eq != std::string::npos && name == "bearing_psd_rad2ps3") {
      char* end = nullptr;
      const double v = std::strtod(kv.c_str() + eq + 1, &end);
      if (end == kv.c_str() + eq + 1 || *end != '\0' || !(v >= 0.0 && v <= 1.0)) {
        return "mfbp-multipath: bearing_psd_rad2ps3 = " + kv.substr(eq + 1) + ": must be a number in [0, 1]";
      }
      p.bearing_psd_rad2ps3 = static_cast<float>(v);
      continue;
    }
    if (eq == std::string::npos || name != "smoothing_lag_scans") {
      return "mfbp-multipath: unknown parameter \"" + kv +
             "\" (known: smoothing_lag_scans=N, bearing_psd_rad2ps3=Q)";
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
    const std::string refused = othr_scenario_required(setup, "mfbp-multipath");
    if (!refused.empty()) return refused;
    MultipathParams<float> p;
    configure_othr(setup, p);  // the known uniform rate, as the paper's JDT-VB assumes
    for (std::size_t i = 0; i < setup.spec.othr.paths.size() && i < p.pd.size(); ++i) {
      // pd 1 is a valid scenario but not a valid model (ln(1 - pd)): just below.
      const double pd = setup.spec.othr.paths[i].pd;
      p.pd[i] = static_cast<float>(pd < 0.999 ? pd : 0.999);
    }
    p.smoothing_lag_scans = kDefaultLagScans;
    p.bearing_psd_rad2ps3 = othr_cross_range_bearing_psd(p.range_psd_m2ps3, p.region);
    const std::string error = apply_overrides(setup.mfbp_params, p);
    if (!error.empty()) return error;
    return init_tracker(p, "multipath");
  }
};

}  // namespace

std::unique_ptr<TrackerAdapter> make_multipath_tracker() { return std::make_unique<MultipathAdapter>(); }

}  // namespace mptrack::sim
