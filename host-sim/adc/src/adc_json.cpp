// Strict JSON reader/writer for raw-ADC scenarios; see adc_json.h.
#include "mptrack/adc/adc_json.h"

#include <cmath>
#include <fstream>
#include <initializer_list>
#include <sstream>

namespace mptrack::adc {

using json = nlohmann::ordered_json;

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) { throw AdcScenarioError(path + ": " + what); }

std::string join(const std::string& path, const char* key) { return path.empty() ? std::string(key) : path + "." + key; }

void check_object(const json& v, const std::string& path, std::initializer_list<const char*> allowed) {
  if (!v.is_object()) fail(path.empty() ? std::string("(document)") : path, "expected an object");
  for (auto it = v.begin(); it != v.end(); ++it) {
    bool known = false;
    for (const char* k : allowed) known = known || it.key() == k;
    if (!known) fail(join(path, it.key().c_str()), "unknown field");
  }
}

const json* find(const json& obj, const char* key) {
  const auto it = obj.find(key);
  return it == obj.end() ? nullptr : &*it;
}

const json& need(const json& obj, const std::string& path, const char* key) {
  const json* v = find(obj, key);
  if (v == nullptr) fail(join(path, key), "missing");
  return *v;
}

double number(const json& v, const std::string& path) {
  if (!v.is_number()) fail(path, "expected a number");
  const double x = v.get<double>();
  if (!std::isfinite(x)) fail(path, "expected a finite number");
  return x;
}

void opt_number(const json& obj, const std::string& path, const char* key, double& out) {
  if (const json* v = find(obj, key)) out = number(*v, join(path, key));
}

std::uint32_t integer(const json& v, const std::string& path) {
  if (!v.is_number_integer() || v.get<std::int64_t>() < 0 || v.get<std::int64_t>() > 0xffffffffLL) {
    fail(path, "expected a non-negative integer");
  }
  return static_cast<std::uint32_t>(v.get<std::int64_t>());
}

void opt_integer(const json& obj, const std::string& path, const char* key, std::uint32_t& out) {
  if (const json* v = find(obj, key)) out = integer(*v, join(path, key));
}

std::array<double, 2> pair(const json& v, const std::string& path) {
  if (!v.is_array() || v.size() != 2) fail(path, "expected an array of 2 numbers");
  return {number(v[0], path + "[0]"), number(v[1], path + "[1]")};
}

void opt_pair(const json& obj, const std::string& path, const char* key, std::array<double, 2>& out) {
  if (const json* v = find(obj, key)) out = pair(*v, join(path, key));
}

std::string text(const json& v, const std::string& path) {
  if (!v.is_string()) fail(path, "expected a string");
  return v.get<std::string>();
}

template <class F>
void each(const json& obj, const std::string& path, const char* key, F&& f) {
  const json* v = find(obj, key);
  if (v == nullptr) return;
  const std::string p = join(path, key);
  if (!v->is_array()) fail(p, "expected an array");
  for (std::size_t i = 0; i < v->size(); ++i) f((*v)[i], p + "[" + std::to_string(i) + "]");
}

}  // namespace

