// The scenario generator as a scan source; see scan_source.h.
#include <stdexcept>
#include <string>
#include <utility>

#include "cli/input_checks.h"
#include "run/scan_source.h"

namespace mptrack::sim {

MeasurementSource::MeasurementSource(scenario::ScenarioSpec spec, std::uint64_t seed, double clutter_scale)
    : spec_(std::move(spec)), seed_(seed), clutter_scale_(clutter_scale) {
  const std::string error = scenario::validate(spec_);
  if (!error.empty()) throw std::runtime_error("scenario " + spec_.name + ": " + error);
}

void MeasurementSource::begin_run(std::uint32_t run) {
  scenario::Generator gen;
  scenario::GeneratorOptions options;
  options.clutter_scale = clutter_scale_;
  if (gen.init(spec_, seed_, run, options) != Status::kOk) throw std::runtime_error(gen.error());
  scans_.assign(spec_.num_scans, scenario::SimScan{});
  for (std::uint32_t k = 1; k <= spec_.num_scans; ++k) {
    if (gen.generate(k, scans_[k - 1]) != Status::kOk) {
      throw std::runtime_error("generator failed at scan " + std::to_string(k));
    }
  }
  if (run == 0) check_targets_in_region(spec_, scans_);
}

void MeasurementSource::deliver(const ScanStep& step, FrameInput /*input: always detections*/) {
  for (const scenario::SimScan& s : scans_) step(s, nullptr);
}

}  // namespace mptrack::sim
