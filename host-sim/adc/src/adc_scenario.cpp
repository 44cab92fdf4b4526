// Validation, equality and the built-in raw-ADC scenarios; see adc_scenario.h.
// The built-ins mirror host-sim/scenarios/{seed004-drones,mimo-interference}.json
// exactly (adc_json_test checks the shipped files against them).
#include "mptrack/adc/adc_scenario.h"

#include <cmath>
#include <set>

namespace mptrack::adc {

namespace {

std::string idx(const char* list, std::size_t i) { return std::string(list) + "[" + std::to_string(i) + "]"; }

bool pos(double x) { return std::isfinite(x) && x > 0.0; }
bool nonneg(double x) { return std::isfinite(x) && x >= 0.0; }
bool fin(double x) { return std::isfinite(x); }

std::string lifetime(const std::string& p, std::uint32_t birth, std::uint32_t death, std::uint32_t frames) {
  if (birth < 1 || birth > frames) return p + ".birth_frame: expected 1..num_frames";
  if (death < birth || death > frames) return p + ".death_frame: expected birth_frame..num_frames";
  return "";
}

}  // namespace

std::string validate(const AdcScenario& s) {
  if (s.name.empty()) return "name: expected a non-empty string";
  if (s.num_frames < 1) return "num_frames: expected a positive integer";
  if (!pos(s.frame_period_s)) return "frame_period_s: expected a positive number";
  if (!pos(s.ospa_cutoff_m)) return "ospa_cutoff_m: expected a positive number";
  if (!(fin(s.ospa_order) && s.ospa_order >= 1.0)) return "ospa_order: expected a number >= 1";
  const RadarSpec& r = s.radar;
  if (!pos(r.carrier_hz)) return "radar.carrier_hz: expected a positive number";
  if (!pos(r.bandwidth_hz)) return "radar.bandwidth_hz: expected a positive number";
  if (!pos(r.chirp_duration_s)) return "radar.chirp_duration_s: expected a positive number";
  if (!pos(r.sample_rate_hz)) return "radar.sample_rate_hz: expected a positive number";
  if (!(pos(r.element_spacing_wavelengths) && r.element_spacing_wavelengths <= 1.0))
    return "radar.element_spacing_wavelengths: expected a number in (0, 1]";
  if (!pos(r.tx_amplitude)) return "radar.tx_amplitude: expected a positive number";
  if (!pos(r.antenna_gain)) return "radar.antenna_gain: expected a positive number";
  if (!pos(r.noise_temperature_k)) return "radar.noise_temperature_k: expected a positive number";
  const FrontEndSpec& f = s.frontend;
  if (!nonneg(f.min_range_m)) return "frontend.min_range_m: expected a non-negative number";
  if (!(pos(f.max_range_m) && f.max_range_m > f.min_range_m))
    return "frontend.max_range_m: expected a number > min_range_m";
  if (!(pos(f.max_abs_bearing_deg) && f.max_abs_bearing_deg <= 90.0))
    return "frontend.max_abs_bearing_deg: expected a number in (0, 90]";
  if (!(pos(f.cfar_pfa) && f.cfar_pfa <= 0.5)) return "frontend.cfar_pfa: expected a number in (0, 0.5]";
  if (f.cfar_type != "ca" && f.cfar_type != "go" && f.cfar_type != "so" && f.cfar_type != "os")
    return "frontend.cfar_type: expected \"ca\", \"go\", \"so\" or \"os\"";
  for (const auto& [w, name] : {std::pair<const std::string&, const char*>{f.range_window, "range_window"},
                                std::pair<const std::string&, const char*>{f.angle_window, "angle_window"}}) {
    if (w != "rectangular" && w != "hann" && w != "hamming" && w != "blackman")
      return std::string("frontend.") + name + ": expected \"rectangular\", \"hann\", \"hamming\" or \"blackman\"";
  }
  if (f.cfar_guard_cells > 64) return "frontend.cfar_guard_cells: expected 0..64";
  if (f.cfar_training_cells < 1 || f.cfar_training_cells > 64) return "frontend.cfar_training_cells: expected 1..64";
  if (!pos(s.tracker_model.sigma_range_m)) return "tracker_model.sigma_range_m: expected a positive number";
  if (!pos(s.tracker_model.sigma_bearing_deg)) return "tracker_model.sigma_bearing_deg: expected a positive number";
  const AdcModelSpec& a = s.adc;
  if (a.sample_format != "float" && a.sample_format != "int16")
    return "adc.sample_format: expected \"float\" or \"int16\"";
  if (a.bits < 2 || a.bits > 16) return "adc.bits = " + std::to_string(a.bits) + ": expected 2..16";
  if (!(pos(a.full_scale_v) && a.full_scale_v <= 1e3))
    return "adc.full_scale_v: expected a number in (0, 1000] V";
  if (!(nonneg(a.saturation_fraction) && a.saturation_fraction <= 1.0))
    return "adc.saturation_fraction: expected a number in [0, 1]";
  if (a.saturation_policy != "keep" && a.saturation_policy != "drop")
    return "adc.saturation_policy: expected \"keep\" or \"drop\"";
  std::set<std::uint32_t> ids;
  for (std::size_t i = 0; i < s.drones.size(); ++i) {
    const DroneSpec& d = s.drones[i];
    const std::string p = idx("drones", i);
    if (d.id < 1 || !ids.insert(d.id).second) return p + ".id: expected a unique integer >= 1";
    for (double v : {d.start_m[0], d.start_m[1], d.velocity_mps[0], d.velocity_mps[1]}) {
      if (!fin(v)) return p + ".start_m: expected finite numbers";
    }
    std::string e = lifetime(p, d.birth_frame, d.death_frame, s.num_frames);
    if (!e.empty()) return e;
    if (!pos(d.mean_rcs_m2)) return p + ".mean_rcs_m2: expected a positive number";
    if (d.swerling != 1 && d.swerling != 3) return p + ".swerling: expected 1 or 3";
    for (std::size_t k = 0; k < d.legs.size(); ++k) {
      if (d.legs[k].steps < 1) return p + "." + idx("legs", k) + ".steps: expected a positive integer";
      if (!fin(d.legs[k].velocity_mps[0]) || !fin(d.legs[k].velocity_mps[1]))
        return p + "." + idx("legs", k) + ".velocity_mps: expected finite numbers";
    }
  }
  for (std::size_t i = 0; i < s.clutter_patches.size(); ++i) {
    const ClutterPatchSpec& c = s.clutter_patches[i];
    const std::string p = idx("clutter_patches", i);
    if (!(pos(c.range_min_m) && c.range_max_m > c.range_min_m && fin(c.range_max_m)))
      return p + ".range_max_m: expected 0 < range_min_m < range_max_m";
    if (!(fin(c.bearing_min_deg) && fin(c.bearing_max_deg) && c.bearing_max_deg >= c.bearing_min_deg &&
          c.bearing_min_deg >= -90.0 && c.bearing_max_deg <= 90.0))
      return p + ".bearing_max_deg: expected -90 <= bearing_min_deg <= bearing_max_deg <= 90";
    if (c.scatterers < 1) return p + ".scatterers: expected a positive integer";
    if (!pos(c.mean_rcs_m2)) return p + ".mean_rcs_m2: expected a positive number";
    std::string e = lifetime(p, c.birth_frame, c.death_frame, s.num_frames);
    if (!e.empty()) return e;
  }
  for (std::size_t i = 0; i < s.chaff_clouds.size(); ++i) {
    const ChaffCloudSpec& c = s.chaff_clouds[i];
    const std::string p = idx("chaff_clouds", i);
    if (!fin(c.centre_m[0]) || !fin(c.centre_m[1])) return p + ".centre_m: expected finite numbers";
    if (!fin(c.drift_mps[0]) || !fin(c.drift_mps[1])) return p + ".drift_mps: expected finite numbers";
    if (!pos(c.sigma0_m)) return p + ".sigma0_m: expected a positive number";
    if (!nonneg(c.growth_mps)) return p + ".growth_mps: expected a non-negative number";
    if (c.scatterers < 1) return p + ".scatterers: expected a positive integer";
    if (!pos(c.mean_rcs_m2)) return p + ".mean_rcs_m2: expected a positive number";
    std::string e = lifetime(p, c.birth_frame, c.death_frame, s.num_frames);
    if (!e.empty()) return e;
  }
  for (std::size_t i = 0; i < s.jammers.size(); ++i) {
    const JammerSpec& j = s.jammers[i];
    const std::string p = idx("jammers", i);
    if (!(fin(j.bearing_min_deg) && fin(j.bearing_max_deg) && j.bearing_max_deg >= j.bearing_min_deg &&
          j.bearing_min_deg >= -90.0 && j.bearing_max_deg <= 90.0))
      return p + ".bearing_max_deg: expected -90 <= bearing_min_deg <= bearing_max_deg <= 90";
    if (j.sources < 1 || j.sources > 64) return p + ".sources: expected 1..64";
    if (!(fin(j.jnr_db) && j.jnr_db >= -100.0 && j.jnr_db <= 100.0)) return p + ".jnr_db: expected -100..100";
    std::string e = lifetime(p, j.birth_frame, j.death_frame, s.num_frames);
    if (!e.empty()) return e;
  }
  for (std::size_t i = 0; i < s.phases.size(); ++i) {
    const EvalPhase& e = s.phases[i];
    const std::string p = idx("phases", i);
    if (e.name.empty()) return p + ".name: expected a non-empty string";
    if (e.first_frame < 1 || e.last_frame < e.first_frame || e.last_frame > s.num_frames)
      return p + ".last_frame: expected 1 <= first_frame <= last_frame <= num_frames";
  }
  return "";
}

bool operator==(const AdcScenario& a, const AdcScenario& b) {
  const auto leg_eq = [](const MotionLeg& x, const MotionLeg& y) {
    return x.steps == y.steps && x.velocity_mps == y.velocity_mps;
  };
  if (a.name != b.name || a.description != b.description || a.num_frames != b.num_frames ||
      a.frame_period_s != b.frame_period_s || a.ospa_cutoff_m != b.ospa_cutoff_m || a.ospa_order != b.ospa_order)
    return false;
  const RadarSpec &r = a.radar, &q = b.radar;
  if (r.carrier_hz != q.carrier_hz || r.bandwidth_hz != q.bandwidth_hz || r.chirp_duration_s != q.chirp_duration_s ||
      r.sample_rate_hz != q.sample_rate_hz || r.element_spacing_wavelengths != q.element_spacing_wavelengths ||
      r.tx_amplitude != q.tx_amplitude || r.antenna_gain != q.antenna_gain ||
      r.noise_temperature_k != q.noise_temperature_k || r.noise_model != q.noise_model)
    return false;
  const FrontEndSpec &f = a.frontend, &g = b.frontend;
  if (f.min_range_m != g.min_range_m || f.max_range_m != g.max_range_m ||
      f.max_abs_bearing_deg != g.max_abs_bearing_deg || f.cfar_pfa != g.cfar_pfa || f.cfar_type != g.cfar_type ||
      f.range_window != g.range_window || f.angle_window != g.angle_window ||
      f.cfar_guard_cells != g.cfar_guard_cells || f.cfar_training_cells != g.cfar_training_cells)
    return false;
  if (a.tracker_model.sigma_range_m != b.tracker_model.sigma_range_m ||
      a.tracker_model.sigma_bearing_deg != b.tracker_model.sigma_bearing_deg)
    return false;
  if (a.adc.sample_format != b.adc.sample_format || a.adc.bits != b.adc.bits ||
      a.adc.full_scale_v != b.adc.full_scale_v || a.adc.saturation_fraction != b.adc.saturation_fraction ||
      a.adc.saturation_policy != b.adc.saturation_policy)
    return false;
  if (a.drones.size() != b.drones.size() || a.clutter_patches.size() != b.clutter_patches.size() ||
      a.chaff_clouds.size() != b.chaff_clouds.size() || a.jammers.size() != b.jammers.size() ||
      a.phases.size() != b.phases.size())
    return false;
  for (std::size_t i = 0; i < a.drones.size(); ++i) {
    const DroneSpec &x = a.drones[i], &y = b.drones[i];
    if (x.id != y.id || x.start_m != y.start_m || x.velocity_mps != y.velocity_mps || x.birth_frame != y.birth_frame ||
        x.death_frame != y.death_frame || x.mean_rcs_m2 != y.mean_rcs_m2 || x.swerling != y.swerling ||
        x.legs.size() != y.legs.size())
      return false;
    for (std::size_t k = 0; k < x.legs.size(); ++k) {
      if (!leg_eq(x.legs[k], y.legs[k])) return false;
    }
  }
  for (std::size_t i = 0; i < a.clutter_patches.size(); ++i) {
    const ClutterPatchSpec &x = a.clutter_patches[i], &y = b.clutter_patches[i];
    if (x.id != y.id || x.range_min_m != y.range_min_m || x.range_max_m != y.range_max_m ||
        x.bearing_min_deg != y.bearing_min_deg || x.bearing_max_deg != y.bearing_max_deg ||
        x.scatterers != y.scatterers || x.mean_rcs_m2 != y.mean_rcs_m2 || x.birth_frame != y.birth_frame ||
        x.death_frame != y.death_frame)
      return false;
  }
  for (std::size_t i = 0; i < a.chaff_clouds.size(); ++i) {
    const ChaffCloudSpec &x = a.chaff_clouds[i], &y = b.chaff_clouds[i];
    if (x.id != y.id || x.centre_m != y.centre_m || x.drift_mps != y.drift_mps || x.sigma0_m != y.sigma0_m ||
        x.growth_mps != y.growth_mps || x.scatterers != y.scatterers || x.mean_rcs_m2 != y.mean_rcs_m2 ||
        x.birth_frame != y.birth_frame || x.death_frame != y.death_frame)
      return false;
  }
  for (std::size_t i = 0; i < a.jammers.size(); ++i) {
    const JammerSpec &x = a.jammers[i], &y = b.jammers[i];
    if (x.bearing_min_deg != y.bearing_min_deg || x.bearing_max_deg != y.bearing_max_deg || x.sources != y.sources ||
        x.jnr_db != y.jnr_db || x.birth_frame != y.birth_frame || x.death_frame != y.death_frame)
      return false;
  }
  for (std::size_t i = 0; i < a.phases.size(); ++i) {
    const EvalPhase &x = a.phases[i], &y = b.phases[i];
    if (x.name != y.name || x.first_frame != y.first_frame || x.last_frame != y.last_frame) return false;
  }
  return true;
}

namespace {

// 7 m/s at 45 deg and 5 m/s at 150 deg (seed 004 Sec. V-A), to 16 digits so the JSON
// files hold the same doubles.
constexpr double kV45 = 4.949747468305833;
constexpr double kV30x = 4.330127018922193;

AdcScenario seed004_drones() {
  AdcScenario s;
  s.name = "seed004-drones";
  s.description =
      "Seed 004 (arXiv 2503.15246) Sec. V: 3x3 TDM-MIMO radar at 10 GHz, 20 MHz chirp, 10 Hz frames; three "
      "Swerling-3 drones (0.05 m^2) crossing at frame 22, track 3 lives 50..95; clutter-free, model-A noise";
  s.num_frames = 100;
  s.frame_period_s = 0.1;
  DroneSpec d1;
  d1.id = 1;
  d1.start_m = {10.0, 10.0};
  d1.velocity_mps = {kV45, kV45};
  d1.birth_frame = 1;
  d1.death_frame = 100;
  DroneSpec d2;
  d2.id = 2;
  d2.start_m = {10.0, 31.0};
  d2.velocity_mps = {kV45, -kV45};
  d2.birth_frame = 1;
  d2.death_frame = 100;
  d2.legs = {MotionLeg{20, {kV45, -kV45}}, MotionLeg{80, {0.0, 7.0}}};
  DroneSpec d3;
  d3.id = 3;
  d3.start_m = {15.0, 20.0};
  d3.velocity_mps = {kV45, -kV45};
  d3.birth_frame = 50;
  d3.death_frame = 95;
  d3.legs = {MotionLeg{16, {kV45, -kV45}}, MotionLeg{14, {-kV30x, 2.5}}, MotionLeg{16, {-kV30x, 2.5}}};
  s.drones = {d1, d2, d3};
  // frames_1_70: the span where seed 004 Fig. 4 shows VMP below ~1 m, before
  // drone 1 fades out at the array-gain limit.
  s.phases = {EvalPhase{"frames_1_70", 1, 70},   EvalPhase{"start", 1, 5},          EvalPhase{"crossing", 20, 24},
              EvalPhase{"track3_birth", 50, 54}, EvalPhase{"track3_maneuver", 66, 80},
              EvalPhase{"low_snr", 80, 100},     EvalPhase{"track3_death", 96, 100}};
  return s;
}

AdcScenario mimo_interference() {
  AdcScenario s = seed004_drones();
  s.name = "mimo-interference";
  s.description =
      "seed004-drones plus the interference the product exists for: two distributed clutter patches (one on "
      "track 1's outbound path at 60-75 m), a blooming chaff cloud from frame 30 and a 3-source noise jammer "
      "sector at -60..-50 deg (JNR 10 dB per sample) for frames 40..70";
  ClutterPatchSpec p1;
  p1.id = 1;
  p1.range_min_m = 60.0;
  p1.range_max_m = 75.0;
  p1.bearing_min_deg = 30.0;
  p1.bearing_max_deg = 50.0;
  p1.scatterers = 60;
  p1.mean_rcs_m2 = 0.02;
  p1.birth_frame = 1;
  p1.death_frame = 100;
  ClutterPatchSpec p2;
  p2.id = 2;
  p2.range_min_m = 20.0;
  p2.range_max_m = 35.0;
  p2.bearing_min_deg = -40.0;
  p2.bearing_max_deg = -20.0;
  p2.scatterers = 60;
  p2.mean_rcs_m2 = 0.005;
  p2.birth_frame = 1;
  p2.death_frame = 100;
  s.clutter_patches = {p1, p2};
  ChaffCloudSpec c;
  c.id = 3;
  c.centre_m = {-20.0, 40.0};
  c.drift_mps = {1.0, 0.5};
  c.sigma0_m = 2.0;
  c.growth_mps = 0.5;
  c.scatterers = 40;
  c.mean_rcs_m2 = 0.005;
  c.birth_frame = 30;
  c.death_frame = 100;
  s.chaff_clouds = {c};
  JammerSpec j;
  j.bearing_min_deg = -60.0;
  j.bearing_max_deg = -50.0;
  j.sources = 3;
  j.jnr_db = 10.0;
  j.birth_frame = 40;
  j.death_frame = 70;
  s.jammers = {j};
  s.phases.push_back(EvalPhase{"jammer_on", 40, 70});
  return s;
}

AdcScenario strong_target() {
  AdcScenario s = seed004_drones();
  s.name = "strong-target";
  s.description =
      "One strong drone alone in noise (issue 16: false tracks from range/angle sidelobes): seed004-drones' "
      "radar and front end, a Swerling-3 0.05 m^2 drone at 14.4 m (~28 dB, as drone 1 at the start of "
      "seed 004) moving 0.5 m/s across the line of sight (14.4 -> 15.2 m, SNR within 1 dB), 100 frames";
  DroneSpec d;
  d.id = 1;
  d.start_m = {12.0, 8.0};
  d.velocity_mps = {-0.2773500981126146, 0.4160251471689219};  // 0.5 m/s, perpendicular to start_m
  d.birth_frame = 1;
  d.death_frame = 100;
  s.drones = {d};
  s.phases = {EvalPhase{"all", 1, 100}};
  return s;
}

}  // namespace

std::vector<std::string> builtin_adc_scenario_names() {
  return {"seed004-drones", "mimo-interference", "strong-target"};
}

bool builtin_adc_scenario(const std::string& name, AdcScenario& out) {
  if (name == "seed004-drones") {
    out = seed004_drones();
    return true;
  }
  if (name == "mimo-interference") {
    out = mimo_interference();
    return true;
  }
  if (name == "strong-target") {
    out = strong_target();
    return true;
  }
  return false;
}

}  // namespace mptrack::adc
