// Recorded detections as a scan source (run/scan_source.h): the scans of a
// detections file (detections_csv.h), delivered as they are, with no truth.
// The sensor (region, noise, threshold, period, clutter rates the trackers
// are set up with) comes from a scenario; its scan count and evaluation
// window follow the file.
#pragma once

#include <stdexcept>
#include <vector>

#include "run/scan_source.h"

namespace mptrack::sim {

class ReplaySource final : public ScanSource {
 public:
  /// `sensor`: the scenario the trackers are configured from.
  ReplaySource(scenario::ScenarioSpec sensor, std::vector<scenario::SimScan> scans)
      : spec_(std::move(sensor)), scans_(std::move(scans)) {
    if (scans_.empty()) throw std::runtime_error("replay: no scans");
    spec_.num_scans = static_cast<std::uint32_t>(scans_.size());
    if (spec_.eval_first_scan > spec_.num_scans) spec_.eval_first_scan = 1;
    if (spec_.eval_last_scan > spec_.num_scans || spec_.eval_last_scan < spec_.eval_first_scan) {
      spec_.eval_last_scan = spec_.num_scans;
    }
  }
  const scenario::ScenarioSpec& spec() const override { return spec_; }
  void begin_run(std::uint32_t /*run: one recording*/) override {}
  void deliver(const ScanStep& step, FrameInput /*input: always detections*/) override {
    for (const scenario::SimScan& s : scans_) step(s, nullptr);
  }
  const std::vector<scenario::SimScan>& scans() const override { return scans_; }

 private:
  scenario::ScenarioSpec spec_;
  std::vector<scenario::SimScan> scans_;
};

}  // namespace mptrack::sim
