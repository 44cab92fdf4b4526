// Strict JSON scenario reader; see scenario_json.h (the writer:
// scenario_json_write.cpp).
#include "scenario_json.h"

#include <cmath>
#include <fstream>
#include <initializer_list>
#include <ostream>
#include <sstream>

#include "mptrack/scenario/builtin.h"

namespace mptrack::sim {

using json = nlohmann::ordered_json;
using scenario::ClutterSpec;
using scenario::MotionKind;
using scenario::MotionSegment;
using scenario::ScenarioSpec;
using scenario::Swerling;
using scenario::TargetSpec;

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw ScenarioError(path + ": " + what);
}

std::string join(const std::string& path, const char* key) {
  return path.empty() ? std::string(key) : path + "." + key;
}

void require_object(const json& v, const std::string& path, std::initializer_list<const char*> allowed) {
  if (!v.is_object()) fail(path.empty() ? std::string("(document)") : path, "expected an object");
  for (auto it = v.begin(); it != v.end(); ++it) {
    bool known = false;
    for (const char* k : allowed) known = known || it.key() == k;
    if (!known) fail(join(path, it.key().c_str()), "unknown field");
  }
}

const json& member(const json& obj, const std::string& path, const char* key) {
  const auto it = obj.find(key);
  if (it == obj.end()) fail(join(path, key), "missing");
  return *it;
}

enum class Range { kAny, kPositive, kNonNegative };

double number(const json& v, const std::string& path, Range range = Range::kAny) {
  const char* expect = range == Range::kPositive      ? "expected a positive number"
                       : range == Range::kNonNegative ? "expected a non-negative number"
                                                      : "expected a finite number";
  if (!v.is_number()) fail(path, expect);
  const double x = v.get<double>();
  if (!std::isfinite(x) || (range == Range::kPositive && !(x > 0.0)) ||
      (range == Range::kNonNegative && !(x >= 0.0))) {
    fail(path, expect);
  }
  return x;
}

double number_field(const json& obj, const std::string& path, const char* key, Range range = Range::kAny) {
  return number(member(obj, path, key), join(path, key), range);
}

double optional_number(const json& obj, const std::string& path, const char* key, double fallback,
                       Range range = Range::kAny) {
  const auto it = obj.find(key);
  return it == obj.end() ? fallback : number(*it, join(path, key), range);
}

std::uint32_t uint_value(const json& v, const std::string& path) {
  if (!v.is_number_integer() || v.get<std::int64_t>() < 0 || v.get<std::int64_t>() > 0xffffffffLL) {
    fail(path, "expected a non-negative integer");
  }
  return static_cast<std::uint32_t>(v.get<std::int64_t>());
}

std::string string_field(const json& obj, const std::string& path, const char* key) {
  const json& v = member(obj, path, key);
  if (!v.is_string()) fail(join(path, key), "expected a string");
  return v.get<std::string>();
}

template <std::size_t N>
std::array<double, N> number_array(const json& obj, const std::string& path, const char* key) {
  const json& v = member(obj, path, key);
  const std::string p = join(path, key);
  if (!v.is_array() || v.size() != N) fail(p, "expected an array of " + std::to_string(N) + " numbers");
  std::array<double, N> out{};
  for (std::size_t i = 0; i < N; ++i) out[i] = number(v[i], p + "[" + std::to_string(i) + "]");
  return out;
}

void lifetime(const json& obj, const std::string& path, std::uint32_t& birth, std::uint32_t& death) {
  const json& v = member(obj, path, "lifetime");
  const std::string p = join(path, "lifetime");
  if (!v.is_array() || v.size() != 2) fail(p, "expected [birth_scan, death_scan]");
  birth = uint_value(v[0], p + "[0]");
  death = uint_value(v[1], p + "[1]");
}

Swerling swerling(const json& obj, const std::string& path) {
  const auto it = obj.find("swerling");
  if (it == obj.end()) return Swerling::kOne;
  if (!it->is_number_integer() || (it->get<int>() != 1 && it->get<int>() != 3)) {
    fail(join(path, "swerling"), "expected 1 or 3");
  }
  return it->get<int>() == 3 ? Swerling::kThree : Swerling::kOne;
}

