// gnn: the GNN + Kalman detect-then-track baseline on GnnTracker<double>,
// configured from the scenario (region, measurement noise). The defaults of
// GnnParams are seed 004's (short-range MIMO); for seed 000's 10-50 km
// targets at 40-57 m/s the new-track velocity std is raised to v_max / 2.
#include "mptrack/gnn/gnn_tracker.h"
#include "trackers/core_adapter.h"
#include "tracker_registry.h"

namespace mptrack::sim {

namespace {

using Tracker = GnnTracker<double, DefaultCaps>;

class GnnAdapter final : public CoreTrackerAdapter<Tracker> {
 public:
  std::string init(const TrackerSetup& setup) override {
    if (std::string why = polar_scenario_required(setup, "gnn"); !why.empty()) return why;
    const scenario::ScenarioSpec& s = setup.spec;
    GnnParams<double> p;
    set_scenario_noise(s, p.noise);
    p.region = scenario_region(s);
    p.accel_var_m2ps4 = 1.0;          // (1 m/s^2)^2: seed 000 maneuvers reach 0.33 m/s^2
    p.init_velocity_std_mps = 60.0;   // v_max = 120 m/s (seed 000 Sec. IV-A) / 2
    return init_tracker(p, "gnn");
  }
};

}  // namespace

std::unique_ptr<TrackerAdapter> make_gnn_tracker() { return std::make_unique<GnnAdapter>(); }

}  // namespace mptrack::sim
