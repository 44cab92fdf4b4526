// Scenario writer: ScenarioSpec to the JSON schema that scenario_json.cpp
// reads (host-sim/scenarios/*.json), indented for people to edit.
#include <fstream>
#include <ostream>

#include "scenario_json.h"

namespace mptrack::sim {

using json = nlohmann::ordered_json;
namespace sc = scenario;

namespace {

json lifetime_json(std::uint32_t birth, std::uint32_t death) { return json::array({birth, death}); }

// Indented like dump(2), but arrays of scalars stay on one line ([1, 340]).
void pretty(std::ostream& out, const json& v, int indent) {
  const std::string pad(static_cast<std::size_t>(indent) + 2, ' ');
  if (v.is_object() && !v.empty()) {
    out << "{\n";
    std::size_t i = 0;
    for (auto it = v.begin(); it != v.end(); ++it, ++i) {
      out << pad << json(it.key()).dump() << ": ";
      pretty(out, it.value(), indent + 2);
      out << (i + 1 < v.size() ? ",\n" : "\n");
    }
    out << std::string(static_cast<std::size_t>(indent), ' ') << "}";
    return;
  }
  if (v.is_array() && !v.empty()) {
    bool scalars = true;
    for (const auto& e : v) scalars = scalars && e.is_primitive();
    if (scalars) {
      out << "[";
      for (std::size_t i = 0; i < v.size(); ++i) out << (i ? ", " : "") << v[i].dump();
      out << "]";
      return;
    }
    out << "[\n";
    for (std::size_t i = 0; i < v.size(); ++i) {
      out << pad;
      pretty(out, v[i], indent + 2);
      out << (i + 1 < v.size() ? ",\n" : "\n");
    }
    out << std::string(static_cast<std::size_t>(indent), ' ') << "]";
    return;
  }
  out << v.dump();
}

json target_json(const sc::TargetSpec& t, bool othr) {
  if (othr) {
    return {{"id", t.id},
            {"ground_state", t.ground_state},
            {"lifetime", lifetime_json(t.birth_scan, t.death_scan)},
            {"snr", t.snr}};
  }
  json j = {{"id", t.id},
            {"initial_state", t.initial_state},
            {"lifetime", lifetime_json(t.birth_scan, t.death_scan)},
            {"snr", t.snr},
            {"swerling", static_cast<int>(t.swerling)}};
  json motion = json::array();
  for (const sc::MotionSegment& m : t.motion) {
    json seg = {{"start_s", m.start_s}};
    switch (m.kind) {
      case sc::MotionKind::kConstantVelocity: seg["type"] = "cv"; break;
      case sc::MotionKind::kConstantAcceleration:
        seg["type"] = "ca";
        seg["accel_mps2"] = m.accel_mps2;
        break;
      case sc::MotionKind::kCoordinatedTurn:
        seg["type"] = "ct";
        seg["turn_rate_deg_s"] = m.turn_rate_deg_s;
        break;
      case sc::MotionKind::kSetVelocity:
        seg["type"] = "set_velocity";
        seg["velocity_mps"] = m.velocity_mps;
        break;
    }
    motion.push_back(seg);
  }
  j["motion"] = motion;
  return j;
}

json clutter_json(const sc::ClutterSpec& c, bool cartesian) {
  json j = {{"id", c.id}, {"type", c.uniform ? "uniform" : "gaussian"}, {"mean_count", c.mean_count}};
  if (!c.uniform && cartesian) {
    j["mean"] = {{"x_m", c.mean_x_m}, {"y_m", c.mean_y_m}};
    j["spread"] = {{"sigma_x_m", c.sigma_x_m}, {"sigma_y_m", c.sigma_y_m}, {"correlation", c.correlation}};
  } else if (!c.uniform) {
    j["mean"] = {{"range_m", c.mean_range_m}, {"azimuth_deg", c.mean_azimuth_deg}};
    j["spread"] = {{"sigma_range_m", c.sigma_range_m},
                   {"sigma_azimuth_deg", c.sigma_azimuth_deg},
                   {"correlation", c.correlation}};
  }
  if (c.amplitude == sc::ClutterAmplitude::kWeibull) {
    j["amplitude"] = {{"model", "weibull"}, {"shape", c.weibull_shape}, {"scale", c.weibull_scale}};
  } else {
    j["cnr"] = c.cnr;
    j["swerling"] = static_cast<int>(c.swerling);
  }
  j["lifetime"] = lifetime_json(c.birth_scan, c.death_scan);
  const sc::TimeVariation& v = c.variation;
  if (!(v == sc::TimeVariation{})) {
    j["variation"] = {{"count_sin_amplitude", v.count_sin_amplitude},
                      {"cov_scale", {v.cov_scale_start, v.cov_scale_end}},
                      {"drift_range_mps", v.drift_range_mps},
                      {"drift_azimuth_deg_s", v.drift_azimuth_deg_s}};
  }
  return j;
}

}  // namespace

json scenario_to_json(const sc::ScenarioSpec& s) {
  json doc = json::object();
  doc["schema"] = kScenarioSchema;
  doc["name"] = s.name;
  doc["description"] = s.description;
  doc["scans"] = s.num_scans;
  doc["scan_period_s"] = s.scan_period_s;
  const bool cartesian = s.space == sc::MeasurementSpace::kCartesian;
  const bool othr = s.space == sc::MeasurementSpace::kOthr;
  if (cartesian) {
    doc["measurement_space"] = "cartesian";
    doc["region"] = {{"x_m", {s.xy_region.x_min_m, s.xy_region.x_max_m}},
                     {"y_m", {s.xy_region.y_min_m, s.xy_region.y_max_m}}};
    doc["measurement_noise"] = {{"sigma_xy_m", s.sigma_xy_m}};
  } else if (othr) {
    doc["measurement_space"] = "othr";
    doc["region"] = {{"range_m", {s.region.range_min_m, s.region.range_max_m}},
                     {"azimuth_deg", {s.region.azimuth_min_deg, s.region.azimuth_max_deg}},
                     {"range_rate_max_mps", s.othr.range_rate_max_mps}};
    doc["measurement_noise"] = {{"sigma_range_m", s.sigma_range_m},
                                {"sigma_azimuth_deg", s.sigma_azimuth_deg},
                                {"sigma_range_rate_mps", s.othr.sigma_range_rate_mps}};
    json list = json::array();
    for (const sc::OthrPathSpec& p : s.othr.paths) {
      list.push_back({{"name", p.name}, {"tx_height_km", p.tx_height_km}, {"rx_height_km", p.rx_height_km}, {"pd", p.pd}});
    }
    doc["paths"] = {{"baseline_km", s.othr.baseline_km}, {"list", list}};
  } else {
    doc["region"] = {{"range_m", {s.region.range_min_m, s.region.range_max_m}},
                     {"azimuth_deg", {s.region.azimuth_min_deg, s.region.azimuth_max_deg}}};
    doc["measurement_noise"] = {{"sigma_range_m", s.sigma_range_m}, {"sigma_azimuth_deg", s.sigma_azimuth_deg}};
  }
  doc["threshold"] = s.threshold;
  doc["evaluation"] = {{"first_scan", s.eval_first_scan}, {"last_scan", s.eval_last_scan}};
  json targets = json::array();
  for (const sc::TargetSpec& t : s.targets) targets.push_back(target_json(t, othr));
  doc["targets"] = targets;
  json clut = json::array();
  for (const sc::ClutterSpec& c : s.clutter) clut.push_back(clutter_json(c, cartesian));
  doc["clutter"] = clut;
  return doc;
}

void save_scenario_file(const sc::ScenarioSpec& spec, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw ScenarioError(path + ": cannot write file");
  pretty(out, scenario_to_json(spec), 0);
  out << "\n";
  if (!out) throw ScenarioError(path + ": write failed");
}

}  // namespace mptrack::sim