MotionSegment motion_segment(const json& v, const std::string& path) {
  MotionSegment m;
  const std::string type = v.is_object() ? string_field(v, path, "type") : std::string();
  if (type == "cv") {
    require_object(v, path, {"start_s", "type"});
    m.kind = MotionKind::kConstantVelocity;
  } else if (type == "ca") {
    require_object(v, path, {"start_s", "type", "accel_mps2"});
    m.kind = MotionKind::kConstantAcceleration;
    m.accel_mps2 = number_array<2>(v, path, "accel_mps2");
  } else if (type == "ct") {
    require_object(v, path, {"start_s", "type", "turn_rate_deg_s"});
    m.kind = MotionKind::kCoordinatedTurn;
    m.turn_rate_deg_s = number_field(v, path, "turn_rate_deg_s");
  } else if (type == "set_velocity") {
    require_object(v, path, {"start_s", "type", "velocity_mps"});
    m.kind = MotionKind::kSetVelocity;
    m.velocity_mps = number_array<2>(v, path, "velocity_mps");
  } else {
    if (!v.is_object()) fail(path, "expected an object");
    fail(join(path, "type"), "expected \"cv\", \"ca\", \"ct\" or \"set_velocity\"");
  }
  m.start_s = number_field(v, path, "start_s");
  return m;
}

// OTHR target (seed 002): "ground_state" [g km, g_dot km/s, theta rad,
// theta_dot rad/s] instead of "initial_state" and "motion"; "snr" optional.
TargetSpec othr_target(const json& v, const std::string& path) {
  require_object(v, path, {"id", "ground_state", "lifetime", "snr"});
  TargetSpec t;
  t.id = uint_value(member(v, path, "id"), join(path, "id"));
  t.ground_state = number_array<4>(v, path, "ground_state");
  lifetime(v, path, t.birth_scan, t.death_scan);
  t.snr = optional_number(v, path, "snr", 1.0, Range::kPositive);
  return t;
}

// OTHR "paths": {"baseline_km": d, "list": [{"name", "tx_height_km", "rx_height_km", "pd"}, ...]}.
void othr_paths(const json& doc, scenario::OthrSpec& o) {
  const json& paths = member(doc, "", "paths");
  require_object(paths, "paths", {"baseline_km", "list"});
  o.baseline_km = number_field(paths, "paths", "baseline_km");
  const json& list = member(paths, "paths", "list");
  if (!list.is_array()) fail("paths.list", "expected an array of paths");
  o.paths.clear();
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string p = "paths.list[" + std::to_string(i) + "]";
    require_object(list[i], p, {"name", "tx_height_km", "rx_height_km", "pd"});
    scenario::OthrPathSpec ps;
    ps.name = string_field(list[i], p, "name");
    ps.tx_height_km = number_field(list[i], p, "tx_height_km");
    ps.rx_height_km = number_field(list[i], p, "rx_height_km");
    ps.pd = number_field(list[i], p, "pd", Range::kPositive);
    o.paths.push_back(ps);
  }
}

TargetSpec target(const json& v, const std::string& path) {
  require_object(v, path, {"id", "initial_state", "lifetime", "snr", "swerling", "motion"});
  TargetSpec t;
  t.id = uint_value(member(v, path, "id"), join(path, "id"));
  t.initial_state = number_array<4>(v, path, "initial_state");
  lifetime(v, path, t.birth_scan, t.death_scan);
  t.snr = number_field(v, path, "snr", Range::kPositive);
  t.swerling = swerling(v, path);
  const auto it = v.find("motion");
  if (it != v.end()) {
    const std::string p = join(path, "motion");
    if (!it->is_array()) fail(p, "expected an array of segments");
    for (std::size_t i = 0; i < it->size(); ++i) {
      t.motion.push_back(motion_segment((*it)[i], p + "[" + std::to_string(i) + "]"));
    }
  }
  return t;
}

// Optional "amplitude": {"model": "weibull", "shape": b, "scale": sigma0}
// (docs/algorithms/models.md §Amplitude likelihoods); it replaces "cnr" and "swerling".
void clutter_amplitude(const json& v, const std::string& path, ClutterSpec& c) {
  const std::string pa = join(path, "amplitude");
  const json& a = member(v, path, "amplitude");
  require_object(a, pa, {"model", "shape", "scale"});
  if (string_field(a, pa, "model") != "weibull") fail(join(pa, "model"), "expected \"weibull\"");
  c.amplitude = scenario::ClutterAmplitude::kWeibull;
  c.weibull_shape = number_field(a, pa, "shape", Range::kPositive);
  c.weibull_scale = number_field(a, pa, "scale", Range::kPositive);
}

