// Raw-ADC scan source; see adc_source.h.
#include "stream/adc_source.h"

#include "param_error_text.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>
#include <utility>

#include "mptrack/adc/adc_model.h"
#include "mptrack/adc/frontend_config.h"
#include "mptrack/adc/sbl_config.h"
#include "mptrack/frontend/front_end.h"
#include "mptrack/sbl/sbl_detector.h"
#include "mptrack/math/detmath.h"
#include "mptrack/validate.h"
#include "stream/adc_trackers.h"

namespace mptrack::sim {

namespace {

constexpr double kMatchGate_m = 3.0;  ///< detection <-> drone association gate for origin labels and accuracy

// FrontEndStageTimes wants a 32-bit tick source: steady-clock nanoseconds
// (wraps every 4.3 s; stage deltas are far shorter).
std::uint32_t ns_clock() { return static_cast<std::uint32_t>(stream_now_ns()); }

/// Labels each detection with the nearest drone within the gate (each
/// detection and each drone used once, closest pairs first); fills
/// truth.measurement_index. Adds the squared errors of the matches.
void label_origins(scenario::SimScan& s, FrontEndTotals& tot) {
  struct Pair {
    double d;
    std::size_t t, m;
  };
  std::vector<Pair> pairs;
  for (std::size_t t = 0; t < s.truth.size(); ++t) {
    for (std::size_t m = 0; m < s.measurements.size(); ++m) {
      const scenario::SimMeasurement& y = s.measurements[m];
      double sn = 0.0, cs = 1.0;
      dmath::dsincos(y.azimuth_rad, sn, cs);
      const double d = std::hypot(y.range_m * cs - s.truth[t].x.px, y.range_m * sn - s.truth[t].x.py);
      if (d < kMatchGate_m) pairs.push_back(Pair{d, t, m});
    }
  }
  std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) {
    return a.d < b.d || (a.d == b.d && (a.t < b.t || (a.t == b.t && a.m < b.m)));
  });
  for (const Pair& p : pairs) {
    scenario::TruthState& t = s.truth[p.t];
    scenario::SimMeasurement& y = s.measurements[p.m];
    if (t.measurement_index >= 0 || y.origin.kind == scenario::OriginKind::kTarget) continue;
    t.measurement_index = static_cast<std::int32_t>(p.m);
    t.detected = true;
    y.origin = scenario::Origin{scenario::OriginKind::kTarget, t.target_id};
    const double r = std::hypot(t.x.px, t.x.py);
    const double dr = y.range_m - r;
    double db = y.azimuth_rad - dmath::datan2(t.x.py, t.x.px);
    tot.sum_range_err2 += dr * dr;
    tot.sum_bearing_err2 += db * db;
    ++tot.matched;
  }
}

scenario::SimScan truth_scan(std::uint32_t k, std::uint64_t time_us, const std::vector<adc::DroneTruth>& truth) {
  scenario::SimScan s;
  s.scan = k;
  s.time_us = time_us;
  for (const adc::DroneTruth& t : truth) {
    scenario::TruthState ts;
    ts.target_id = t.id;
    ts.x.px = t.state.x;
    ts.x.py = t.state.y;
    ts.x.vx = t.state.vx;
    ts.x.vy = t.state.vy;
    ts.snr = t.snr_mean;
    ts.in_region = true;
    s.truth.push_back(ts);
  }
  return s;
}

}  // namespace

class AdcScanSource::FrontEndBox {
 public:
  frontend::FrontEnd<adc::AdcCaps> fe;
  SblDetector<float> sbl;
  Scan<float, adc::AdcCaps::kMaxDetections> scan;
};

AdcScanSource::AdcScanSource(adc::AdcScenario scenario, std::uint64_t seed, double rate_hz,
                             std::uint32_t consumer_delay_us)
    : sc_(std::move(scenario)),
      view_(tracker_view(sc_)),
      seed_(seed),
      rate_hz_(rate_hz),
      consumer_delay_us_(consumer_delay_us),
      fe_(std::make_unique<FrontEndBox>()) {}

AdcScanSource::~AdcScanSource() = default;