AdcScenario adc_scenario_from_json(const json& doc) {
  check_object(doc, "", {"schema", "name", "description", "num_frames", "frame_period_s", "ospa_cutoff_m",
                         "ospa_order", "radar", "frontend", "tracker_model", "adc", "drones", "clutter_patches",
                         "chaff_clouds", "jammers", "phases"});
  if (text(need(doc, "", "schema"), "schema") != kAdcScenarioSchema) {
    fail("schema", std::string("expected \"") + kAdcScenarioSchema + "\"");
  }
  AdcScenario s;
  s.name = text(need(doc, "", "name"), "name");
  if (const json* v = find(doc, "description")) s.description = text(*v, "description");
  s.num_frames = integer(need(doc, "", "num_frames"), "num_frames");
  opt_number(doc, "", "frame_period_s", s.frame_period_s);
  opt_number(doc, "", "ospa_cutoff_m", s.ospa_cutoff_m);
  opt_number(doc, "", "ospa_order", s.ospa_order);
  if (const json* r = find(doc, "radar")) {
    const std::string p = "radar";
    check_object(*r, p, {"carrier_hz", "bandwidth_hz", "chirp_duration_s", "sample_rate_hz",
                         "element_spacing_wavelengths", "tx_amplitude", "antenna_gain", "noise_temperature_k",
                         "noise_model"});
    RadarSpec& o = s.radar;
    opt_number(*r, p, "carrier_hz", o.carrier_hz);
    opt_number(*r, p, "bandwidth_hz", o.bandwidth_hz);
    opt_number(*r, p, "chirp_duration_s", o.chirp_duration_s);
    opt_number(*r, p, "sample_rate_hz", o.sample_rate_hz);
    opt_number(*r, p, "element_spacing_wavelengths", o.element_spacing_wavelengths);
    opt_number(*r, p, "tx_amplitude", o.tx_amplitude);
    opt_number(*r, p, "antenna_gain", o.antenna_gain);
    opt_number(*r, p, "noise_temperature_k", o.noise_temperature_k);
    if (const json* v = find(*r, "noise_model")) {
      const std::string m = text(*v, "radar.noise_model");
      if (m == "model_a") o.noise_model = NoiseModel::kModelA;
      else if (m == "literal") o.noise_model = NoiseModel::kLiteral;
      else fail("radar.noise_model", "expected \"model_a\" or \"literal\"");
    }
  }
  if (const json* f = find(doc, "frontend")) {
    const std::string p = "frontend";
    check_object(*f, p, {"min_range_m", "max_range_m", "max_abs_bearing_deg", "cfar_type", "cfar_pfa",
                         "cfar_guard_cells", "cfar_training_cells", "range_window", "angle_window"});
    FrontEndSpec& o = s.frontend;
    opt_number(*f, p, "min_range_m", o.min_range_m);
    opt_number(*f, p, "max_range_m", o.max_range_m);
    opt_number(*f, p, "max_abs_bearing_deg", o.max_abs_bearing_deg);
    opt_number(*f, p, "cfar_pfa", o.cfar_pfa);
    if (const json* v = find(*f, "cfar_type")) o.cfar_type = text(*v, "frontend.cfar_type");
    if (const json* v = find(*f, "range_window")) o.range_window = text(*v, "frontend.range_window");
    if (const json* v = find(*f, "angle_window")) o.angle_window = text(*v, "frontend.angle_window");
    opt_integer(*f, p, "cfar_guard_cells", o.cfar_guard_cells);
    opt_integer(*f, p, "cfar_training_cells", o.cfar_training_cells);
  }
  if (const json* t = find(doc, "tracker_model")) {
    check_object(*t, "tracker_model", {"sigma_range_m", "sigma_bearing_deg"});
    opt_number(*t, "tracker_model", "sigma_range_m", s.tracker_model.sigma_range_m);
    opt_number(*t, "tracker_model", "sigma_bearing_deg", s.tracker_model.sigma_bearing_deg);
  }
  if (const json* a = find(doc, "adc")) {
    const std::string p = "adc";
    check_object(*a, p, {"sample_format", "bits", "full_scale_v", "saturation_fraction", "saturation_policy"});
    AdcModelSpec& o = s.adc;
    if (const json* v = find(*a, "sample_format")) o.sample_format = text(*v, "adc.sample_format");
    opt_integer(*a, p, "bits", o.bits);
    opt_number(*a, p, "full_scale_v", o.full_scale_v);
    opt_number(*a, p, "saturation_fraction", o.saturation_fraction);
    if (const json* v = find(*a, "saturation_policy")) o.saturation_policy = text(*v, "adc.saturation_policy");
  }
  need(doc, "", "drones");
  each(doc, "", "drones", [&](const json& v, const std::string& p) {
    check_object(v, p, {"id", "start_m", "velocity_mps", "birth_frame", "death_frame", "mean_rcs_m2", "swerling",
                        "legs"});
    DroneSpec d;
    d.id = integer(need(v, p, "id"), join(p, "id"));
    d.start_m = pair(need(v, p, "start_m"), join(p, "start_m"));
    d.velocity_mps = pair(need(v, p, "velocity_mps"), join(p, "velocity_mps"));
    d.birth_frame = integer(need(v, p, "birth_frame"), join(p, "birth_frame"));
    d.death_frame = integer(need(v, p, "death_frame"), join(p, "death_frame"));
    opt_number(v, p, "mean_rcs_m2", d.mean_rcs_m2);
    if (const json* w = find(v, "swerling")) d.swerling = static_cast<int>(integer(*w, join(p, "swerling")));
    each(v, p, "legs", [&](const json& l, const std::string& lp) {
      check_object(l, lp, {"steps", "velocity_mps"});
      MotionLeg leg;
      leg.steps = integer(need(l, lp, "steps"), join(lp, "steps"));
      leg.velocity_mps = pair(need(l, lp, "velocity_mps"), join(lp, "velocity_mps"));
      d.legs.push_back(leg);
    });
    s.drones.push_back(d);
  });
  each(doc, "", "clutter_patches", [&](const json& v, const std::string& p) {
    check_object(v, p, {"id", "range_m", "bearing_deg", "scatterers", "mean_rcs_m2", "birth_frame", "death_frame"});
    ClutterPatchSpec c;
    c.id = integer(need(v, p, "id"), join(p, "id"));
    const auto r = pair(need(v, p, "range_m"), join(p, "range_m"));
    const auto b = pair(need(v, p, "bearing_deg"), join(p, "bearing_deg"));
    c.range_min_m = r[0];
    c.range_max_m = r[1];
    c.bearing_min_deg = b[0];
    c.bearing_max_deg = b[1];
    c.scatterers = integer(need(v, p, "scatterers"), join(p, "scatterers"));
    opt_number(v, p, "mean_rcs_m2", c.mean_rcs_m2);
    c.birth_frame = integer(need(v, p, "birth_frame"), join(p, "birth_frame"));
    c.death_frame = integer(need(v, p, "death_frame"), join(p, "death_frame"));
    s.clutter_patches.push_back(c);
  });
  each(doc, "", "chaff_clouds", [&](const json& v, const std::string& p) {
    check_object(v, p, {"id", "centre_m", "drift_mps", "sigma0_m", "growth_mps", "scatterers", "mean_rcs_m2",
                        "birth_frame", "death_frame"});
    ChaffCloudSpec c;
    c.id = integer(need(v, p, "id"), join(p, "id"));
    c.centre_m = pair(need(v, p, "centre_m"), join(p, "centre_m"));
    opt_pair(v, p, "drift_mps", c.drift_mps);
    opt_number(v, p, "sigma0_m", c.sigma0_m);
    opt_number(v, p, "growth_mps", c.growth_mps);
    c.scatterers = integer(need(v, p, "scatterers"), join(p, "scatterers"));
    opt_number(v, p, "mean_rcs_m2", c.mean_rcs_m2);
    c.birth_frame = integer(need(v, p, "birth_frame"), join(p, "birth_frame"));
    c.death_frame = integer(need(v, p, "death_frame"), join(p, "death_frame"));
    s.chaff_clouds.push_back(c);
  });
  each(doc, "", "jammers", [&](const json& v, const std::string& p) {
    check_object(v, p, {"bearing_deg", "sources", "jnr_db", "birth_frame", "death_frame"});
    JammerSpec j;
    const auto b = pair(need(v, p, "bearing_deg"), join(p, "bearing_deg"));
    j.bearing_min_deg = b[0];
    j.bearing_max_deg = b[1];
    opt_integer(v, p, "sources", j.sources);
    j.jnr_db = number(need(v, p, "jnr_db"), join(p, "jnr_db"));
    j.birth_frame = integer(need(v, p, "birth_frame"), join(p, "birth_frame"));
    j.death_frame = integer(need(v, p, "death_frame"), join(p, "death_frame"));
    s.jammers.push_back(j);
  });
  each(doc, "", "phases", [&](const json& v, const std::string& p) {
    check_object(v, p, {"name", "frames"});
    EvalPhase e;
    e.name = text(need(v, p, "name"), join(p, "name"));
    const json& fr = need(v, p, "frames");
    if (!fr.is_array() || fr.size() != 2) fail(join(p, "frames"), "expected [first, last]");
    e.first_frame = integer(fr[0], join(p, "frames") + "[0]");
    e.last_frame = integer(fr[1], join(p, "frames") + "[1]");
    s.phases.push_back(e);
  });
  const std::string err = validate(s);
  if (!err.empty()) throw AdcScenarioError(err);
  return s;
}