ClutterSpec clutter(const json& v, const std::string& path, bool cartesian) {
  ClutterSpec c;
  const std::string type = v.is_object() ? string_field(v, path, "type") : std::string();
  const bool weibull = v.is_object() && v.contains("amplitude");
  if (weibull && (type == "uniform" || type == "gaussian")) {
    if (type == "uniform") {
      require_object(v, path, {"id", "type", "mean_count", "amplitude", "lifetime", "variation"});
    } else {
      require_object(v, path, {"id", "type", "mean_count", "mean", "spread", "amplitude", "lifetime", "variation"});
    }
    clutter_amplitude(v, path, c);
  }
  if (type == "gaussian" && cartesian) {
    if (!weibull) {
      require_object(v, path,
                     {"id", "type", "mean_count", "mean", "spread", "cnr", "swerling", "lifetime", "variation"});
    }
    c.uniform = false;
    const std::string pm = join(path, "mean");
    const json& mean = member(v, path, "mean");
    require_object(mean, pm, {"x_m", "y_m"});
    c.mean_x_m = number_field(mean, pm, "x_m");
    c.mean_y_m = number_field(mean, pm, "y_m");
    const std::string ps = join(path, "spread");
    const json& spread = member(v, path, "spread");
    require_object(spread, ps, {"sigma_x_m", "sigma_y_m", "correlation"});
    c.sigma_x_m = number_field(spread, ps, "sigma_x_m", Range::kPositive);
    c.sigma_y_m = number_field(spread, ps, "sigma_y_m", Range::kPositive);
    c.correlation = optional_number(spread, ps, "correlation", 0.0);
  } else if (type == "uniform") {
    if (!weibull) require_object(v, path, {"id", "type", "mean_count", "cnr", "swerling", "lifetime", "variation"});
    c.uniform = true;
  } else if (type == "gaussian") {
    if (!weibull) {
      require_object(v, path,
                     {"id", "type", "mean_count", "mean", "spread", "cnr", "swerling", "lifetime", "variation"});
    }
    c.uniform = false;
    const std::string pm = join(path, "mean");
    const json& mean = member(v, path, "mean");
    require_object(mean, pm, {"range_m", "azimuth_deg"});
    c.mean_range_m = number_field(mean, pm, "range_m", Range::kNonNegative);
    c.mean_azimuth_deg = number_field(mean, pm, "azimuth_deg");
    const std::string ps = join(path, "spread");
    const json& spread = member(v, path, "spread");
    require_object(spread, ps, {"sigma_range_m", "sigma_azimuth_deg", "correlation"});
    c.sigma_range_m = number_field(spread, ps, "sigma_range_m", Range::kPositive);
    c.sigma_azimuth_deg = number_field(spread, ps, "sigma_azimuth_deg", Range::kPositive);
    c.correlation = optional_number(spread, ps, "correlation", 0.0);
  } else {
    if (!v.is_object()) fail(path, "expected an object");
    fail(join(path, "type"), "expected \"uniform\" or \"gaussian\"");
  }
  c.id = uint_value(member(v, path, "id"), join(path, "id"));
  c.mean_count = number_field(v, path, "mean_count", Range::kNonNegative);
  if (!weibull) {
    c.cnr = number_field(v, path, "cnr", Range::kPositive);
    c.swerling = swerling(v, path);
  }
  lifetime(v, path, c.birth_scan, c.death_scan);
  const auto it = v.find("variation");
  if (it != v.end()) {
    const std::string pv = join(path, "variation");
    require_object(*it, pv, {"count_sin_amplitude", "cov_scale", "drift_range_mps", "drift_azimuth_deg_s"});
    c.variation.count_sin_amplitude = optional_number(*it, pv, "count_sin_amplitude", 0.0);
    if (it->contains("cov_scale")) {
      const auto s = number_array<2>(*it, pv, "cov_scale");
      c.variation.cov_scale_start = s[0];
      c.variation.cov_scale_end = s[1];
    }
    c.variation.drift_range_mps = optional_number(*it, pv, "drift_range_mps", 0.0);
    c.variation.drift_azimuth_deg_s = optional_number(*it, pv, "drift_azimuth_deg_s", 0.0);
  }
  return c;
}

}  // namespace