void AdcScanSource::begin_run(std::uint32_t run) {
  adc::FrameSynthesizer syn;
  if (syn.init(sc_, seed_, run) != Status::kOk) throw std::runtime_error(syn.error());
  const std::uint32_t n = sc_.num_frames;
  cubes_.assign(n, adc::AdcCube{});
  truth_scans_.assign(n, scenario::SimScan{});
  std::vector<adc::DroneTruth> truth;
  for (std::uint32_t k = 1; k <= n; ++k) {
    if (syn.synthesize(k, cubes_[k - 1], truth) != Status::kOk) throw std::runtime_error("synthesis failed");
    truth_scans_[k - 1] = truth_scan(k, cubes_[k - 1].time_us, truth);
  }
}

void AdcScanSource::deliver(const ScanStep& step, FrameInput input) {
  ParamError where;
  if (input == FrameInput::kCfarDetections) {
    const frontend::FrontEndParams fp = adc::frontend_params_for(sc_);
    if (frontend::FrontEnd<adc::AdcCaps>::validate(fp, &where) != Status::kOk) {
      throw std::runtime_error("invalid front-end parameter " + describe_param_error("frontend", where));
    }
    if (fe_->fe.init(fp) != Status::kOk) throw std::runtime_error("front end init failed");
  } else if (input == FrameInput::kSblDetections) {
    const SblParams sp = adc::sbl_params_for(sc_);
    if (SblDetector<float>::validate(sp, &where) != Status::kOk) {
      throw std::runtime_error("invalid SBL detector parameter " + describe_param_error("sbl", where));
    }
    if (fe_->sbl.init(sp) != Status::kOk) throw std::runtime_error("SBL detector init failed");
  }
  scans_ = truth_scans_;
  records_.assign(sc_.num_frames, FrameRecord{});
  clipped_.assign(sc_.num_frames, 0);
  StreamOptions opt;
  opt.rate_hz = rate_hz_;
  StreamCounters rc;
  if (int16()) {
    // The producer is the ADC: it quantises the frame into the slot.
    if (!volts_) volts_ = std::make_unique<adc::AdcCube>();
    auto ring = std::make_unique<StreamRing16>();  // fresh counters per delivery
    rc = run_stream<StreamFrame16>(
        *ring, sc_.num_frames, opt,
        [&](std::uint32_t k, StreamFrame16& slot) { clipped_[k - 1] = adc::quantise(cubes_[k - 1], sc_.adc, slot.cube); },
        [&](const StreamFrame16& f, std::uint64_t queue_ns) { consume(f, queue_ns, step, input); });
  } else {
    auto ring = std::make_unique<StreamRing>();  // fresh counters per delivery
    rc = run_stream<StreamFrame>(
        *ring, sc_.num_frames, opt, [&](std::uint32_t k, StreamFrame& slot) { slot.cube = cubes_[k - 1]; },
        [&](const StreamFrame& f, std::uint64_t queue_ns) { consume(f, queue_ns, step, input); });
  }
  totals_ = FrontEndTotals{};
  totals_.ring = rc;
  label_run();
}

template <class Frame>
void AdcScanSource::consume(const Frame& f, std::uint64_t queue_ns, const ScanStep& step, FrameInput input) {
  constexpr bool kInt16 = std::is_same_v<Frame, StreamFrame16>;
  const std::uint64_t t0 = stream_now_ns();
  FrameRecord& r = records_[f.frame - 1];
  r.processed = true;
  r.queue_us = static_cast<double>(queue_ns) * 1e-3;
  scenario::SimScan& s = scans_[f.frame - 1];
  // The float-only stages (SBL, VMP) read volts: the int16 codes scaled back.
  const adc::AdcCube* volts = nullptr;
  if constexpr (kInt16) {
    if (input != FrameInput::kCfarDetections) {
      adc::codes_to_volts(f.cube, sc_.adc, *volts_);
      volts = volts_.get();
      r.saturated = adc::frame_saturated(f.cube, sc_.adc);
    }
  } else {
    volts = &f.cube;
  }
  if (input == FrameInput::kCfarDetections) {
    const bool saturated = detect_cfar(f.cube, s, r);
    if constexpr (kInt16) r.saturated = saturated;
  } else if (input == FrameInput::kSblDetections) {
    detect_sbl(*volts, s, r);
  }
  const std::uint64_t t1 = stream_now_ns();
  r.detections = static_cast<std::uint32_t>(s.measurements.size());
  // Saturation policy "drop": the frame reaches no tracker (as an overrun).
  r.dropped_saturated = r.saturated && sc_.adc.saturation_policy == "drop";
  if (r.dropped_saturated) {
    s.measurements.clear();
  } else {
    r.tracker_us = step(s, input == FrameInput::kRawFrame ? volts : nullptr);
  }
  stage_profile_.poll();
  r.frame_us = static_cast<double>(t1 - t0) * 1e-3 + r.tracker_us;
  if (consumer_delay_us_ > 0) std::this_thread::sleep_for(std::chrono::microseconds(consumer_delay_us_));
}

