// Harness input checks; see input_checks.h.
#include "cli/input_checks.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <map>
#include <stdexcept>

#include "param_error_text.h"

namespace mptrack::sim {

namespace {

std::string fmt(double x) { return format_number(x); }

}  // namespace

CLI::Validator integer_in(std::uint64_t lo, std::uint64_t hi) {
  const std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  return CLI::Validator(
      [lo, hi, range](std::string& text) -> std::string {
        errno = 0;
        char* end = nullptr;
        const unsigned long long v = std::strtoull(text.c_str(), &end, 10);
        const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
        if (!digits || errno != 0 || *end != '\0' || v < lo || v > hi) {
          return text + " is not an integer in " + range;
        }
        return "";
      },
      "INT in " + range, "integer_in");
}

CLI::Validator number_in(double lo, double hi, bool lo_open) {
  const std::string range = std::string(lo_open ? "(" : "[") + fmt(lo) + ", " + fmt(hi) + "]";
  return CLI::Validator(
      [lo, hi, lo_open, range](std::string& text) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        const bool parsed = !text.empty() && end != nullptr && *end == '\0';
        const bool ok = parsed && std::isfinite(v) && (lo_open ? v > lo : v >= lo) && v <= hi;
        if (!ok) return text + " is not a finite number in " + range;
        return "";
      },
      "NUMBER in " + range, "number_in");
}

void check_raw_adc_only_flags(const std::string& scenario, double rate_hz, std::uint32_t frames) {
  const char* flag = rate_hz != 0.0 ? "--rate" : frames != 0 ? "--frames" : nullptr;
  if (flag == nullptr) return;
  throw std::runtime_error(std::string(flag) + " applies to raw-ADC scenarios only (seed004-drones, mimo-interference); " +
                           scenario + " is measurement-level (use --scans to shorten it)");
}

void check_raw_adc_only_adc_flags(const std::string& scenario, const std::string& adc_format,
                                  const std::string& saturation_policy) {
  const char* flag = !adc_format.empty() ? "--adc-format" : !saturation_policy.empty() ? "--saturation-policy" : nullptr;
  if (flag == nullptr) return;
  throw std::runtime_error(std::string(flag) + " applies to raw-ADC scenarios only (seed004-drones, mimo-interference); " +
                           scenario + " is measurement-level (its scenario has no ADC)");
}

void check_bounded_work(const scenario::ScenarioSpec& spec, double clutter_scale) {
  const double n = scenario::expected_measurements_per_scan(spec, clutter_scale);
  if (n <= kMaxExpectedMeasurementsPerScan) return;
  throw std::runtime_error("scenario " + spec.name + ": expected " + fmt(n) +
                           " measurements per scan (clutter mean counts x --clutter-scale " + fmt(clutter_scale) +
                           ", plus targets) exceeds " + fmt(kMaxExpectedMeasurementsPerScan) +
                           " (10 x the largest tracker cap, LargeCaps::kMaxMeasurements = 1024); "
                           "lower clutter mean_count or --clutter-scale");
}

double estimate_output_bytes(const scenario::ScenarioSpec& spec, double clutter_scale, std::uint64_t runs,
                             std::int64_t csv_runs) {
  const double written = csv_runs < 0 ? static_cast<double>(runs)
                                      : std::fmin(static_cast<double>(runs), static_cast<double>(csv_runs));
  // measurements.csv ~55 B a row; truth.csv and tracks.csv ~80 B per target
  // (tracks ~ truths); metrics.csv ~80 B per scan.
  const double per_scan = 55.0 * scenario::expected_measurements_per_scan(spec, clutter_scale) +
                          160.0 * static_cast<double>(spec.targets.size()) + 80.0;
  return written * static_cast<double>(spec.num_scans) * per_scan;
}

void check_output_size(const scenario::ScenarioSpec& spec, double clutter_scale, std::uint64_t runs,
                       std::int64_t csv_runs, const std::string& out_dir, bool force) {
  if (out_dir.empty() || force) return;
  const double bytes = estimate_output_bytes(spec, clutter_scale, runs, csv_runs);
  if (bytes <= kMaxOutputBytes) return;
  throw std::runtime_error("--runs " + std::to_string(runs) + " x " + std::to_string(spec.num_scans) +
                           " scans would write about " + fmt(bytes / 1e9) + " GB of CSV to " + out_dir +
                           " (limit " + fmt(kMaxOutputBytes / 1e9) +
                           " GB): write fewer runs with --csv-runs N, or pass --force");
}

void check_targets_in_region(const scenario::ScenarioSpec& spec, const std::vector<scenario::SimScan>& scans) {
  if (spec.space == scenario::MeasurementSpace::kOthr) return;
  std::map<std::uint32_t, bool> seen_inside;
  for (const auto& t : spec.targets) seen_inside[static_cast<std::uint32_t>(t.id)] = false;
  const scenario::Region& r = spec.region;
  const scenario::CartesianRegion& b = spec.xy_region;
  const double az_min = scenario::deg_to_rad(r.azimuth_min_deg), az_max = scenario::deg_to_rad(r.azimuth_max_deg);
  for (const scenario::SimScan& s : scans) {
    for (const scenario::TruthState& t : s.truth) {
      const double x = t.x.px, y = t.x.py;
      bool inside = false;
      if (spec.space == scenario::MeasurementSpace::kCartesian) {
        inside = x >= b.x_min_m && x <= b.x_max_m && y >= b.y_min_m && y <= b.y_max_m;
      } else {
        const double range = std::hypot(x, y), az = std::atan2(y, x);
        inside = range >= r.range_min_m && range <= r.range_max_m && az >= az_min && az <= az_max;
      }
      if (inside) seen_inside[t.target_id] = true;
    }
  }
  for (std::size_t i = 0; i < spec.targets.size(); ++i) {
    if (seen_inside[static_cast<std::uint32_t>(spec.targets[i].id)]) continue;
    const std::string region =
        spec.space == scenario::MeasurementSpace::kCartesian
            ? "x [" + fmt(b.x_min_m) + ", " + fmt(b.x_max_m) + "] m, y [" + fmt(b.y_min_m) + ", " + fmt(b.y_max_m) + "] m"
            : "range [" + fmt(r.range_min_m) + ", " + fmt(r.range_max_m) + "] m, azimuth [" + fmt(r.azimuth_min_deg) +
                  ", " + fmt(r.azimuth_max_deg) + "] deg";
    throw std::runtime_error("scenario " + spec.name + ": targets[" + std::to_string(i) + "] (id " +
                             std::to_string(spec.targets[i].id) +
                             ") is never inside the surveillance region (" + region +
                             ") during its lifetime: it could only be scored as a missed truth");
  }
}

}  // namespace mptrack::sim
