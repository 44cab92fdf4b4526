// Bounded list of detection candidates, strongest first.
//
// Overflow policy (issue: "keep the strongest, count the rest"): inserting
// into a full list drops the weakest entry (which may be the new one) and
// counts it. Order is total and deterministic: power descending, then cell
// index ascending, so equal powers never depend on insertion order.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace mptrack::frontend {

/// One local maximum that passed CFAR.
struct PeakCandidate {
  std::uint32_t cell = 0;    ///< power-map linear index (tie-breaker)
  std::uint16_t range_bin = 0;
  std::uint16_t doppler_bin = 0;
  std::uint16_t angle_bin = 0;
  float power = 0.0f;        ///< map power at the cell
  float noise = 0.0f;        ///< CFAR noise estimate (map units)
};

/// True if a ranks before b.
inline bool stronger(const PeakCandidate& a, const PeakCandidate& b) {
  if (a.power != b.power) return a.power > b.power;
  return a.cell < b.cell;
}

template <std::size_t N>
class PeakList {
  static_assert(N >= 1, "PeakList needs capacity >= 1");

 public:
  /// Sets the active capacity (<= N) and empties the list.
  void reset(std::size_t limit) {
    limit_ = limit < N ? limit : N;
    size_ = 0;
    dropped_ = 0;
  }

  /// Insertion into the sorted array: O(limit) per call.
  void insert(const PeakCandidate& c) {
    if (limit_ == 0) {
      ++dropped_;
      return;
    }
    if (size_ == limit_) {
      if (!stronger(c, items_[size_ - 1])) {
        ++dropped_;
        return;
      }
      --size_;  // evict the weakest
      ++dropped_;
    }
    std::size_t pos = size_;
    while (pos > 0 && stronger(c, items_[pos - 1])) {
      items_[pos] = items_[pos - 1];
      --pos;
    }
    items_[pos] = c;
    ++size_;
  }

  std::size_t size() const { return size_; }
  const PeakCandidate& operator[](std::size_t i) const { return items_[i]; }
  /// Candidates dropped by the cap since reset() [count].
  std::size_t dropped() const { return dropped_; }

 private:
  std::array<PeakCandidate, N> items_{};
  std::size_t size_ = 0;
  std::size_t limit_ = N;
  std::size_t dropped_ = 0;
};

}  // namespace mptrack::frontend
