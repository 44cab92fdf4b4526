// Raw-ADC scans as a scan source (run/scan_source.h): per run,
//   1. begin_run: synthesise every frame and its truth (not timed);
//   2. deliver:   stream the frames through the SPSC ring (stream_pipeline.h)
//                 at rate_hz; the consumer hands the tracker step what it
//                 consumes (run/frame_input.h): FrontEnd::process's detections
//                 (range, Doppler, angle, CFAR stages timed), the SBL
//                 detector's (timed) or the frame itself; a dropped frame
//                 reaches no tracker;
//   3. then labels each detection with the nearest drone (truth only, after
//                 the tracker saw the frame) for CAR and front-end accuracy.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "mptrack/adc/adc_scenario.h"
#include "mptrack/adc/synthesizer.h"
#include "mptrack/platform/stage_report.h"
#include "run/scan_source.h"
#include "stream/stream_pipeline.h"

namespace mptrack::sim {

/// One frame of one delivery (a row of frontend.csv) [us].
struct FrameRecord {
  std::uint32_t detections = 0, drone_detections = 0, over_cap = 0;
  double range_us = 0, doppler_us = 0, angle_us = 0, cfar_us = 0, tracker_us = 0, frame_us = 0, queue_us = 0;
  bool processed = false;
};

/// Detection totals of one delivery (one tracker's pass over a run).
struct FrontEndTotals {
  StreamCounters ring;
  std::uint64_t drone_frames = 0;      ///< (alive drone, processed frame) pairs
  std::uint64_t matched = 0;           ///< ... with a detection within the gate
  double sum_range_err2 = 0.0;         ///< [m^2] over the matches
  double sum_bearing_err2 = 0.0;       ///< [rad^2]
};

class AdcScanSource final : public ScanSource {
 public:
  /// `scenario` must be valid (adc::validate); consumer_delay_us is an extra
  /// sleep per consumed frame (tests: a slow consumer).
  AdcScanSource(adc::AdcScenario scenario, std::uint64_t seed, double rate_hz, std::uint32_t consumer_delay_us);
  ~AdcScanSource() override;
  const scenario::ScenarioSpec& spec() const override { return view_; }
  void begin_run(std::uint32_t run) override;
  void deliver(const ScanStep& step, FrameInput input) override;
  const std::vector<scenario::SimScan>& scans() const override { return scans_; }

  const adc::AdcScenario& scenario() const { return sc_; }
  /// The last delivery's frames (index frame-1).
  const std::vector<FrameRecord>& frame_records() const { return records_; }
  /// The last delivery's totals (what that tracker was given).
  const FrontEndTotals& totals() const { return totals_; }
  /// The per-stage table of a -DMPTRACK_PROFILE=ON build (no-op otherwise).
  void print_stage_profile() const { stage_profile_.print(); }

 private:
  class FrontEndBox;
  void consume(const StreamFrame& f, std::uint64_t queue_ns, const ScanStep& step, FrameInput input);
  /// Runs the detector `input` names (front end or SBL) on f into s (stage times into r).
  void detect(const StreamFrame& f, FrameInput input, scenario::SimScan& s, FrameRecord& r);
  void label_run();

  adc::AdcScenario sc_;
  scenario::ScenarioSpec view_;
  std::uint64_t seed_ = 1;
  double rate_hz_ = 0.0;
  std::uint32_t consumer_delay_us_ = 0;
  std::unique_ptr<FrontEndBox> fe_;
  std::vector<adc::AdcCube> cubes_;
  std::vector<scenario::SimScan> truth_scans_;  ///< truth only, as synthesised
  std::vector<scenario::SimScan> scans_;        ///< + the last delivery's detections and labels
  std::vector<FrameRecord> records_;
  FrontEndTotals totals_;
  platform::CoreProfileRecorders stage_profile_;
};

}  // namespace mptrack::sim
