// Producer/consumer streaming through the SPSC ring (host-sim/src/stream):
// every frame is accounted for, overruns drop new frames and count them.
#include <doctest/doctest.h>

#include <chrono>
#include <memory>
#include <thread>
#include <vector>

#include "stream/adc_runner.h"
#include "stream/stream_pipeline.h"

using mptrack::sim::StreamCounters;
using mptrack::sim::StreamFrame;
using mptrack::sim::StreamOptions;
using mptrack::sim::StreamRing;

namespace {

// The producer stamps the frame number into the first sample so the
// consumer can check it got the right payload.
void fill(std::uint32_t k, StreamFrame& slot) { slot.cube.iq[0] = static_cast<float>(k); }

}  // namespace

TEST_CASE("stream: lossless mode delivers every frame once, in order, with its payload") {
  auto ring = std::make_unique<StreamRing>();
  std::vector<std::uint32_t> seen;
  bool payload_ok = true;
  StreamOptions opt;  // rate 0: back-pressure
  const StreamCounters c = mptrack::sim::run_stream(*ring, 50, opt, fill, [&](const StreamFrame& f, std::uint64_t) {
    seen.push_back(f.frame);
    payload_ok = payload_ok && f.cube.iq[0] == static_cast<float>(f.frame);
    std::this_thread::sleep_for(std::chrono::microseconds(200));  // slower than the producer: ring fills
  });
  CHECK(c.frames_offered == 50);
  CHECK(c.frames_pushed == 50);
  CHECK(c.frames_processed == 50);
  CHECK(c.dropped_frames == 0);
  REQUIRE(seen.size() == 50);
  for (std::uint32_t i = 0; i < 50; ++i) CHECK(seen[i] == i + 1);
  CHECK(payload_ok);
}

TEST_CASE("stream: a slow consumer at a fixed frame rate drops frames, and pushed = processed, offered = processed + dropped") {
  auto ring = std::make_unique<StreamRing>();
  std::vector<std::uint32_t> seen;
  StreamOptions opt;
  opt.rate_hz = 2000.0;  // a frame every 0.5 ms ...
  const StreamCounters c = mptrack::sim::run_stream(*ring, 80, opt, fill, [&](const StreamFrame& f, std::uint64_t) {
    seen.push_back(f.frame);
    std::this_thread::sleep_for(std::chrono::milliseconds(3));  // ... consumed every >= 3 ms
  });
  CHECK(c.frames_offered == 80);
  CHECK(c.dropped_frames > 0);
  CHECK(c.frames_pushed == c.frames_processed);
  CHECK(c.frames_offered == c.frames_processed + c.dropped_frames);
  CHECK(seen.size() == c.frames_processed);
  // The first kCapacity frames always fit; frames arrive in increasing order.
  CHECK(c.frames_processed >= StreamRing::kCapacity);
  for (std::size_t i = 1; i < seen.size(); ++i) CHECK(seen[i] > seen[i - 1]);
}

TEST_CASE("stream: the raw-ADC runner accounts every frame and times every stage") {
  mptrack::sim::AdcRunConfig cfg;
  REQUIRE(mptrack::adc::builtin_adc_scenario("seed004-drones", cfg.scenario));
  cfg.tracker = "gnn";
  cfg.frames = 12;
  cfg.progress = false;
  const mptrack::sim::AdcSummary s = mptrack::sim::run_adc_monte_carlo(cfg);
  CHECK(s.ring.frames_offered == 12);
  CHECK(s.ring.frames_processed == 12);
  CHECK(s.ring.dropped_frames == 0);
  CHECK(s.stages.range.count == 12);
  CHECK(s.stages.tracker.count == 12);
  CHECK(s.stages.range.max_us > 0.0);
  CHECK(s.base.scans == 12);
  CHECK(s.base.mean_truths == doctest::Approx(2.0));  // drones 1 and 2 for n = 1..12

  // Same frames, a consumer slowed to 20 ms per frame at 200 Hz: frames drop,
  // every one is counted, and dropped frames score OSPA = c (no estimate).
  cfg.rate_hz = 200.0;
  cfg.consumer_delay_us = 20000;
  const mptrack::sim::AdcSummary d = mptrack::sim::run_adc_monte_carlo(cfg);
  CHECK(d.ring.frames_offered == 12);
  CHECK(d.ring.dropped_frames > 0);
  CHECK(d.ring.frames_offered == d.ring.frames_processed + d.ring.dropped_frames);
  CHECK(d.stages.range.count == d.ring.frames_processed);
}
