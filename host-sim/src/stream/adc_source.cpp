// Raw-ADC scan source; see adc_source.h.
#include "stream/adc_source.h"

#include "param_error_text.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

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
  auto ring = std::make_unique<StreamRing>();  // fresh counters per delivery
  StreamOptions opt;
  opt.rate_hz = rate_hz_;
  const StreamCounters rc = run_stream(
      *ring, sc_.num_frames, opt, [&](std::uint32_t k, StreamFrame& slot) { slot.cube = cubes_[k - 1]; },
      [&](const StreamFrame& f, std::uint64_t queue_ns) { consume(f, queue_ns, step, input); });
  totals_ = FrontEndTotals{};
  totals_.ring = rc;
  label_run();
}

void AdcScanSource::consume(const StreamFrame& f, std::uint64_t queue_ns, const ScanStep& step, FrameInput input) {
  const std::uint64_t t0 = stream_now_ns();
  FrameRecord& r = records_[f.frame - 1];
  r.processed = true;
  r.queue_us = static_cast<double>(queue_ns) * 1e-3;
  scenario::SimScan& s = scans_[f.frame - 1];
  if (input != FrameInput::kRawFrame) detect(f, input, s, r);
  const std::uint64_t t1 = stream_now_ns();
  r.detections = static_cast<std::uint32_t>(s.measurements.size());
  r.tracker_us = step(s, input == FrameInput::kRawFrame ? &f.cube : nullptr);
  stage_profile_.poll();
  r.frame_us = static_cast<double>(t1 - t0) * 1e-3 + r.tracker_us;
  if (consumer_delay_us_ > 0) std::this_thread::sleep_for(std::chrono::microseconds(consumer_delay_us_));
}

void AdcScanSource::detect(const StreamFrame& f, FrameInput input, scenario::SimScan& s, FrameRecord& r) {
  frontend::FrontEndStageTimes times;
  times.clock = &ns_clock;
  const bool sbl = input == FrameInput::kSblDetections;
  // SBL stage times use the front end's slots: spectrum, -, map searches, refinement.
  const Status fst = sbl ? fe_->sbl.process(f.cube, fe_->scan, &times) : fe_->fe.process(f.cube, fe_->scan, &times);
  stage_profile_.poll();
  r.range_us = times.ticks[0] * 1e-3;
  r.doppler_us = times.ticks[1] * 1e-3;
  r.angle_us = times.ticks[2] * 1e-3;
  r.cfar_us = times.ticks[3] * 1e-3;
  r.over_cap = static_cast<std::uint32_t>(sbl ? fe_->sbl.last_frame_dropped() : fe_->fe.last_frame_dropped());
  // kCapacityExceeded: the strongest detections were kept (the rest are
  // counted in over_cap); the frame is still usable.
  if (fst != Status::kOk && fst != Status::kCapacityExceeded) return;
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
  }
}

}  // namespace mptrack::sim
