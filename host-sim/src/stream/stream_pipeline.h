// Producer/consumer streaming of raw ADC frames through the platform ring
// buffer (platform/spsc_ring.h), as on the board: the producer stands in for
// the ADC DMA-complete interrupt, the consumer is the processing loop.
//
//   producer thread                         consumer (calling thread)
//     wait for frame k's deadline             f = ring.begin_read()
//     slot = ring.begin_write()               consume(*f, queue wait)
//     slot ? fill + commit : dropped          ring.end_read()
//
// Pacing: rate_hz > 0 releases frame k at t0 + k / rate_hz and drops it
// (counted by the ring) if every slot is full, exactly the board's overrun
// policy. rate_hz == 0 is lossless back-pressure: the producer waits for a
// free slot, so the pipeline runs as fast as the consumer (Monte Carlo
// accuracy runs). Invariant after run_stream(): offered = processed + dropped
// and pushed = processed.
#pragma once

#include <cstdint>
#include <functional>

#include "mptrack/adc/adc_model.h"
#include "mptrack/adc/synthesizer.h"
#include "mptrack/platform/spsc_ring.h"

namespace mptrack::sim {

/// One ring slot: a raw frame plus bookkeeping. Cube is the float cube
/// (volts, no ADC model) or the int16 cube of ADC codes (adc/adc_model.h),
/// what a board's ring carries.
template <class Cube>
struct StreamFrameT {
  std::uint32_t frame = 0;       ///< 1-based frame number
  std::uint64_t pushed_ns = 0;   ///< steady-clock stamp at commit [ns]
  Cube cube;
};
using StreamFrame = StreamFrameT<adc::AdcCube>;
using StreamFrame16 = StreamFrameT<adc::AdcCube16>;

inline constexpr std::size_t kStreamSlots = 8;  ///< 7 frames in flight (~130 KiB float, ~65 KiB int16)
template <class Frame>
using StreamRingT = platform::SpscRing<Frame, kStreamSlots>;
using StreamRing = StreamRingT<StreamFrame>;
using StreamRing16 = StreamRingT<StreamFrame16>;

struct StreamOptions {
  double rate_hz = 0.0;          ///< frame rate [Hz]; 0 = lossless, as fast as consumed
};

struct StreamCounters {
  std::uint64_t frames_offered = 0;    ///< frames the producer tried to push
  std::uint64_t frames_pushed = 0;     ///< accepted by the ring
  std::uint64_t frames_processed = 0;  ///< read and released by the consumer
  std::uint64_t dropped_frames = 0;    ///< refused by a full ring (overrun)
  std::uint64_t producer_late = 0;     ///< frames released after their deadline + 1 period
};

/// Fills slot.cube (and nothing else) for frame number `frame`.
template <class Frame>
using FrameFillT = std::function<void(std::uint32_t frame, Frame& slot)>;
/// Processes one frame; queue_ns = time it waited in the ring [ns].
template <class Frame>
using FrameConsumeT = std::function<void(const Frame& frame, std::uint64_t queue_ns)>;
using FrameFill = FrameFillT<StreamFrame>;
using FrameConsume = FrameConsumeT<StreamFrame>;

/// Keeps a parameter out of template argument deduction (std::type_identity, C++20).
template <class T>
struct NonDeduced {
  using type = T;
};

/// Streams frames 1..num_frames from fill (producer thread) to consume
/// (calling thread) through `ring` (which must be fresh: counters at 0).
/// Instantiated for StreamFrame and StreamFrame16.
template <class Frame>
StreamCounters run_stream(StreamRingT<Frame>& ring, std::uint32_t num_frames, const StreamOptions& opt,
                          const typename NonDeduced<FrameFillT<Frame>>::type& fill,
                          const typename NonDeduced<FrameConsumeT<Frame>>::type& consume);

/// Monotonic nanoseconds (steady_clock).
std::uint64_t stream_now_ns();

}  // namespace mptrack::sim
