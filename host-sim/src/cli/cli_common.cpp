// Helpers shared by several subcommands; see commands.h.
#include <algorithm>
#include <exception>
#include <stdexcept>

#include "cli/commands.h"
#include "mptrack/adc/adc_json.h"

namespace mptrack::sim {

const char* const kMfbpParamHelp =
    "override an MfbpParams field for the MF-BP trackers, NAME=VALUE (repeatable), e.g. "
    "accel_var_m2ps4=0.3, amplitude.use_amplitude=0 or unresolved_chi2=0; names in host-sim/README.md";
const char* const kClassifierHelp =
    "seed003-sea scenarios: the classifier's CNN for mfbp-nn and nemp, float or int8 (the quantised network of "
    "./run quantise-classifier; docs/algorithms/nemp.md)";
const char* const kRfsParamHelp =
    "override an RfsFilterParams field for gmphd, gmcphd and cbmember (and their variants), NAME=VALUE "
    "(repeatable), e.g. extract_threshold=0.9 (PHD: report only components heavier than 0.9) or birth_rate=0.05; names in host-sim/README.md";

double parse_ratio(const std::string& text, const char* flag) {
  const auto slash = text.find('/');
  try {
    std::size_t used = 0;
    if (slash == std::string::npos) {
      const double v = std::stod(text, &used);
      if (used == text.size()) return v;
    } else {
      const double a = std::stod(text.substr(0, slash), &used);
      std::size_t used_b = 0;
      const std::string b_text = text.substr(slash + 1);
      const double b = std::stod(b_text, &used_b);
      if (used == slash && used_b == b_text.size() && b != 0.0) return a / b;
    }
  } catch (const std::exception&) {
  }
  throw std::runtime_error(std::string(flag) + ": expected a number or a ratio like 10/3, got '" + text + "'");
}

bool is_adc_scenario(const std::string& name, const std::string& file) {
  if (!file.empty()) return adc::is_adc_scenario_file(file);
  adc::AdcScenario s;
  return adc::builtin_adc_scenario(name, s);
}

bool load_adc_scenario(const std::string& name, const std::string& file, adc::AdcScenario& out) {
  if (!file.empty()) {
    out = adc::load_adc_scenario_file(file);
    return true;
  }
  return adc::builtin_adc_scenario(name, out);
}

void check_top_level_options(const CLI::App& app, const Subcommand& c) {
  for (const CLI::Option* opt : app.get_options()) {
    if (opt->count() == 0 || opt->get_lnames().empty()) continue;
    const std::string flag = "--" + opt->get_lnames().front();
    if (std::find(c.reads.begin(), c.reads.end(), flag) != c.reads.end()) continue;
    std::string text = flag + " is not an option of `" + c.app->get_name() + "`";
    if (flag == "--scenario-file" && c.app->get_option_no_throw("--scenario") != nullptr) {
      text += " (its --scenario takes a built-in name or a scenario JSON file)";
    }
    throw std::runtime_error(text + "; see `mptrack-sim " + c.app->get_name() + " --help`");
  }
}

}  // namespace mptrack::sim