template <class Cube>
bool AdcScanSource::detect_cfar(const Cube& cube, scenario::SimScan& s, FrameRecord& r) {
  frontend::FrontEndStageTimes times;
  times.clock = &ns_clock;
  const std::uint64_t saturated_before = fe_->fe.counters().frames_saturated;
  const Status fst = fe_->fe.process(cube, fe_->scan, &times);
  stage_profile_.poll();
  take_detections(fst, times, fe_->fe.last_frame_dropped(), s, r);
  return fe_->fe.counters().frames_saturated != saturated_before;
}

void AdcScanSource::detect_sbl(const adc::AdcCube& cube, scenario::SimScan& s, FrameRecord& r) {
  frontend::FrontEndStageTimes times;
  times.clock = &ns_clock;
  // SBL stage times use the front end's slots: spectrum, -, map searches, refinement.
  const Status fst = fe_->sbl.process(cube, fe_->scan, &times);
  stage_profile_.poll();
  take_detections(fst, times, fe_->sbl.last_frame_dropped(), s, r);
}

void AdcScanSource::take_detections(Status fst, const frontend::FrontEndStageTimes& times, std::size_t over_cap,
                                    scenario::SimScan& s, FrameRecord& r) {
  r.range_us = times.ticks[0] * 1e-3;
  r.doppler_us = times.ticks[1] * 1e-3;
  r.angle_us = times.ticks[2] * 1e-3;
  r.cfar_us = times.ticks[3] * 1e-3;
  r.over_cap = static_cast<std::uint32_t>(over_cap);
  // kCapacityExceeded: the strongest detections were kept (the rest are
  // counted in over_cap); kPartial: a saturated int16 frame or a detection
  // dropped for a non-finite amplitude (counted by the front end), the rest
  // valid. Both frames are usable; the saturation policy is consume()'s.
  if (fst != Status::kOk && fst != Status::kCapacityExceeded && fst != Status::kPartial) return;
  for (const Measurement<float>& m : fe_->scan.measurements) {
    scenario::SimMeasurement y;
    y.range_m = static_cast<double>(m.range_m);
    y.azimuth_rad = static_cast<double>(m.azimuth_rad);
    y.amplitude = static_cast<double>(m.amplitude);
    y.origin = scenario::Origin{scenario::OriginKind::kClutter, 0};
    s.measurements.push_back(y);
  }
}

void AdcScanSource::label_run() {
  for (std::uint32_t k = 1; k <= sc_.num_frames; ++k) {
    scenario::SimScan& s = scans_[k - 1];
    label_origins(s, totals_);
    FrameRecord& r = records_[k - 1];
    for (const auto& t : s.truth) r.drone_detections += t.measurement_index >= 0 ? 1u : 0u;
    if (r.processed) totals_.drone_frames += s.truth.size();
    totals_.clipped_samples += clipped_[k - 1];
    if (r.saturated) {
      ++totals_.frames_saturated;
      totals_.saturated_detections += r.detections;
    }
    if (r.dropped_saturated) ++totals_.saturated_frames_dropped;
  }
}

}  // namespace mptrack::sim
