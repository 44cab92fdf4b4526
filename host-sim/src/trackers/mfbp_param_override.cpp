// --mfbp-param NAME=VALUE overrides; see mfbp_param_override.h.
#include "trackers/mfbp_param_override.h"

#include <cstdlib>

namespace mptrack::sim {

std::string apply_mfbp_param(MfbpParams<double>& p, const std::string& kv) {
  const std::size_t eq = kv.find('=');
  if (eq == std::string::npos) return "--mfbp-param " + kv + ": expected NAME=VALUE";
  const std::string name = kv.substr(0, eq);
  const std::string text = kv.substr(eq + 1);
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end == nullptr || *end != '\0') return "--mfbp-param " + name + ": '" + text + "' is not a number";
  const auto count = [v]() { return v < 0.0 ? std::size_t{0} : static_cast<std::size_t>(v); };
  struct Real { const char* name; double MfbpParams<double>::*field; };
  static const Real kReals[] = {
      {"process_noise_var", &MfbpParams<double>::process_noise_var},
      {"manoeuvre_noise_var_max", &MfbpParams<double>::manoeuvre_noise_var_max},
      {"manoeuvre_fading", &MfbpParams<double>::manoeuvre_fading},
      {"unresolved_chi2", &MfbpParams<double>::unresolved_chi2},
      {"gate_chi2", &MfbpParams<double>::gate_chi2},
      {"report_existence_min", &MfbpParams<double>::report_existence_min},
      {"p_survive", &MfbpParams<double>::p_survive},
      {"p_birth", &MfbpParams<double>::p_birth},
      {"confirm_threshold", &MfbpParams<double>::confirm_threshold},
      {"delete_threshold", &MfbpParams<double>::delete_threshold},
      {"pd_no_amplitude", &MfbpParams<double>::pd_no_amplitude},
      {"bp_damping", &MfbpParams<double>::bp_damping},
      {"birth_max_component_share", &MfbpParams<double>::birth_max_component_share},
      {"unexplained_threshold", &MfbpParams<double>::unexplained_threshold},
  };
  for (const Real& r : kReals) {
    if (name == r.name) {
      p.*(r.field) = v;
      return "";
    }
  }
  struct Count { const char* name; std::size_t MfbpParams<double>::*field; };
  static const Count kCounts[] = {
      {"delete_run", &MfbpParams<double>::delete_run},
      {"window_length", &MfbpParams<double>::window_length},
      {"slide", &MfbpParams<double>::slide},
      {"mp_max_iterations", &MfbpParams<double>::mp_max_iterations},
      {"bp_max_iterations", &MfbpParams<double>::bp_max_iterations},
      {"birth_max_per_window", &MfbpParams<double>::birth_max_per_window},
      {"tentative_timeout_scans", &MfbpParams<double>::tentative_timeout_scans},
  };
  for (const Count& c : kCounts) {
    if (name == c.name) {
      p.*(c.field) = count();
      return "";
    }
  }
  struct Flag { const char* name; bool MfbpParams<double>::*field; };
  static const Flag kFlags[] = {
      {"unresolved_pooling", &MfbpParams<double>::unresolved_pooling},
      {"association_cavity", &MfbpParams<double>::association_cavity},
      {"late_birth", &MfbpParams<double>::late_birth},
      {"use_amplitude", &MfbpParams<double>::use_amplitude},
      {"use_doppler", &MfbpParams<double>::use_doppler},
  };
  for (const Flag& f : kFlags) {
    if (name == f.name) {
      p.*(f.field) = v != 0.0;
      return "";
    }
  }
  return "--mfbp-param: unknown parameter '" + name + "' (see host-sim/README.md)";
}

std::string apply_mfbp_params(MfbpParams<double>& p, const std::vector<std::string>& overrides) {
  for (const std::string& kv : overrides) {
    std::string error = apply_mfbp_param(p, kv);
    if (!error.empty()) return error;
  }
  return "";
}

}  // namespace mptrack::sim
