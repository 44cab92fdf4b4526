// "oracle": a truth-aided pseudo-tracker for testing the harness pipeline
// (metrics, CSV, plot) without a real tracker. At each scan it reports every
// target-originated measurement, converted to Cartesian, as a confirmed track
// with the target's id, and the true clutter map of that scan.
// On raw-ADC scenarios the front end's detections carry no origin, so there
// the oracle reports every true object's state itself: the ceiling
// (OSPA 0) that detect-then-track and VMP are compared against.
#include "mptrack/math/detmath.h"
#include "tracker_registry.h"

namespace mptrack::sim {

namespace {

class OracleTracker final : public TrackerAdapter {
 public:
  std::string init(const TrackerSetup& setup) override {
    spec_ = setup.spec;
    clutter_scale_ = setup.clutter_scale;
    raw_ = setup.raw_scenario != nullptr;
    counters_ = TrackerCounters{};
    return {};
  }

  Status step(const scenario::SimScan& scan, std::vector<EstimateOut>& out) override {
    EstimateOut e;
    e.scan = scan.scan;
    ++counters_.scans;
    counters_.measurements_in += scan.measurements.size();
    if (raw_) {
      for (const scenario::TruthState& x : scan.truth) e.tracks.push_back(truth_track(x));
      out.push_back(e);
      return Status::kOk;
    }
    for (std::size_t j = 0; j < scan.measurements.size(); ++j) {
      const scenario::SimMeasurement& m = scan.measurements[j];
      if (m.origin.kind != scenario::OriginKind::kTarget) continue;
      TrackOut t;
      t.id = m.origin.id;
      double s = 0.0;
      double c = 0.0;
      dmath::dsincos(m.azimuth_rad, s, c);
      t.px = m.range_m * c;
      t.py = m.range_m * s;
      t.existence = 1.0;
      t.snr = m.amplitude * m.amplitude - 1.0;
      t.confirmed = true;
      t.measurement_index = static_cast<std::int32_t>(j);
      e.tracks.push_back(t);
    }
    for (const scenario::ClutterSpec& c : spec_.clutter) {
      if (!scenario::alive(c.birth_scan, c.death_scan, scan.scan)) continue;
      const scenario::ClutterAtScan p = scenario::clutter_at_scan(spec_, c, scan.scan);
      ClutterOut o;
      o.id = c.id;
      o.uniform = c.uniform;
      o.mean_range_m = p.mean_range_m;
      o.mean_azimuth_rad = p.mean_azimuth_rad;
      o.cov_rr = p.cov_rr;
      o.cov_ra = p.cov_ra;
      o.cov_aa = p.cov_aa;
      o.expected_count = p.mean_count * clutter_scale_;
      o.cnr = p.cnr;
      e.clutter.push_back(o);
    }
    out.push_back(e);
    return Status::kOk;
  }

  Status flush(std::vector<EstimateOut>& /*out*/) override { return Status::kOk; }
  TrackerCounters counters() const override { return counters_; }

 private:
  static TrackOut truth_track(const scenario::TruthState& x) {
    TrackOut t;
    t.id = x.target_id;
    t.px = x.x.px;
    t.py = x.x.py;
    t.vx = x.x.vx;
    t.vy = x.x.vy;
    t.existence = 1.0;
    t.snr = x.snr;
    t.confirmed = true;
    t.measurement_index = x.measurement_index;
    return t;
  }

  scenario::ScenarioSpec spec_;
  double clutter_scale_ = 1.0;
  bool raw_ = false;  ///< raw-ADC scenario: report the truth itself
  TrackerCounters counters_;
};

}  // namespace

std::unique_ptr<TrackerAdapter> make_oracle_tracker() { return std::make_unique<OracleTracker>(); }

}  // namespace mptrack::sim
