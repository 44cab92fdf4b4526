// --mfbp-param NAME=VALUE overrides; see mfbp_param_override.h. NAME is the
// field as written in MfbpParams, dotted for the shared blocks of
// tracker_params.h ("noise.range_std_m", "amplitude.use_amplitude").
#include "trackers/mfbp_param_override.h"

#include <iterator>

#include "trackers/param_override.h"

namespace mptrack::sim {

namespace {

using P = MfbpParams<double>;

using Real = RealField<P>;
using Count = CountField<P>;
using Flag = FlagField<P>;

// One line per field a user tunes most; units and defaults in mfbp_params.h.
const Real kReals[] = {
    {"accel_var_m2ps4", [](P& p) -> double& { return p.accel_var_m2ps4; }},
    {"manoeuvre_noise_var_max", [](P& p) -> double& { return p.manoeuvre_noise_var_max; }},
    {"manoeuvre_fading", [](P& p) -> double& { return p.manoeuvre_fading; }},
    {"unresolved_chi2", [](P& p) -> double& { return p.unresolved_chi2; }},
    {"gate_chi2", [](P& p) -> double& { return p.gate_chi2; }},
    {"report_existence_min", [](P& p) -> double& { return p.report_existence_min; }},
    {"duplicate_chi2", [](P& p) -> double& { return p.duplicate_chi2; }},
    {"p_survive", [](P& p) -> double& { return p.p_survive; }},
    {"p_birth", [](P& p) -> double& { return p.p_birth; }},
    {"confirm_threshold", [](P& p) -> double& { return p.confirm_threshold; }},
    {"delete_threshold", [](P& p) -> double& { return p.delete_threshold; }},
    {"pd_no_amplitude", [](P& p) -> double& { return p.pd_no_amplitude; }},
    {"bp_damping", [](P& p) -> double& { return p.bp_damping; }},
    {"birth_max_component_share", [](P& p) -> double& { return p.birth_max_component_share; }},
    {"birth_amplitude_tail", [](P& p) -> double& { return p.birth_amplitude_tail; }},
    {"birth_single_point_tail", [](P& p) -> double& { return p.birth_single_point_tail; }},
    {"birth_in_clutter_max_cnr", [](P& p) -> double& { return p.birth_in_clutter_max_cnr; }},
    {"uniform_rate_floor_per_scan", [](P& p) -> double& { return p.uniform_rate_floor_per_scan; }},
    {"unexplained_threshold", [](P& p) -> double& { return p.unexplained_threshold; }},
    {"noise.range_std_m", [](P& p) -> double& { return p.noise.range_std_m; }},
    {"noise.azimuth_std_rad", [](P& p) -> double& { return p.noise.azimuth_std_rad; }},
    {"noise.doppler_std_mps", [](P& p) -> double& { return p.noise.doppler_std_mps; }},
    {"amplitude.threshold", [](P& p) -> double& { return p.amplitude.threshold; }},
    {"confirm_threshold_in_clutter", [](P& p) -> double& { return p.confirm_threshold_in_clutter; }},
    {"filter_confirm_score_in_clutter", [](P& p) -> double& { return p.filter_confirm_score_in_clutter; }},
};
const Count kCounts[] = {
    {"delete_run", [](P& p) -> std::size_t& { return p.delete_run; }},
    {"window_length", [](P& p) -> std::size_t& { return p.window_length; }},
    {"slide", [](P& p) -> std::size_t& { return p.slide; }},
    {"confirm_lookahead_in_clutter", [](P& p) -> std::size_t& { return p.confirm_lookahead_in_clutter; }},
    {"mp_max_iterations", [](P& p) -> std::size_t& { return p.mp_max_iterations; }},
    {"bp_max_iterations", [](P& p) -> std::size_t& { return p.bp_max_iterations; }},
    {"birth_max_per_window", [](P& p) -> std::size_t& { return p.birth_max_per_window; }},
    {"tentative_timeout_scans", [](P& p) -> std::size_t& { return p.tentative_timeout_scans; }},
    {"tentative_timeout_in_clutter_scans", [](P& p) -> std::size_t& { return p.tentative_timeout_in_clutter_scans; }},
    {"birth_max_in_clutter", [](P& p) -> std::size_t& { return p.birth_max_in_clutter; }},
    {"delete_run_in_clutter", [](P& p) -> std::size_t& { return p.delete_run_in_clutter; }},
};
const Flag kFlags[] = {
    {"filter_score_in_any_component", [](P& p) -> bool& { return p.filter_score_in_any_component; }},
    {"unresolved_pooling", [](P& p) -> bool& { return p.unresolved_pooling; }},
    {"unresolved_taper", [](P& p) -> bool& { return p.unresolved_taper; }},
    {"association_cavity", [](P& p) -> bool& { return p.association_cavity; }},
    {"late_birth", [](P& p) -> bool& { return p.late_birth; }},
    {"retire_in_new_clutter", [](P& p) -> bool& { return p.retire_in_new_clutter; }},
    {"amplitude.use_amplitude", [](P& p) -> bool& { return p.amplitude.use_amplitude; }},
    {"use_doppler", [](P& p) -> bool& { return p.use_doppler; }},
    {"tentative_predictive_in_clutter", [](P& p) -> bool& { return p.tentative_predictive_in_clutter; }},
};

}  // namespace

std::string apply_mfbp_param(MfbpParams<double>& p, const std::string& kv) {
  // NempParams fields ("nemp.rounds=3") are the nemp adapter's
  // (trackers/nemp_adapter.cpp); every MF-BP tracker of a compare gets the
  // same list, so the others pass them by.
  if (kv.rfind("nemp.", 0) == 0) return "";
  static const ParamTable<P> kTable{"--mfbp-param", kReals, std::size(kReals), kCounts, std::size(kCounts),
                                    kFlags, std::size(kFlags)};
  return apply_param(p, kv, kTable);
}

std::string apply_mfbp_params(MfbpParams<double>& p, const std::vector<std::string>& overrides) {
  for (const std::string& kv : overrides) {
    std::string error = apply_mfbp_param(p, kv);
    if (!error.empty()) return error;
  }
  return "";
}

}  // namespace mptrack::sim
