// Issue 18 scenes (host-sim/scenarios/): a scene without uniform clutter is
// a valid configuration for every measurement-level tracker, and MF-BP's
// uniform-rate floor (mfbp_params.h, uniform_rate_floor_per_scan) is what
// makes it valid for MF-BP.
#include <doctest/doctest.h>

#include <string>

#include "mptrack/mfbp/mfbp_params.h"
#include "mptrack/mfbp/mfbp_tracker.h"
#include "runner.h"
#include "scenario_json.h"
#include "tracker_registry.h"

using namespace mptrack::sim;

namespace {

const std::string kDir = MPTRACK_SCENARIO_DIR;

/// Trackers for other kinds of scene: raw frames (vmp, sbl-gnn), OTHR
/// (mfbp-multipath, mptf), seed 003 sea scenes with patches (mfbp-nn, nemp).
bool raw_frame_or_special(const std::string& name) {
  return name == "vmp" || name == "sbl-gnn" || name == "mfbp-multipath" || name == "mptf" || name == "mfbp-nn" ||
         name == "nemp";
}

}  // namespace

TEST_CASE("clutter scenes: the Gaussian-clutter-only scene has no uniform clutter") {
  const mptrack::scenario::ScenarioSpec s = load_scenario_file(kDir + "/gaussian-clutter-only.json");
  REQUIRE(!s.clutter.empty());
  for (const auto& c : s.clutter) CHECK_FALSE(c.uniform);
}

TEST_CASE("clutter scenes: every measurement-level tracker runs the Gaussian-clutter-only scene") {
  RunConfig cfg;
  cfg.spec = load_scenario_file(kDir + "/gaussian-clutter-only.json");
  cfg.spec.num_scans = 12;
  cfg.spec.eval_first_scan = 1;
  cfg.spec.eval_last_scan = 12;
  for (auto& t : cfg.spec.targets) t.death_scan = 12;
  for (auto& c : cfg.spec.clutter) c.death_scan = 12;
  cfg.runs = 1;
  cfg.seed = 3;
  cfg.progress = false;
  for (const TrackerInfo& info : tracker_list()) {
    if (raw_frame_or_special(info.name)) continue;
    CAPTURE(info.name);
    cfg.tracker = info.name;
    std::string error;
    try {
      const Summary sum = run_monte_carlo(cfg);
      CHECK(sum.scans == 12);
    } catch (const std::exception& e) {
      error = e.what();
    }
    CHECK_MESSAGE(error.empty(), error);
  }
}

TEST_CASE("clutter scenes: MF-BP accepts a zero uniform rate and uses the floor") {
  using P = mptrack::MfbpParams<float>;
  P p = mptrack::seed000_default_params<float>();
  p.uniform_rate_per_scan = 0.0f;
  CHECK(p.validate() == mptrack::Status::kOk);
  CHECK(mptrack::effective_uniform_rate(0.0f, p) == p.uniform_rate_floor_per_scan);
  CHECK(mptrack::effective_uniform_rate(30.0f, p) == 30.0f);  // above the floor: unchanged
  p.clutter_mode = mptrack::ClutterMode::kKnownMap;
  p.known_clutter.uniform_rate_per_scan = 0.0f;
  CHECK(p.validate() == mptrack::Status::kOk);
  p.uniform_rate_floor_per_scan = 0.0f;  // the floor itself must be positive
  mptrack::ParamError where;
  CHECK(p.validate(&where) == mptrack::Status::kInvalidArgument);
  static mptrack::MfbpTracker<float, mptrack::SmallBoardCaps> trk;
  p.uniform_rate_floor_per_scan = 1.0f;
  p.window_length = 4;  // SmallBoardCaps::kMaxWindow
  p.slide = 2;
  CHECK(trk.init(p) == mptrack::Status::kOk);
}
