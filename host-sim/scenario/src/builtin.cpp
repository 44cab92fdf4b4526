// Seed 000 scenarios (spec 4.1-4.4). [impl] choices are the spec's defaults:
// region r in [10, 50] km x az in [10, 60] deg (A20), Poisson clutter (A21),
// T1/T2 piecewise truth (A19), Swerling I for S2/S3 (A30), uniform CNR 1 (A17).
#include "mptrack/scenario/builtin.h"

namespace mptrack::scenario {

namespace {

constexpr std::uint32_t kScans = 340;

MotionSegment ca(double start_s, double ax, double ay) {
  MotionSegment m;
  m.start_s = start_s;
  m.kind = MotionKind::kConstantAcceleration;
  m.accel_mps2 = {ax, ay};
  return m;
}

MotionSegment set_velocity(double start_s, double vx, double vy) {
  MotionSegment m;
  m.start_s = start_s;
  m.kind = MotionKind::kSetVelocity;
  m.velocity_mps = {vx, vy};
  return m;
}

TargetSpec target(std::uint32_t id, double px, double vx, double py, double vy, double snr) {
  TargetSpec t;
  t.id = id;
  t.initial_state = {px, vx, py, vy};
  t.birth_scan = 1;
  t.death_scan = kScans;
  t.snr = snr;
  t.swerling = Swerling::kOne;
  return t;
}

// Targets 1 and 2 (spec 4.1 default truth, A19): CV for 25 s, then a constant
// a_y for 121.875 s until v_y = 0 (|a_y| = 40 / 121.875 m/s^2), then CV,
// parallel at y = 10027.5 m and 10007.5 m. The set_velocity segment pins v_y
// to exactly 0 so rounding in a_y cannot leave a drift.
constexpr double kManeuverStart_s = 25.0;
constexpr double kManeuverEnd_s = 146.875;
constexpr double kAy = 40.0 / 121.875;

void add_targets_1_2(ScenarioSpec& s, double snr1, double snr2) {
  TargetSpec t1 = target(1, 10000.0, 40.0, 13465.0, -40.0, snr1);
  t1.motion = {ca(kManeuverStart_s, 0.0, kAy), set_velocity(kManeuverEnd_s, 40.0, 0.0)};
  TargetSpec t2 = target(2, 10000.0, 40.0, 6570.0, 40.0, snr2);
  t2.motion = {ca(kManeuverStart_s, 0.0, -kAy), set_velocity(kManeuverEnd_s, 40.0, 0.0)};
  s.targets.push_back(t1);
  s.targets.push_back(t2);
}

// Targets 3-5: constant velocity, crossing near k = 170.5 (spec 4.1).
void add_targets_3_5(ScenarioSpec& s) {
  s.targets.push_back(target(3, 28000.0, 40.0, 20543.0, -12.0, 10.0 / 3.0));
  s.targets.push_back(target(4, 28000.0, 40.0, 18000.0, 0.0, 50.0 / 3.0));
  s.targets.push_back(target(5, 28000.0, 40.0, 15458.0, 12.0, 10.0 / 3.0));
}

ClutterSpec uniform_clutter() {
  ClutterSpec c;
  c.id = 0;
  c.uniform = true;
  c.mean_count = 30.0;
  c.cnr = 1.0;
  c.birth_scan = 1;
  c.death_scan = kScans;
  return c;
}

ClutterSpec gaussian(std::uint32_t id, double count, double r_m, double az_deg, std::uint32_t birth,
                     std::uint32_t death, double cnr) {
  ClutterSpec c;
  c.id = id;
  c.uniform = false;
  c.mean_count = count;
  c.mean_range_m = r_m;
  c.mean_azimuth_deg = az_deg;
  c.sigma_range_m = 1000.0;  // Table III: diag(1 km, 3 deg)^2
  c.sigma_azimuth_deg = 3.0;
  c.correlation = 0.0;
  c.cnr = cnr;
  c.birth_scan = birth;
  c.death_scan = death;
  return c;
}

ScenarioSpec base(const char* name, const char* description) {
  ScenarioSpec s;
  s.name = name;
  s.description = description;
  s.num_scans = kScans;
  s.scan_period_s = 1.25;
  s.region = Region{10000.0, 50000.0, 10.0, 60.0};
  s.sigma_range_m = 20.0;
  s.sigma_azimuth_deg = 0.6;
  s.threshold = 0.715;
  s.eval_first_scan = 1;
  s.eval_last_scan = kScans;
  return s;
}

void add_table3_components(ScenarioSpec& s, bool time_varying) {
  s.clutter.push_back(uniform_clutter());
  s.clutter.push_back(gaussian(1, 20.0, 20000.0, 30.0, 130, 170, 20.0 / 3.0));   // chaff near T1/T2
  s.clutter.push_back(gaussian(2, 20.0, 27000.0, 23.0, 227, 280, 10.0));         // atmospheric "fog"
  s.clutter.push_back(gaussian(3, 30.0, 41000.0, 27.0, 172, 225, 20.0 / 3.0));   // chaff near T3-T5
  if (time_varying) {
    for (ClutterSpec& c : s.clutter) {
      if (c.uniform) continue;
      c.variation.count_sin_amplitude = 0.5;     // P104: lambda = (1 + sin(pi f)/2) lambda_0
      c.variation.cov_scale_start = 1.0 / 3.0;   // P104: Cov = (1/3 + f) Cov_0
      c.variation.cov_scale_end = 4.0 / 3.0;
    }
  }
}

ScenarioSpec make_s1() {
  ScenarioSpec s = base("seed000-s1",
                        "Seed 000 Scenario 1 (Table IV): Targets 1 and 2 (close, then parallel 20 m apart) in "
                        "uniform clutter; Table V column (SNR 10/3, 10), Swerling I. Evaluated on the second "
                        "interval, k >= 119.");
  add_targets_1_2(s, 10.0 / 3.0, 10.0);
  s.clutter.push_back(uniform_clutter());
  s.eval_first_scan = 119;
  return s;
}

ScenarioSpec make_s2() {
  ScenarioSpec s = base("seed000-s2",
                        "Seed 000 Scenario 2 (Table IV): five targets (Table II), uniform clutter and three "
                        "non-uniform components of constant count and shape (Table III), Swerling I.");
  add_targets_1_2(s, 10.0 / 3.0, 50.0 / 3.0);
  add_targets_3_5(s);
  add_table3_components(s, false);
  return s;
}

ScenarioSpec make_s3() {
  ScenarioSpec s = base("seed000-s3",
                        "Seed 000 Scenario 3 (Table IV): as Scenario 2, with time-varying non-uniform clutter "
                        "(P104: count (1 + sin(pi f)/2) lambda_0, covariance (1/3 + f) Cov_0).");
  add_targets_1_2(s, 10.0 / 3.0, 50.0 / 3.0);
  add_targets_3_5(s);
  add_table3_components(s, true);
  return s;
}

}  // namespace

std::vector<std::string> builtin_scenario_names() { return {"seed000-s1", "seed000-s2", "seed000-s3"}; }

bool builtin_scenario(const std::string& name, ScenarioSpec& out) {
  if (name == "seed000-s1") {
    out = make_s1();
  } else if (name == "seed000-s2") {
    out = make_s2();
  } else if (name == "seed000-s3") {
    out = make_s3();
  } else {
    return false;
  }
  return true;
}

void set_table5_row(ScenarioSpec& s1, Swerling swerling, double snr1, double snr2) {
  for (TargetSpec& t : s1.targets) {
    t.swerling = swerling;
    if (t.id == 1) t.snr = snr1;
    if (t.id == 2) t.snr = snr2;
  }
  for (ClutterSpec& c : s1.clutter) c.swerling = swerling;
}

}  // namespace mptrack::scenario
