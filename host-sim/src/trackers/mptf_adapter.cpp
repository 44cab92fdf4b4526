// mptf: the multipath track fusion baseline of seed 002 (slant PDA path
// tracks fused in ground coordinates; docs/algorithms/mptf.md) on
// MptfTracker<float, LargeCaps> (LargeCaps: 1024 detections and 1024 path
// tracks, for Nc = 400), configured from an OTHR scenario as the
// multipath MF-BP adapter is: paths (heights and pd), baseline,
// slant-coordinate region, noise and clutter rate.
#include "mptrack/mptf/mptf_tracker.h"
#include "trackers/core_adapter.h"
#include "trackers/othr_setup.h"
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
    const std::string refused = othr_scenario_required(setup, "mptf");
    if (!refused.empty()) return refused;
    const scenario::ScenarioSpec& s = setup.spec;
    MptfParams<float> p;
    configure_othr(setup, p);
    double pd_sum = 0.0;
    for (const scenario::OthrPathSpec& ps : s.othr.paths) pd_sum += ps.pd;
    // A path track does not know its path: the PDA uses the mean p_d.
    const double pd = s.othr.paths.empty() ? 0.75 : pd_sum / static_cast<double>(s.othr.paths.size());
    p.pd = static_cast<float>(pd > 1e-3 ? pd : 1e-3);
    p.fuse_min_paths = p.num_paths < 2 ? p.num_paths : 2u;
    p.delete_misses = othr_clutter_mean(setup) > kDenseClutter ? 5u : 3u;
    return init_tracker(p, "mptf");
  }
};

}  // namespace

std::unique_ptr<TrackerAdapter> make_mptf_tracker() { return std::make_unique<MptfAdapter>(); }

}  // namespace mptrack::sim
