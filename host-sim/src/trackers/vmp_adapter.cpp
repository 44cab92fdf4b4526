// `--tracker vmp` on raw-ADC scenarios: seed 004's VMP tracker
// (core/include/mptrack/vmp/) on the raw frame itself, in float as on a
// board, configured from the scenario's radar (adc::vmp_params_for).
#include "trackers/vmp_adapter.h"

#include "mptrack/adc/vmp_config.h"
#include "mptrack/vmp/vmp_tracker.h"
#include "param_error_text.h"

namespace mptrack::sim {

namespace {

class VmpAdapter final : public TrackerAdapter {
 public:
  using Tracker = VmpTracker<float>;

  VmpAdapter() : tracker_(std::make_unique<Tracker>()) {}

  std::string init(const TrackerSetup& setup) override {
    if (!setup.raw_scenario) return "vmp runs on raw ADC frames only (seed004-drones, mimo-interference)";
    const VmpParams p = adc::vmp_params_for(*setup.raw_scenario);
    ParamError where;
    if (Tracker::validate(p, &where) != Status::kOk) {
      return describe_param_error("vmp", where);
    }
    const Status st = tracker_->init(p);
    return st == Status::kOk ? std::string() : std::string("init failed: ") + to_string(st);
  }

  FrameInput frame_input() const override { return FrameInput::kRawFrame; }

  Status step_frame(const RawFrame& frame, const scenario::SimScan& /*scan*/,
                    std::vector<EstimateOut>& out) override {
    const Status st = tracker_->step(frame);
    collect(out);
    return st;
  }

  /// Detections never reach a raw-frame tracker.
  Status step(const scenario::SimScan& /*scan*/, std::vector<EstimateOut>& /*out*/) override {
    return Status::kInvalidArgument;
  }

  Status flush(std::vector<EstimateOut>& out) override {
    const Status st = tracker_->flush();
    collect(out);
    return st;
  }

  TrackerCounters counters() const override { return tracker_->counters(); }

 private:
  void collect(std::vector<EstimateOut>& out) {
    for (const auto& e : tracker_->outputs()) out.push_back(to_estimate_out(e));
  }

  std::unique_ptr<Tracker> tracker_;
};

}  // namespace

std::unique_ptr<TrackerAdapter> make_vmp_adapter() { return std::make_unique<VmpAdapter>(); }

}  // namespace mptrack::sim
