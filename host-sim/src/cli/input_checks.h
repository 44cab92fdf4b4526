// Range checks of harness flags and bounded-work checks of a run, each
// refusing with a message that names the flag or field, the value and the
// limit (issue 17: hangs, silent acceptance, unreadable CLI11 messages).
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "mptrack/scenario/generator.h"
#include "mptrack/scenario/scenario_spec.h"

namespace mptrack::sim {

/// An integer flag in [lo, hi]: "--runs = 0: must be an integer in [1, 1000000]".
CLI::Validator integer_in(std::uint64_t lo, std::uint64_t hi);

/// A finite number in [lo, hi] ((lo, hi] if lo_open): rejects nan and inf.
CLI::Validator number_in(double lo, double hi, bool lo_open = false);

/// Refuses `--rate` / `--frames` given to a measurement-level scenario
/// (they apply to raw-ADC frames only); throws std::runtime_error.
void check_raw_adc_only_flags(const std::string& scenario, double rate_hz, std::uint32_t frames);
/// The same for --adc-format and --saturation-policy (non-empty = given).
void check_raw_adc_only_adc_flags(const std::string& scenario, const std::string& adc_format,
                                  const std::string& saturation_policy);

/// Measurement limit per scan: far above every caps preset (LargeCaps 1024
/// detections per scan), so only a scenario that would swamp any tracker
/// is refused.
inline constexpr double kMaxExpectedMeasurementsPerScan = 10.0 * 1024.0;

/// Throws if the scenario's expected measurements per scan (scenario_spec.h)
/// exceed kMaxExpectedMeasurementsPerScan, with the figure.
void check_bounded_work(const scenario::ScenarioSpec& spec, double clutter_scale);

/// Estimated CSV bytes of a run: runs written x scans x rows per scan x a
/// typical row length.
double estimate_output_bytes(const scenario::ScenarioSpec& spec, double clutter_scale, std::uint64_t runs,
                             std::int64_t csv_runs);

/// Refusal threshold of estimate_output_bytes without --force.
inline constexpr double kMaxOutputBytes = 2e9;

/// Throws (naming --runs, --csv-runs and --force) if out_dir is set and the
/// estimate exceeds kMaxOutputBytes, unless force.
void check_output_size(const scenario::ScenarioSpec& spec, double clutter_scale, std::uint64_t runs,
                       std::int64_t csv_runs, const std::string& out_dir, bool force);

/// Throws if a target of a polar or Cartesian scenario is never inside the
/// surveillance region during its lifetime in `scans` (it could only ever
/// count as a missed truth). OTHR scenarios are not checked.
void check_targets_in_region(const scenario::ScenarioSpec& spec, const std::vector<scenario::SimScan>& scans);

}  // namespace mptrack::sim
