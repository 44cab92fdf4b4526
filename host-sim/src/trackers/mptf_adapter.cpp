// mptf: the multipath track fusion baseline of seed 002 (slant PDA path
// tracks fused in ground coordinates; docs/algorithms/mptf.md) on
// MptfTracker<float, LargeCaps> (LargeCaps: 1024 detections and 1024 path
// tracks, for Nc = 400), configured from an OTHR scenario as the
// multipath MF-BP adapter is: paths (heights and pd), baseline,
// slant-coordinate region, noise and clutter rate.
#include "mptrack/mptf/mptf_tracker.h"
#include "trackers/core_adapter.h"
#include "tracker_registry.h"

namespace mptrack::sim {

namespace {

using Tracker = MptfTracker<float, LargeCaps>;

/// Seed 002 Sec. IV deletes after 3 empty scans at Nc = 125 and 5 at Nc = 400:
/// 5 above this clutter rate [detections per scan].
constexpr double kDenseClutter = 250.0;

class MptfAdapter final : public CoreTrackerAdapter<Tracker> {
 public:
  std::string init(const TrackerSetup& setup) override {
    const scenario::ScenarioSpec& s = setup.spec;
    if (s.space != scenario::MeasurementSpace::kOthr) {
      return "mptf needs an OTHR scenario (measurement_space \"othr\", e.g. seed002-othr)";
    }
    MptfParams<float> p;
    p.num_paths = static_cast<std::uint32_t>(s.othr.paths.size());
    double pd_sum = 0.0;
    for (std::size_t i = 0; i < s.othr.paths.size() && i < p.paths.size(); ++i) {
      const scenario::OthrPathSpec& ps = s.othr.paths[i];
      p.paths[i] = {static_cast<float>(ps.tx_height_km), static_cast<float>(ps.rx_height_km)};
      pd_sum += ps.pd;
    }
    // A path track does not know its path: the PDA uses the mean p_d.
    const double pd = s.othr.paths.empty() ? 0.75 : pd_sum / static_cast<double>(s.othr.paths.size());
    p.pd = static_cast<float>(pd > 1e-3 ? pd : 1e-3);
    p.fuse_min_paths = p.num_paths < 2 ? p.num_paths : 2u;
    p.baseline_km = static_cast<float>(s.othr.baseline_km);
    const PolarRegion<double> r = scenario_region(s);
    p.region = {static_cast<float>(r.range_min_m), static_cast<float>(r.range_max_m),
                static_cast<float>(r.azimuth_min_rad), static_cast<float>(r.azimuth_max_rad)};
    p.range_rate_span_mps = static_cast<float>(s.othr.range_rate_max_mps);
    p.noise.range_std_m = static_cast<float>(s.sigma_range_m);
    p.noise.azimuth_std_rad = static_cast<float>(scenario::deg_to_rad(s.sigma_azimuth_deg));
    p.noise.doppler_std_mps = static_cast<float>(s.othr.sigma_range_rate_mps);
    double clutter = 0.0;  // the known uniform rate, as for the multipath MF-BP
    for (const scenario::ClutterSpec& c : s.clutter) clutter += c.mean_count * setup.clutter_scale;
    p.clutter_mean_count = static_cast<float>(clutter > 1.0 ? clutter : 1.0);
    p.delete_misses = clutter > kDenseClutter ? 5u : 3u;
    p.max_gap_s = static_cast<float>(4.0 * s.scan_period_s);
    return init_tracker(p, "mptf");
  }
};

}  // namespace

std::unique_ptr<TrackerAdapter> make_mptf_tracker() { return std::make_unique<MptfAdapter>(); }

}  // namespace mptrack::sim