ScenarioSpec scenario_from_json(const json& doc) {
  require_object(doc, "", {"schema", "name", "description", "scans", "scan_period_s", "measurement_space",
                           "region", "measurement_noise", "threshold", "evaluation", "targets", "clutter",
                           "paths"});
  ScenarioSpec s;
  if (string_field(doc, "", "schema") != kScenarioSchema) {
    fail("schema", std::string("expected \"") + kScenarioSchema + "\"");
  }
  s.name = string_field(doc, "", "name");
  s.description = doc.contains("description") ? string_field(doc, "", "description") : std::string();
  s.num_scans = uint_value(member(doc, "", "scans"), "scans");
  s.scan_period_s = number_field(doc, "", "scan_period_s", Range::kPositive);

  // Optional "measurement_space": "polar" (default, seed 000) | "cartesian" (seed 001).
  if (doc.contains("measurement_space")) {
    const std::string space = string_field(doc, "", "measurement_space");
    if (space == "cartesian") {
      s.space = scenario::MeasurementSpace::kCartesian;
    } else if (space == "othr") {
      s.space = scenario::MeasurementSpace::kOthr;
    } else if (space != "polar") {
      fail("measurement_space", "expected \"polar\", \"cartesian\" or \"othr\"");
    }
  }
  const bool cartesian = s.space == scenario::MeasurementSpace::kCartesian;
  const bool othr = s.space == scenario::MeasurementSpace::kOthr;
  if (!othr && doc.contains("paths")) fail("paths", "only an OTHR scenario has propagation paths");
  const json& region = member(doc, "", "region");
  const json& noise = member(doc, "", "measurement_noise");
  if (cartesian) {
    require_object(region, "region", {"x_m", "y_m"});
    const auto rx = number_array<2>(region, "region", "x_m");
    const auto ry = number_array<2>(region, "region", "y_m");
    s.xy_region = scenario::CartesianRegion{rx[0], rx[1], ry[0], ry[1]};
    require_object(noise, "measurement_noise", {"sigma_xy_m"});
    s.sigma_xy_m = number_field(noise, "measurement_noise", "sigma_xy_m", Range::kPositive);
  } else if (othr) {
    // Slant range, azimuth and a symmetric range-rate interval.
    require_object(region, "region", {"range_m", "azimuth_deg", "range_rate_max_mps"});
    const auto rr = number_array<2>(region, "region", "range_m");
    const auto ra = number_array<2>(region, "region", "azimuth_deg");
    s.region = scenario::Region{rr[0], rr[1], ra[0], ra[1]};
    s.othr.range_rate_max_mps = number_field(region, "region", "range_rate_max_mps", Range::kPositive);
    require_object(noise, "measurement_noise", {"sigma_range_m", "sigma_azimuth_deg", "sigma_range_rate_mps"});
    s.sigma_range_m = number_field(noise, "measurement_noise", "sigma_range_m", Range::kPositive);
    s.sigma_azimuth_deg = number_field(noise, "measurement_noise", "sigma_azimuth_deg", Range::kPositive);
    s.othr.sigma_range_rate_mps = number_field(noise, "measurement_noise", "sigma_range_rate_mps", Range::kPositive);
    othr_paths(doc, s.othr);
  } else {
    require_object(region, "region", {"range_m", "azimuth_deg"});
    const auto rr = number_array<2>(region, "region", "range_m");
    const auto ra = number_array<2>(region, "region", "azimuth_deg");
    s.region = scenario::Region{rr[0], rr[1], ra[0], ra[1]};
    require_object(noise, "measurement_noise", {"sigma_range_m", "sigma_azimuth_deg"});
    s.sigma_range_m = number_field(noise, "measurement_noise", "sigma_range_m", Range::kPositive);
    s.sigma_azimuth_deg = number_field(noise, "measurement_noise", "sigma_azimuth_deg", Range::kPositive);
  }
  s.threshold = number_field(doc, "", "threshold", Range::kPositive);

  s.eval_first_scan = 1;
  s.eval_last_scan = s.num_scans;
  const auto ev = doc.find("evaluation");
  if (ev != doc.end()) {
    require_object(*ev, "evaluation", {"first_scan", "last_scan"});
    if (ev->contains("first_scan")) s.eval_first_scan = uint_value((*ev)["first_scan"], "evaluation.first_scan");
    if (ev->contains("last_scan")) s.eval_last_scan = uint_value((*ev)["last_scan"], "evaluation.last_scan");
  }

  const json& targets = member(doc, "", "targets");
  if (!targets.is_array()) fail("targets", "expected an array");
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const std::string p = "targets[" + std::to_string(i) + "]";
    s.targets.push_back(othr ? othr_target(targets[i], p) : target(targets[i], p));
  }
  const json& clut = member(doc, "", "clutter");
  if (!clut.is_array()) fail("clutter", "expected an array");
  for (std::size_t i = 0; i < clut.size(); ++i) {
    s.clutter.push_back(clutter(clut[i], "clutter[" + std::to_string(i) + "]", cartesian));
  }

  const std::string error = scenario::validate(s);
  if (!error.empty()) throw ScenarioError(error);
  return s;
}

ScenarioSpec load_scenario_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ScenarioError(path + ": cannot open file");
  json doc;
  try {
    doc = json::parse(in);
  } catch (const json::parse_error& e) {
    throw ScenarioError(path + ": invalid JSON (" + e.what() + ")");
  }
  try {
    return scenario_from_json(doc);
  } catch (const ScenarioError& e) {
    throw ScenarioError(path + ": " + e.what());
  }
}

ScenarioSpec resolve_scenario(const std::string& name_or_file) {
  ScenarioSpec s;
  if (scenario::builtin_scenario(name_or_file, s)) return s;
  return load_scenario_file(name_or_file);
}

}  // namespace mptrack::sim
