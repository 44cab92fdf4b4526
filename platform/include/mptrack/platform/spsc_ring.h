// Lock-free single-producer single-consumer ring of fixed-size frames.
//
// The producer is a DMA-complete ISR (or, on the host, a producer thread);
// the consumer is the processing loop. Slots are written in place, so a
// frame of hundreds of KiB is never copied through the queue:
//
//   producer (ISR):                     consumer (main loop):
//     Frame* f = ring.begin_write();      const Frame* f = ring.begin_read();
//     if (f) { fill(*f); ring.commit_write(); }   if (f) { process(*f); ring.end_read(); }
//     else   { /* counted as dropped */ }
//
// Overrun policy: when every slot is full the *new* frame is dropped and
// counted (dropped_frames()); a slot the consumer is reading is never
// overwritten and nothing already accepted is lost. One slot is kept free
// to tell full from empty without a shared count, so the ring holds
// kSlots - 1 frames.
//
// Indices are 32-bit atomics with acquire/release ordering: lock-free on
// x86-64, aarch64, armv7-A and Cortex-M7 (ldrex/strex), no OS needed.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>

#include "mptrack/status.h"

namespace mptrack::platform {

template <class Frame, std::size_t kSlots>
class SpscRing {
  static_assert(kSlots >= 2, "an SPSC ring needs at least 2 slots (one is kept free)");
  static_assert((kSlots & (kSlots - 1)) == 0, "kSlots must be a power of two (cheap wrap)");
  static_assert(std::atomic<std::uint32_t>::is_always_lock_free, "needs lock-free 32-bit atomics");

 public:
  static constexpr std::size_t kCapacity = kSlots - 1;  ///< frames held at most

  // ---- producer side (one thread / ISR only) ----

  /// Slot to fill, or nullptr when full (the frame is then counted as dropped).
  Frame* begin_write() {
    const std::uint32_t head = head_.load(std::memory_order_relaxed);
    const std::uint32_t tail = tail_.load(std::memory_order_acquire);
    if (head - tail >= kCapacity) {
      dropped_.fetch_add(1, std::memory_order_relaxed);
      return nullptr;
    }
    return &slots_[head & kMask];
  }

  /// Publishes the slot returned by the last successful begin_write().
  void commit_write() {
    const std::uint32_t head = head_.load(std::memory_order_relaxed);
    head_.store(head + 1, std::memory_order_release);
    pushed_.fetch_add(1, std::memory_order_relaxed);
  }

  /// Copying convenience: kBufferFull (and a dropped frame counted) when full.
  Status push(const Frame& frame) {
    Frame* slot = begin_write();
    if (slot == nullptr) return Status::kBufferFull;
    *slot = frame;
    commit_write();
    return Status::kOk;
  }

  // ---- consumer side (one thread only) ----

  /// Oldest unread frame, or nullptr when empty. Stays valid until end_read().
  const Frame* begin_read() const {
    const std::uint32_t tail = tail_.load(std::memory_order_relaxed);
    const std::uint32_t head = head_.load(std::memory_order_acquire);
    if (head == tail) return nullptr;
    return &slots_[tail & kMask];
  }

  /// Releases the frame returned by begin_read() back to the producer.
  void end_read() {
    const std::uint32_t tail = tail_.load(std::memory_order_relaxed);
    tail_.store(tail + 1, std::memory_order_release);
    processed_.fetch_add(1, std::memory_order_relaxed);
  }

  // ---- counters (any thread; relaxed snapshots) ----
  std::uint32_t frames_pushed() const { return pushed_.load(std::memory_order_relaxed); }
  std::uint32_t frames_processed() const { return processed_.load(std::memory_order_relaxed); }
  std::uint32_t dropped_frames() const { return dropped_.load(std::memory_order_relaxed); }
  /// Frames waiting to be read.
  std::uint32_t size() const {
    return head_.load(std::memory_order_acquire) - tail_.load(std::memory_order_acquire);
  }

 private:
  static constexpr std::uint32_t kMask = static_cast<std::uint32_t>(kSlots - 1);

  // Producer and consumer indices on separate cache lines (no false sharing).
  alignas(64) std::atomic<std::uint32_t> head_{0};  ///< next slot to write (free-running)
  alignas(64) std::atomic<std::uint32_t> tail_{0};  ///< next slot to read (free-running)
  alignas(64) std::atomic<std::uint32_t> pushed_{0};
  std::atomic<std::uint32_t> processed_{0};
  std::atomic<std::uint32_t> dropped_{0};
  std::array<Frame, kSlots> slots_{};
};

}  // namespace mptrack::platform
