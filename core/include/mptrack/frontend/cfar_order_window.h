// Sliding order statistic for OS-CFAR along a line (used by cfar_line.h).
//
// The 2T training cells of the window are split into two binary heaps in
// fixed arrays: `lo_` holds the k smallest (max-heap, its root is the k-th
// smallest x_(k), the OS-CFAR statistic of cfar.h) and `hi_` the other 2T - k
// (min-heap), with max(lo_) <= min(hi_). Sliding the window by one cell
// replaces one cell by another (twice per shift: one per side): the leaving
// cell's heap node takes the entering value and is sifted (O(log T)); if the
// two roots are then out of order they are exchanged and both sifted down
// (one exchange restores max(lo_) <= min(hi_): only the replaced value can
// be on the wrong side). So each shift costs O(log T) compares and moves
// instead of the O(T) shift of a sorted window.
//
// Cells are identified by their position along the (unwrapped) line: a slot
// table indexed by position mod kSlots gives each cell's heap and node. The
// window spans 2(G + T) + 1 <= 257 consecutive positions, so positions of
// cells in the window never share a slot.
//
// The statistic is a value of the window (a selection, no arithmetic), so
// it equals std::nth_element's k-th smallest in Cfar::test() bit for bit,
// whatever the ties. Values must not be NaN (cfar_line screens lines with a
// non-finite value out before).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

namespace mptrack::frontend {

class CfarOrderWindow {
 public:
  /// Training cells at most (2 x CfarParams::training_cells <= 128).
  static constexpr std::size_t kCapacity = 128;
  /// Slot table size: a power of two above the widest window, 2 (64 + 64) + 1.
  static constexpr std::size_t kSlots = 512;

  /// Fills the window with values[0..n) at line positions pos[0..n) and
  /// selects rank k (1-based, 1 <= k <= n <= kCapacity): O(n log n).
  void reset(const float* values, const std::size_t* pos, std::size_t n, std::size_t k) {
    std::array<std::uint16_t, kCapacity> order{};
    for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<std::uint16_t>(i);
    std::sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(n),
              [values](std::uint16_t a, std::uint16_t b) { return values[a] < values[b]; });
    n_lo_ = k;
    n_hi_ = n - k;
    // A descending run is a max-heap, an ascending run a min-heap.
    for (std::size_t i = 0; i < k; ++i) set(kLo, i, values[order[k - 1 - i]], slot_of(pos[order[k - 1 - i]]));
    for (std::size_t i = 0; i < n_hi_; ++i) set(kHi, i, values[order[k + i]], slot_of(pos[order[k + i]]));
  }

  /// The cell at line position out_pos leaves, the cell in_pos (value x)
  /// enters. out_pos must be in the window, in_pos not.
  void replace(std::size_t out_pos, std::size_t in_pos, float x) {
    const std::uint8_t code = where_[slot_of(out_pos)];
    const std::size_t h = code >> 7;
    const std::size_t i = code & 0x7fu;
    const float old = val_[h][i];
    set(h, i, x, slot_of(in_pos));
    if (h == kLo) {
      if (x > old) {
        sift_up<kLo>(i);
      } else {
        sift_down<kLo>(i, n_lo_);
      }
    } else if (x < old) {
      sift_up<kHi>(i);
    } else {
      sift_down<kHi>(i, n_hi_);
    }
    if (n_hi_ > 0 && val_[kLo][0] > val_[kHi][0]) {
      const float lo_v = val_[kLo][0];
      const std::uint16_t lo_s = slot_[kLo][0];
      set(kLo, 0, val_[kHi][0], slot_[kHi][0]);
      set(kHi, 0, lo_v, lo_s);
      sift_down<kLo>(0, n_lo_);
      sift_down<kHi>(0, n_hi_);
    }
  }

  /// The k-th smallest value of the window.
  float kth() const { return val_[kLo][0]; }

 private:
  static constexpr std::size_t kLo = 0;  ///< max-heap of the k smallest
  static constexpr std::size_t kHi = 1;  ///< min-heap of the rest

  static std::uint16_t slot_of(std::size_t pos) { return static_cast<std::uint16_t>(pos & (kSlots - 1)); }

  void set(std::size_t h, std::size_t i, float x, std::uint16_t slot) {
    val_[h][i] = x;
    slot_[h][i] = slot;
    where_[slot] = static_cast<std::uint8_t>((h << 7) | i);
  }

  // Heap order: parent before child, `before` strict (ties stay put).
  template <std::size_t H>
  static bool before(float a, float b) {
    if constexpr (H == kLo) {
      return a > b;
    } else {
      return a < b;
    }
  }

  template <std::size_t H>
  void sift_up(std::size_t i) {
    const float x = val_[H][i];
    const std::uint16_t s = slot_[H][i];
    while (i > 0) {
      const std::size_t parent = (i - 1) / 2;
      if (!before<H>(x, val_[H][parent])) break;
      set(H, i, val_[H][parent], slot_[H][parent]);
      i = parent;
    }
    set(H, i, x, s);
  }

  template <std::size_t H>
  void sift_down(std::size_t i, std::size_t n) {
    const float x = val_[H][i];
    const std::uint16_t s = slot_[H][i];
    for (;;) {
      std::size_t child = 2 * i + 1;
      if (child >= n) break;
      if (child + 1 < n && before<H>(val_[H][child + 1], val_[H][child])) ++child;
      if (!before<H>(val_[H][child], x)) break;
      set(H, i, val_[H][child], slot_[H][child]);
      i = child;
    }
    set(H, i, x, s);
  }

  std::array<std::array<float, kCapacity>, 2> val_{};
  std::array<std::array<std::uint16_t, kCapacity>, 2> slot_{};
  std::array<std::uint8_t, kSlots> where_{};  ///< heap << 7 | node of the cell in each slot
  std::size_t n_lo_ = 0;
  std::size_t n_hi_ = 0;
};

}  // namespace mptrack::frontend
