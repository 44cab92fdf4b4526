// Producer/consumer streaming; see stream_pipeline.h.
#include "stream/stream_pipeline.h"

#include <atomic>
#include <chrono>
#include <thread>

namespace mptrack::sim {

std::uint64_t stream_now_ns() {
  return static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
          .count());
}

template <class Frame>
StreamCounters run_stream(StreamRingT<Frame>& ring, std::uint32_t num_frames, const StreamOptions& opt,
                          const typename NonDeduced<FrameFillT<Frame>>::type& fill,
                          const typename NonDeduced<FrameConsumeT<Frame>>::type& consume) {
  std::atomic<bool> done{false};
  std::uint64_t offered = 0;
  std::uint64_t late = 0;
  std::thread producer([&] {
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    const bool paced = opt.rate_hz > 0.0;
    const double period_s = paced ? 1.0 / opt.rate_hz : 0.0;
    for (std::uint32_t k = 1; k <= num_frames; ++k) {
      if (paced) {
        const auto deadline = t0 + std::chrono::duration_cast<Clock::duration>(
                                       std::chrono::duration<double>(period_s * static_cast<double>(k - 1)));
        std::this_thread::sleep_until(deadline);
        if (Clock::now() - deadline > std::chrono::duration<double>(period_s)) ++late;
      } else {
        // Lossless: wait for a free slot before asking (begin_write on a
        // full ring would count a drop). Single producer: size() can only
        // shrink under us.
        while (ring.size() >= StreamRingT<Frame>::kCapacity) std::this_thread::sleep_for(std::chrono::microseconds(20));
      }
      ++offered;
      Frame* slot = ring.begin_write();
      if (slot == nullptr) continue;  // overrun: counted by the ring
      slot->frame = k;
      fill(k, *slot);
      slot->pushed_ns = stream_now_ns();
      ring.commit_write();
    }
    done.store(true, std::memory_order_release);
  });
  for (;;) {
    const Frame* f = ring.begin_read();
    if (f != nullptr) {
      const std::uint64_t now = stream_now_ns();
      consume(*f, now > f->pushed_ns ? now - f->pushed_ns : 0);
      ring.end_read();
      continue;
    }
    // Re-check after seeing `done`: the last commit happens before the store.
    if (done.load(std::memory_order_acquire) && ring.size() == 0) break;
    std::this_thread::sleep_for(std::chrono::microseconds(20));
  }
  producer.join();
  StreamCounters c;
  c.frames_offered = offered;
  c.frames_pushed = ring.frames_pushed();
  c.frames_processed = ring.frames_processed();
  c.dropped_frames = ring.dropped_frames();
  c.producer_late = late;
  return c;
}

template StreamCounters run_stream<StreamFrame>(StreamRing&, std::uint32_t, const StreamOptions&,
                                                const FrameFill&, const FrameConsume&);
template StreamCounters run_stream<StreamFrame16>(StreamRing16&, std::uint32_t, const StreamOptions&,
                                                  const FrameFillT<StreamFrame16>&,
                                                  const FrameConsumeT<StreamFrame16>&);

}  // namespace mptrack::sim
