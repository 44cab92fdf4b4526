// A scan source: where the scans of a Monte Carlo run come from. The run
// loop (run_loop.h) asks it to prepare run r, then to hand every scan to a
// tracker step, then reads the scans back (with truth) for evaluation.
//   MeasurementSource  the scenario generator (measurement level)
//   AdcScanSource      raw ADC frames -> ring buffer -> front end (stream/)
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "mptrack/scenario/generator.h"
#include "mptrack/scenario/scenario_spec.h"
#include "run/frame_input.h"

namespace mptrack::sim {

/// Runs the tracker on one scan; returns the wall time of its step() [us].
/// `frame` is the raw frame behind the scan when the tracker asked for
/// FrameInput::kRawFrame, else nullptr.
using ScanStep = std::function<double(const scenario::SimScan& scan, const RawFrame* frame)>;

class ScanSource {
 public:
  virtual ~ScanSource() = default;
  /// The measurement-level view of the scenario: what trackers are set up
  /// with, and what the CSV writers and the plot read (evaluation interval).
  virtual const scenario::ScenarioSpec& spec() const = 0;
  std::uint32_t num_scans() const { return spec().num_scans; }
  /// Draws run `run`'s data (not timed). Throws std::runtime_error.
  virtual void begin_run(std::uint32_t run) = 0;
  /// Hands the run's scans to `step` in scan order; a source may skip a
  /// scan (a dropped frame). May be called again for the next tracker: every
  /// call sees the same data. `input`: what the tracker consumes (raw-ADC
  /// sources; a measurement source always gives its detections).
  virtual void deliver(const ScanStep& step, FrameInput input) = 0;
  /// The run's scans (index scan-1) with truth and origins, after deliver().
  virtual const std::vector<scenario::SimScan>& scans() const = 0;
};

/// Measurement-level scans from the scenario generator: scan k of run r is
/// drawn from the stream derive_seed(seed, r, k), so every tracker and every
/// subcommand sees the same measurements for the same seed.
class MeasurementSource final : public ScanSource {
 public:
  /// Validates the scenario (throws std::runtime_error naming the field).
  MeasurementSource(scenario::ScenarioSpec spec, std::uint64_t seed, double clutter_scale);
  const scenario::ScenarioSpec& spec() const override { return spec_; }
  void begin_run(std::uint32_t run) override;
  void deliver(const ScanStep& step, FrameInput input) override;
  const std::vector<scenario::SimScan>& scans() const override { return scans_; }

 private:
  scenario::ScenarioSpec spec_;
  std::uint64_t seed_ = 1;
  double clutter_scale_ = 1.0;
  std::vector<scenario::SimScan> scans_;
};

}  // namespace mptrack::sim