json adc_scenario_to_json(const AdcScenario& s) {
  json j;
  j["schema"] = kAdcScenarioSchema;
  j["name"] = s.name;
  j["description"] = s.description;
  j["num_frames"] = s.num_frames;
  j["frame_period_s"] = s.frame_period_s;
  j["ospa_cutoff_m"] = s.ospa_cutoff_m;
  j["ospa_order"] = s.ospa_order;
  const RadarSpec& r = s.radar;
  j["radar"] = {{"carrier_hz", r.carrier_hz},
                {"bandwidth_hz", r.bandwidth_hz},
                {"chirp_duration_s", r.chirp_duration_s},
                {"sample_rate_hz", r.sample_rate_hz},
                {"element_spacing_wavelengths", r.element_spacing_wavelengths},
                {"tx_amplitude", r.tx_amplitude},
                {"antenna_gain", r.antenna_gain},
                {"noise_temperature_k", r.noise_temperature_k},
                {"noise_model", r.noise_model == NoiseModel::kModelA ? "model_a" : "literal"}};
  const FrontEndSpec& f = s.frontend;
  j["frontend"] = {{"min_range_m", f.min_range_m},
                   {"max_range_m", f.max_range_m},
                   {"max_abs_bearing_deg", f.max_abs_bearing_deg},
                   {"cfar_type", f.cfar_type},
                   {"cfar_pfa", f.cfar_pfa},
                   {"cfar_guard_cells", f.cfar_guard_cells},
                   {"cfar_training_cells", f.cfar_training_cells},
                   {"range_window", f.range_window},
                   {"angle_window", f.angle_window}};
  j["tracker_model"] = {{"sigma_range_m", s.tracker_model.sigma_range_m},
                        {"sigma_bearing_deg", s.tracker_model.sigma_bearing_deg}};
  j["adc"] = {{"sample_format", s.adc.sample_format},
              {"bits", s.adc.bits},
              {"full_scale_v", s.adc.full_scale_v},
              {"saturation_fraction", s.adc.saturation_fraction},
              {"saturation_policy", s.adc.saturation_policy}};
  j["drones"] = json::array();
  for (const DroneSpec& d : s.drones) {
    json legs = json::array();
    for (const MotionLeg& l : d.legs) legs.push_back({{"steps", l.steps}, {"velocity_mps", l.velocity_mps}});
    j["drones"].push_back({{"id", d.id},
                           {"start_m", d.start_m},
                           {"velocity_mps", d.velocity_mps},
                           {"birth_frame", d.birth_frame},
                           {"death_frame", d.death_frame},
                           {"mean_rcs_m2", d.mean_rcs_m2},
                           {"swerling", d.swerling},
                           {"legs", legs}});
  }
  j["clutter_patches"] = json::array();
  for (const ClutterPatchSpec& c : s.clutter_patches) {
    j["clutter_patches"].push_back({{"id", c.id},
                                    {"range_m", {c.range_min_m, c.range_max_m}},
                                    {"bearing_deg", {c.bearing_min_deg, c.bearing_max_deg}},
                                    {"scatterers", c.scatterers},
                                    {"mean_rcs_m2", c.mean_rcs_m2},
                                    {"birth_frame", c.birth_frame},
                                    {"death_frame", c.death_frame}});
  }
  j["chaff_clouds"] = json::array();
  for (const ChaffCloudSpec& c : s.chaff_clouds) {
    j["chaff_clouds"].push_back({{"id", c.id},
                                 {"centre_m", c.centre_m},
                                 {"drift_mps", c.drift_mps},
                                 {"sigma0_m", c.sigma0_m},
                                 {"growth_mps", c.growth_mps},
                                 {"scatterers", c.scatterers},
                                 {"mean_rcs_m2", c.mean_rcs_m2},
                                 {"birth_frame", c.birth_frame},
                                 {"death_frame", c.death_frame}});
  }
  j["jammers"] = json::array();
  for (const JammerSpec& m : s.jammers) {
    j["jammers"].push_back({{"bearing_deg", {m.bearing_min_deg, m.bearing_max_deg}},
                            {"sources", m.sources},
                            {"jnr_db", m.jnr_db},
                            {"birth_frame", m.birth_frame},
                            {"death_frame", m.death_frame}});
  }
  j["phases"] = json::array();
  for (const EvalPhase& e : s.phases) {
    j["phases"].push_back({{"name", e.name}, {"frames", {e.first_frame, e.last_frame}}});
  }
  return j;
}

AdcScenario load_adc_scenario_file(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw AdcScenarioError(path + ": cannot read");
  json doc;
  try {
    doc = json::parse(f);
  } catch (const json::parse_error& e) {
    throw AdcScenarioError(path + ": " + e.what());
  }
  try {
    return adc_scenario_from_json(doc);
  } catch (const AdcScenarioError& e) {
    throw AdcScenarioError(path + ": " + e.what());
  }
}

void save_adc_scenario_file(const AdcScenario& s, const std::string& path) {
  std::ofstream f(path);
  if (!f) throw AdcScenarioError(path + ": cannot write");
  f << adc_scenario_to_json(s).dump(2) << "\n";
}

bool is_adc_scenario_file(const std::string& path) {
  std::ifstream f(path);
  if (!f) return false;
  const json doc = json::parse(f, nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) return false;
  const auto it = doc.find("schema");
  return it != doc.end() && it->is_string() && it->get<std::string>() == kAdcScenarioSchema;
}

}  // namespace mptrack::adc
