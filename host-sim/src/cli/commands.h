// The subcommands of mptrack-sim, one file each (cmd_*.cpp); main.cpp only
// registers them and dispatches. The top-level options (RunOptions) belong
// to the default command (cmd_run.cpp); subcommands read the ones they share
// with it (--tracker, --no-plot, --no-progress) through CLI11's fallthrough.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "mptrack/scenario/scenario_spec.h"
#include "run/run_loop.h"
#include "run/truncate.h"
#include "stream/adc_runner.h"

namespace mptrack::sim {

struct Summary;

/// Options of the default command (Monte Carlo runs of one scenario x one tracker).
struct RunOptions {
  TrackerRunOptions run;           ///< --tracker, --runs, --seed, --out, --csv-runs, --mfbp-param (plot, progress: below)
  std::string scenario_name = "seed000-s2";
  std::string scenario_file;
  int swerling = 0;
  std::string snr1_text, snr2_text;
  double clutter_scale = 1.0;
  double pd = -1.0;  ///< --pd: every OTHR path's detection probability (< 0: the scenario's)
  std::uint32_t scans = 0;
  std::uint32_t frames = 0;
  double rate_hz = 0.0;
  std::string adc_format;          ///< --adc-format (raw-ADC scenarios; "" = the scenario's)
  std::string saturation_policy;   ///< --saturation-policy (raw-ADC scenarios; "" = the scenario's)
  bool no_plot = false;
  bool no_progress = false;
  bool force = false;                 ///< --force: write even above the output-size limit (input_checks.h)
  double scr_db = kNoScr;             ///< --scr: every target's SCR [dB] (seed 003 sea scenes)
  std::string classifier = "float";   ///< --classifier float|int8: the sea scenes' CNN g_M
  static constexpr double kNoScr = -1e300;  ///< --scr not given: the scenario's
};

/// A registered subcommand and what it does once parsed.
struct Subcommand {
  CLI::App* app = nullptr;
  std::function<int(const RunOptions&)> run;
  /// The top-level options (RunOptions) it reads, e.g. "--no-progress";
  /// any other one given with it is refused (check_top_level_options).
  std::vector<std::string> reads = {};
};

/// Throws std::runtime_error if a top-level option was given with
/// subcommand c that c does not read. Through CLI11's fallthrough,
/// `compare --scenario-file F` parses as the default command's
/// --scenario-file, which compare never looks at: it would run its own
/// default scenario on the user's behalf without a word.
void check_top_level_options(const CLI::App& app, const Subcommand& c);

// cmd_run.cpp: the default command.
void add_run_options(CLI::App& app, RunOptions& options);
int run_default_command(const RunOptions& options);

/// Raw-ADC Monte Carlo of the built-in scenario `name` or the file `file`
/// ("" = use the name) with `config` (its scenario is replaced), report on
/// stdout; out_dir "" = out/<scenario>-<tracker>. Returns the exit code.
int run_adc_command(const std::string& name, const std::string& file, AdcRunConfig config);

/// The report of a measurement-level run on stdout.
void print_run_summary(const Summary& s, const std::string& out_dir);

// One per subcommand file, in --help order.
Subcommand add_info_command(CLI::App& app);
Subcommand add_demo_command(CLI::App& app);
Subcommand add_table5_command(CLI::App& app);
Subcommand add_compare_command(CLI::App& app);
Subcommand add_scenario_export_command(CLI::App& app);
Subcommand add_dataset_command(CLI::App& app);  // cmd_dataset.cpp (seed 003 sea clutter)
Subcommand add_replay_command(CLI::App& app);  // cmd_replay.cpp

// Shared by several commands (cli_common.cpp).
/// Help text of --mfbp-param (the same on every command that takes it).
extern const char* const kMfbpParamHelp;
extern const char* const kClassifierHelp;
/// Help text of --rfs-param.
extern const char* const kRfsParamHelp;
/// "10/3", "20" or "3.5" -> double; throws std::runtime_error naming `flag`.
double parse_ratio(const std::string& text, const char* flag);
/// True for a built-in raw-ADC name (file "") or a file with the raw-ADC schema.
bool is_adc_scenario(const std::string& name, const std::string& file);
/// The raw-ADC scenario of the file (if given, throws on errors) or the
/// built-in `name`; false if `name` is not a built-in raw-ADC scenario.
bool load_adc_scenario(const std::string& name, const std::string& file, adc::AdcScenario& out);

// cmd_sea.cpp: the seed 003 sea scenes (sea_runner.h).
/// The default command on a sea scenario (--scr, --tracker mfbp|mfbp-nn|nemp).
int run_sea_command(const RunOptions& options);
/// `compare` on a sea scenario: every tracker at every SCR of `scr_list`
/// ("-10,0,10"; "" = -20..20 step 4). Returns the exit code.
int run_sea_compare_command(const std::string& scenario, const std::string& trackers, const std::string& scr_list,
                            std::uint32_t runs, std::uint64_t seed, const std::vector<std::string>& mfbp_params,
                            const std::string& out_dir, const RunOptions& options);

}  // namespace mptrack::sim
