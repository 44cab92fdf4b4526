// Raw-ADC scans as a scan source (run/scan_source.h): per run,
//   1. begin_run: synthesise every frame and its truth (not timed);
//   2. deliver:   stream the frames through the SPSC ring (stream_pipeline.h)
//                 at rate_hz; the consumer hands the tracker step what it
//                 consumes (run/frame_input.h): FrontEnd::process's detections
//                 (range, Doppler, angle, CFAR stages timed), the SBL
//                 detector's (timed) or the frame itself; a dropped frame
//                 reaches no tracker;
//      With adc.sample_format "int16" the producer is the ADC: it quantises
//      each frame (adc/adc_model.h) into the int16 slot the ring carries; the
//      front end consumes the codes as they are, the float-only stages (SBL,
//      VMP) get them back in volts. A saturated frame (more than
//      adc.saturation_fraction of its values at a rail; the front end's own
//      flag on the CFAR path) follows adc.saturation_policy: "keep" hands
//      its detections on, "drop" hands the frame to no tracker, as an
//      overrun would; both are counted (docs/algorithms/scenarios.md §ADC model);
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

namespace mptrack::frontend {
struct FrontEndStageTimes;
}

namespace mptrack::sim {

/// One frame of one delivery (a row of frontend.csv) [us].
struct FrameRecord {
  std::uint32_t detections = 0, drone_detections = 0, over_cap = 0;
  double range_us = 0, doppler_us = 0, angle_us = 0, cfar_us = 0, tracker_us = 0, frame_us = 0, queue_us = 0;
  bool processed = false;
  bool saturated = false;              ///< int16 path: the frame was saturated
  bool dropped_saturated = false;      ///< ... and saturation_policy "drop" kept it from the tracker
};

/// Detection totals of one delivery (one tracker's pass over a run).
struct FrontEndTotals {
  StreamCounters ring;
  std::uint64_t drone_frames = 0;      ///< (alive drone, processed frame) pairs
  std::uint64_t matched = 0;           ///< ... with a detection within the gate
  double sum_range_err2 = 0.0;         ///< [m^2] over the matches
  double sum_bearing_err2 = 0.0;       ///< [rad^2]
  // int16 ADC path (zero on the float path).
  std::uint64_t clipped_samples = 0;   ///< sample values (I or Q) the ADC model clipped
  std::uint64_t frames_saturated = 0;  ///< processed frames flagged saturated
  std::uint64_t saturated_detections = 0;      ///< detections of those frames (kept or dropped)
  std::uint64_t saturated_frames_dropped = 0;  ///< saturated frames handed to no tracker (policy "drop")
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
  /// Processes one frame of either ring (float or int16 slots).
  template <class Frame>
  void consume(const Frame& f, std::uint64_t queue_ns, const ScanStep& step, FrameInput input);
  /// Runs the CFAR front end on the cube (float or int16) into s (stage
  /// times into r); true when the front end flagged the frame saturated.
  template <class Cube>
  bool detect_cfar(const Cube& cube, scenario::SimScan& s, FrameRecord& r);
  /// Runs the SBL detector on the float cube into s (stage times into r).
  void detect_sbl(const adc::AdcCube& cube, scenario::SimScan& s, FrameRecord& r);
  /// Appends the detector's detections to s unless fst says the frame failed.
  void take_detections(Status fst, const frontend::FrontEndStageTimes& times, std::size_t over_cap,
                       scenario::SimScan& s, FrameRecord& r);
  void label_run();
  bool int16() const { return sc_.adc.sample_format == "int16"; }

  adc::AdcScenario sc_;
  scenario::ScenarioSpec view_;
  std::uint64_t seed_ = 1;
  double rate_hz_ = 0.0;
  std::uint32_t consumer_delay_us_ = 0;
  std::unique_ptr<FrontEndBox> fe_;
  std::vector<adc::AdcCube> cubes_;              ///< the synthesised volts (the ADC's input)
  std::vector<std::size_t> clipped_;             ///< per frame: values the ADC clipped (int16 path)
  std::unique_ptr<adc::AdcCube> volts_;          ///< int16 path: codes back in volts (SBL, VMP)
  std::vector<scenario::SimScan> truth_scans_;  ///< truth only, as synthesised
  std::vector<scenario::SimScan> scans_;        ///< + the last delivery's detections and labels
  std::vector<FrameRecord> records_;
  FrontEndTotals totals_;
  platform::CoreProfileRecorders stage_profile_;
};

}  // namespace mptrack::sim
