// libFuzzer harness: params validation (docs/reliability.md). Starts from
// the defaults of GnnParams, MfbpParams, RfsFilterParams (PHD/CPHD/CBMeMBer)
// and FrontEndParams and lets the input replace any field by a special
// value (NaN, Inf, 0, -1, huge, denormal), a scaled default or raw bits.
// Whatever init() accepts must then run a few scans without a crash, a
// sanitizer report or a non-finite output: validation is the only guard.
#include <cstddef>
#include <cstdint>

#include "fuzz_common.h"
#include "mptrack/cbmember/cbmember_filter.h"
#include "mptrack/frontend/front_end.h"
#include "mptrack/gnn/gnn_tracker.h"
#include "mptrack/mfbp/mfbp_tracker.h"
#include "mptrack/phd/phd_filter.h"

namespace {
using mptrack::Status;
using mptrack::fuzz::FuzzReader;

struct TinyCaps {
  static constexpr std::size_t kMaxTargets = 4;
  static constexpr std::size_t kMaxMeasurements = 8;
  static constexpr std::size_t kMaxClutterComponents = 2;
  static constexpr std::size_t kMaxWindow = 7;
};
struct TinyRadarCaps {
  static constexpr std::size_t kNumTx = 1;
  static constexpr std::size_t kNumRx = 2;
  static constexpr std::size_t kNumSamples = 16;
  static constexpr std::size_t kRangeFftSize = 16;
  static constexpr std::size_t kNumRangeBins = 8;
  static constexpr std::size_t kNumChirps = 4;
  static constexpr std::size_t kNumAngleBins = 4;
  static constexpr std::size_t kMaxDetections = 8;
};

// Field mutators: most fields keep their default, so the fuzzer explores
// one or two bad fields at a time (where validation bugs hide).
void mutate(FuzzReader& in, float& f) {
  const std::uint8_t sel = in.u8();
  if (sel < 160) return;
  if (sel < 200) f = mptrack::fuzz::special_float(sel);
  else if (sel < 240) f *= static_cast<float>(sel - 219) * 0.25f;  // -4.75 .. 5
  else f = in.raw_float();
}
void mutate(FuzzReader& in, double& d) {
  const std::uint8_t sel = in.u8();
  if (sel < 160) return;
  if (sel < 200) d = static_cast<double>(mptrack::fuzz::special_float(sel));
  else if (sel < 240) d *= static_cast<double>(sel - 219) * 0.25;
  else d = in.raw_double();
}
template <class U>
void mutate_int(FuzzReader& in, U& v) {
  const std::uint8_t sel = in.u8();
  if (sel < 160) return;
  if (sel < 220) v = static_cast<U>(sel - 190);  // small, possibly negative
  else v = static_cast<U>(in.u32());
}
void mutate(FuzzReader& in, std::size_t& v) { mutate_int(in, v); }
void mutate(FuzzReader& in, std::uint32_t& v) { mutate_int(in, v); }
void mutate(FuzzReader& in, int& v) { mutate_int(in, v); }
void mutate(FuzzReader& in, bool& b) {
  if (in.u8() >= 160) b = !b;
}
template <class E>
void mutate_enum(FuzzReader& in, E& e) {  // any underlying value, invalid ones too
  const std::uint8_t sel = in.u8();
  if (sel >= 160) e = static_cast<E>(sel % 5u);
}

mptrack::GnnTracker<float, TinyCaps> g_gnn;
mptrack::MfbpTracker<float, TinyCaps> g_mfbp;
mptrack::GmPhdFilter<float, TinyCaps> g_phd;
mptrack::GmCphdFilter<float, TinyCaps> g_cphd;
mptrack::CbMemberFilter<float, TinyCaps> g_cbm;
mptrack::frontend::FrontEnd<TinyRadarCaps> g_fe;
mptrack::frontend::RadarCubeInt16<TinyRadarCaps> g_cube;
mptrack::Scan<float, 8> g_scan;
mptrack::Scan<float, 8> g_fe_scan;

// Three scans of two points placed inside whatever region the params give.
template <class Tracker>
void run_scans(Tracker& t, float r0, float r1, float a0, float a1) {
  for (std::uint64_t k = 0; k < 3; ++k) {
    g_scan.time_us = 1000000u + k * 1000000u;
    g_scan.has_doppler = false;
    g_scan.measurements.clear();
    for (int j = 0; j < 2; ++j) {
      mptrack::Measurement<float> m;
      const float fr = j == 0 ? 0.3f : 0.7f;
      m.range_m = r0 + fr * (r1 - r0);
      m.azimuth_rad = a0 + fr * (a1 - a0);
      m.amplitude = 4.0f;
      static_cast<void>(g_scan.measurements.push_back(m));
    }
    const Status s = t.step(g_scan);
    FUZZ_CHECK(s == Status::kOk || s == Status::kPartial || s == Status::kCapacityExceeded);
    for (const auto& e : t.outputs()) mptrack::fuzz::check_estimate_sane(e);
  }
  const Status f = t.flush();
  FUZZ_CHECK(f == Status::kOk || f == Status::kCapacityExceeded);
  for (const auto& e : t.outputs()) mptrack::fuzz::check_estimate_sane(e);
}

void fuzz_gnn(FuzzReader& in) {
  mptrack::GnnParams<float> p;
  mutate(in, p.accel_var_m2ps4); mutate(in, p.noise.range_std_m);
  mutate(in, p.noise.azimuth_std_rad);
  mutate(in, p.init_velocity_std_mps); mutate(in, p.gate_chi2); mutate(in, p.confirm_hits);
  mutate(in, p.confirm_window); mutate(in, p.max_misses); mutate(in, p.report_tentative);
  mutate(in, p.region.range_min_m); mutate(in, p.region.range_max_m);
  mutate(in, p.region.azimuth_min_rad); mutate(in, p.region.azimuth_max_rad);
  mutate(in, p.min_variance); mutate(in, p.max_gap_s);
  if (g_gnn.init(p) != Status::kOk) return;
  run_scans(g_gnn, p.region.range_min_m, p.region.range_max_m, p.region.azimuth_min_rad,
            p.region.azimuth_max_rad);
}

void fuzz_mfbp(FuzzReader& in) {
  mptrack::MfbpParams<float> p;
  p.bp_max_iterations = 50;
  mutate(in, p.region.range_min_m); mutate(in, p.region.range_max_m);
  mutate(in, p.region.azimuth_min_rad); mutate(in, p.region.azimuth_max_rad);
  mutate(in, p.scan_period_s); mutate(in, p.accel_var_m2ps4); mutate(in, p.noise.range_std_m);
  mutate(in, p.noise.azimuth_std_rad); mutate(in, p.gate_chi2); mutate(in, p.association_cavity);
  mutate(in, p.clutter_gate_chi2); mutate(in, p.use_doppler); mutate(in, p.noise.doppler_std_mps);
  mutate(in, p.doppler_span_mps); mutate(in, p.amplitude.threshold); mutate(in, p.amplitude.swerling);
  mutate(in, p.amplitude.use_amplitude); mutate(in, p.pd_no_amplitude); mutate_enum(in, p.pd_model);
  mutate_enum(in, p.amp_loglik); mutate_enum(in, p.snr_update); mutate(in, p.forgetting_target);
  mutate(in, p.forgetting_clutter); mutate(in, p.ig_birth_shape); mutate(in, p.ig_birth_scale_factor);
  mutate(in, p.p_survive); mutate(in, p.p_birth); mutate(in, p.pd_invisible);
  mutate(in, p.visibility_at_birth); mutate(in, p.window_length); mutate(in, p.slide);
  mutate(in, p.mp_max_iterations); mutate(in, p.mp_tolerance); mutate(in, p.bp_tolerance);
  mutate(in, p.bp_damping); mutate(in, p.w_min); mutate_enum(in, p.clutter_mode);
  mutate(in, p.clutter_rate_in_da); mutate(in, p.uniform_rate_per_scan);
  mutate(in, p.nw_forgetting_factor); mutate_enum(in, p.nw_forgetting); mutate(in, p.dirichlet_kappa);
  mutate(in, p.component_absent_evidence); mutate(in, p.uniform_cnr_prior);
  mutate(in, p.uniform_cnr_prior_shape); mutate(in, p.known_clutter.uniform_rate_per_scan);
  mutate(in, p.known_clutter.uniform_cnr); mutate(in, p.known_clutter.num_components);
  for (auto& c : p.known_clutter.components) {
    mutate(in, c.rate_per_scan); mutate(in, c.cnr);
    mutate(in, c.covariance(0, 0)); mutate(in, c.covariance(0, 1));
  }
  mutate(in, p.v_max_x_mps); mutate(in, p.v_max_y_mps); mutate(in, p.birth_max_lag);
  mutate(in, p.birth_max_per_window); mutate(in, p.late_birth); mutate(in, p.unexplained_threshold);
  mutate(in, p.birth_max_component_share); mutate(in, p.confirm_threshold);
  mutate(in, p.delete_threshold); mutate(in, p.delete_run); mutate(in, p.tentative_timeout_scans);
  mutate(in, p.report_existence_min); mutate(in, p.clutter_birth); mutate(in, p.clutter_cell_range_m);
  mutate(in, p.clutter_cell_az_rad); mutate(in, p.clutter_seed_factor);
  mutate(in, p.clutter_death_count); mutate(in, p.clutter_death_windows);
  mutate(in, p.retire_in_new_clutter); mutate(in, p.birth_in_clutter_max_cnr);
  if (p.bp_max_iterations > 200) return;  // time bound only (valid, but slow)
  if (g_mfbp.init(p) != Status::kOk) return;
  run_scans(g_mfbp, p.region.range_min_m, p.region.range_max_m, p.region.azimuth_min_rad,
            p.region.azimuth_max_rad);
}

void fuzz_filter_params(FuzzReader& in, std::uint8_t which) {
  mptrack::RfsFilterParams<float> p;
  mutate_enum(in, p.space); mutate(in, p.noise.range_std_m); mutate(in, p.noise.azimuth_std_rad);
  mutate(in, p.region.range_min_m); mutate(in, p.region.range_max_m);
  mutate(in, p.region.azimuth_min_rad); mutate(in, p.region.azimuth_max_rad);
  mutate(in, p.cartesian_std_m); mutate(in, p.cartesian_region.x_min_m);
  mutate(in, p.cartesian_region.x_max_m); mutate(in, p.cartesian_region.y_min_m);
  mutate(in, p.cartesian_region.y_max_m); mutate(in, p.scan_period_s); mutate(in, p.accel_var_m2ps4);
  mutate(in, p.survival_prob); mutate(in, p.birth_rate); mutate(in, p.birth_velocity_std_mps);
  mutate(in, p.amplitude.use_amplitude); mutate(in, p.amplitude.threshold);
  mutate(in, p.amplitude.swerling);
  mutate(in, p.target_power_prior); mutate(in, p.target_alpha_prior); mutate(in, p.power_forgetting);
  mutate(in, p.min_alpha); mutate(in, p.max_alpha); mutate(in, p.detection_prob);
  mutate_enum(in, p.clutter_mode); mutate(in, p.clutter_rate); mutate(in, p.weibull_shape);
  mutate(in, p.clutter_scale); mutate(in, p.clutter_forgetting); mutate(in, p.clutter_alpha_prior);
  mutate(in, p.hotspot_half_width0); mutate(in, p.hotspot_half_width1);
  mutate(in, p.hotspot_min_points); mutate(in, p.hotspot_min_rate); mutate(in, p.prune_threshold);
  mutate(in, p.merge_threshold); mutate(in, p.merge_threshold_power); mutate(in, p.gate_probability);
  mutate(in, p.extract_threshold); mutate(in, p.existence_prune); mutate(in, p.existence_extract);
  mutate(in, p.max_gap_s); mutate(in, p.amplitude.max_amplitude);
  const bool polar = p.space == mptrack::MeasurementSpace::kPolar;
  const float r0 = polar ? p.region.range_min_m : p.cartesian_region.x_min_m;
  const float r1 = polar ? p.region.range_max_m : p.cartesian_region.x_max_m;
  const float a0 = polar ? p.region.azimuth_min_rad : p.cartesian_region.y_min_m;
  const float a1 = polar ? p.region.azimuth_max_rad : p.cartesian_region.y_max_m;
  switch (which % 3u) {
    case 0:
      if (g_phd.init(p) != Status::kOk) return;
      run_scans(g_phd, r0, r1, a0, a1);
      break;
    case 1:
      if (g_cphd.init(p) != Status::kOk) return;
      run_scans(g_cphd, r0, r1, a0, a1);
      break;
    default:
      if (g_cbm.init(p) != Status::kOk) return;
      run_scans(g_cbm, r0, r1, a0, a1);
      break;
  }
}

void fuzz_frontend_params(FuzzReader& in) {
  mptrack::frontend::FrontEndParams p;
  p.chirp_duration_s = 0.25e-6;
  p.max_range_m = 40.0;
  p.max_detections = 8;
  mutate(in, p.carrier_hz); mutate(in, p.bandwidth_hz); mutate(in, p.chirp_duration_s);
  mutate(in, p.sample_rate_hz); mutate(in, p.chirp_repetition_s);
  mutate(in, p.element_spacing_wavelengths); mutate(in, p.remove_dc);
  mutate_enum(in, p.range_window); mutate_enum(in, p.doppler_window); mutate_enum(in, p.angle_window);
  mutate(in, p.max_abs_bearing_rad); mutate(in, p.min_range_m); mutate(in, p.max_range_m);
  mutate_enum(in, p.cfar.type); mutate_enum(in, p.cfar.edge); mutate(in, p.cfar.guard_cells);
  mutate(in, p.cfar.training_cells); mutate(in, p.cfar.pfa); mutate(in, p.cfar.os_rank);
  mutate(in, p.max_detections); mutate(in, p.min_noise_power); mutate(in, p.angle_refine_iterations);
  mutate(in, p.max_abs_sample); mutate(in, p.saturation_fraction);
  if (g_fe.init(p) != Status::kOk) return;
  for (std::size_t i = 0; i < g_cube.iq.size(); ++i) {
    g_cube.iq[i] = static_cast<std::int16_t>((i * 7919u) % 2001u) - 1000;  // busy, deterministic
  }
  const Status s = g_fe.process(g_cube, g_fe_scan);
  // kPartial: a detection dropped for a non-finite amplitude (F3); the
  // busy cube (|code| <= 1000) is never saturated or all zero
  FUZZ_CHECK(s == Status::kOk || s == Status::kCapacityExceeded || s == Status::kPartial);
  for (const auto& m : g_fe_scan.measurements) {
    FUZZ_CHECK(mptrack::is_finite(m.range_m) && mptrack::is_finite(m.azimuth_rad) &&
               mptrack::is_finite(m.amplitude) && mptrack::is_finite(m.doppler_mps));
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzReader in(data, size);
  const std::uint8_t which = in.u8();
  switch (which % 6u) {
    case 0: fuzz_gnn(in); break;
    case 1: fuzz_mfbp(in); break;
    case 2: fuzz_frontend_params(in); break;
    default: fuzz_filter_params(in, static_cast<std::uint8_t>(which % 6u - 3u)); break;
  }
  return 0;
}
