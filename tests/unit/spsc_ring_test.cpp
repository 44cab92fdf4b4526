#include <doctest/doctest.h>

#include <array>
#include <chrono>
#include <cstdint>
#include <thread>

#include "mptrack/platform/spsc_ring.h"

using mptrack::Status;
using mptrack::platform::SpscRing;

namespace {
// A frame that carries its own checksum, so a torn (half-written) frame or
// a frame delivered twice is detectable by the consumer.
struct Frame {
  std::uint32_t sequence = 0;
  std::array<std::uint32_t, 64> payload{};
  std::uint32_t checksum = 0;
};

Frame make_frame(std::uint32_t seq) {
  Frame f;
  f.sequence = seq;
  std::uint32_t sum = seq;
  for (std::size_t i = 0; i < f.payload.size(); ++i) {
    f.payload[i] = seq * 2654435761u + static_cast<std::uint32_t>(i);
    sum = sum * 31u + f.payload[i];
  }
  f.checksum = sum;
  return f;
}

bool intact(const Frame& f) { return make_frame(f.sequence).checksum == f.checksum; }
}  // namespace

TEST_CASE("a full ring drops the new frame and counts it") {
  SpscRing<Frame, 4> ring;  // holds 3
  CHECK(ring.push(make_frame(0)) == Status::kOk);
  CHECK(ring.push(make_frame(1)) == Status::kOk);
  CHECK(ring.push(make_frame(2)) == Status::kOk);
  CHECK(ring.push(make_frame(3)) == Status::kBufferFull);
  CHECK(ring.dropped_frames() == 1);
  CHECK(ring.frames_pushed() == 3);
  // The three accepted frames come out in order, intact.
  for (std::uint32_t seq = 0; seq < 3; ++seq) {
    const Frame* f = ring.begin_read();
    REQUIRE(f != nullptr);
    CHECK(f->sequence == seq);
    CHECK(intact(*f));
    ring.end_read();
  }
  CHECK(ring.begin_read() == nullptr);
  CHECK(ring.frames_processed() == 3);
}

TEST_CASE("the slot being read is never handed to the producer") {
  SpscRing<Frame, 2> ring;  // holds 1
  CHECK(ring.push(make_frame(7)) == Status::kOk);
  const Frame* reading = ring.begin_read();
  REQUIRE(reading != nullptr);
  CHECK(ring.begin_write() == nullptr);  // full while the consumer holds the slot
  CHECK(reading->sequence == 7);
  ring.end_read();
  CHECK(ring.begin_write() != nullptr);
}

TEST_CASE("producer faster than consumer: every frame processed once or counted dropped") {
  static SpscRing<Frame, 8> ring;
  constexpr std::uint32_t kFrames = 20000;
  std::uint32_t accepted = 0;
  std::thread producer([&] {
    for (std::uint32_t seq = 0; seq < kFrames; ++seq) {
      if (ring.push(make_frame(seq)) == Status::kOk) ++accepted;
    }
  });
  std::uint32_t processed = 0;
  std::uint32_t torn = 0;
  std::uint32_t out_of_order = 0;
  std::int64_t last = -1;
  while (true) {
    const Frame* f = ring.begin_read();
    if (f == nullptr) {
      if (ring.frames_pushed() + ring.dropped_frames() == kFrames && ring.size() == 0) break;
      std::this_thread::yield();
      continue;
    }
    if (!intact(*f)) ++torn;
    if (static_cast<std::int64_t>(f->sequence) <= last) ++out_of_order;
    last = f->sequence;
    ++processed;
    ring.end_read();
  }
  producer.join();
  CHECK(torn == 0);
  CHECK(out_of_order == 0);
  CHECK(processed == accepted);
  CHECK(ring.frames_processed() + ring.dropped_frames() == kFrames);
}

TEST_CASE("consumer stall: the ring fills, the overflow is counted, the stored frames come out in order") {
  SpscRing<Frame, 8> ring;  // holds 7
  for (std::uint32_t seq = 0; seq < 100; ++seq) {
    const Status s = ring.push(make_frame(seq));
    CHECK(s == (seq < 7 ? Status::kOk : Status::kBufferFull));
  }
  CHECK(ring.frames_pushed() == 7);
  CHECK(ring.dropped_frames() == 93);
  for (std::uint32_t seq = 0; seq < 7; ++seq) {  // the stall ends
    const Frame* f = ring.begin_read();
    REQUIRE(f != nullptr);
    CHECK(f->sequence == seq);
    CHECK(intact(*f));
    ring.end_read();
  }
  CHECK(ring.begin_read() == nullptr);
  CHECK(ring.push(make_frame(100)) == Status::kOk);  // the producer is accepted again
  const Frame* f = ring.begin_read();
  REQUIRE(f != nullptr);
  CHECK(f->sequence == 100);
  ring.end_read();
  CHECK(ring.frames_processed() + ring.dropped_frames() == 101);
}

TEST_CASE("bursty producer, slow consumer: every frame processed once or counted dropped, none torn") {
  static SpscRing<Frame, 16> ring;
  constexpr std::uint32_t kBursts = 200;
  constexpr std::uint32_t kBurst = 24;  // longer than the ring: every burst overflows
  std::thread producer([&] {
    for (std::uint32_t b = 0; b < kBursts; ++b) {
      for (std::uint32_t i = 0; i < kBurst; ++i) static_cast<void>(ring.push(make_frame(b * kBurst + i)));
      std::this_thread::sleep_for(std::chrono::microseconds(300));
    }
  });
  std::uint32_t processed = 0, torn = 0, not_increasing = 0;
  std::int64_t last = -1;
  while (true) {
    const Frame* f = ring.begin_read();
    if (f == nullptr) {
      if (ring.frames_pushed() + ring.dropped_frames() == kBursts * kBurst && ring.size() == 0) break;
      std::this_thread::yield();
      continue;
    }
    if (!intact(*f)) ++torn;
    if (static_cast<std::int64_t>(f->sequence) <= last) ++not_increasing;  // twice or reordered
    last = f->sequence;
    ++processed;
    std::this_thread::sleep_for(std::chrono::microseconds(20));  // slow consumer
    ring.end_read();
  }
  producer.join();
  CHECK(torn == 0);
  CHECK(not_increasing == 0);
  CHECK(processed == ring.frames_pushed());
  CHECK(ring.dropped_frames() > 0);  // the bursts did overflow
  CHECK(ring.frames_processed() + ring.dropped_frames() == kBursts * kBurst);
}
