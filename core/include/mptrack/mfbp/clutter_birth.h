// Grid seeding of clutter components (docs/algorithms/mfbp.md §Birth): measurements
// that uniform clutter explains are histogrammed on a polar grid; dense cells
// (count >= max(2 n_scans, factor mu_cell)) are merged with their
// 4-neighbours into seeds, and each seed becomes a Normal-Wishart component.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace mptrack::mfbp {

/// Fixed-size histogram grid plus connected-component labelling.
template <std::size_t MaxCells>
class SeedGrid {
 public:
  /// Sets up nr x na cells; false if they do not fit (caller coarsens).
  bool reset(std::size_t nr, std::size_t na) {
    if (nr == 0 || na == 0 || nr * na > MaxCells) return false;
    nr_ = nr;
    na_ = na;
    for (std::size_t c = 0; c < nr_ * na_; ++c) {
      count_[c] = 0;
      label_[c] = 0;
    }
    return true;
  }
  std::size_t cells() const { return nr_ * na_; }
  std::size_t cell_of(std::size_t ir, std::size_t ia) const { return ir * na_ + ia; }
  void add(std::size_t cell) {
    if (count_[cell] < 0xFFFFu) ++count_[cell];
  }
  std::uint16_t count(std::size_t cell) const { return count_[cell]; }

  /// Labels 4-connected groups of cells with count >= threshold as 1, 2, ...
  /// in raster order (deterministic). Returns the number of groups.
  std::size_t label_seeds(std::size_t threshold) {
    std::size_t groups = 0;
    for (std::size_t c = 0; c < nr_ * na_; ++c) {
      if (label_[c] != 0 || count_[c] < threshold) continue;
      ++groups;
      std::size_t top = 0;
      stack_[top++] = static_cast<std::uint16_t>(c);
      label_[c] = static_cast<std::uint16_t>(groups);
      while (top > 0) {
        const std::size_t cur = stack_[--top];
        const std::size_t ir = cur / na_, ia = cur % na_;
        const std::size_t nb[4] = {ir > 0 ? cur - na_ : cur, ir + 1 < nr_ ? cur + na_ : cur,
                                   ia > 0 ? cur - 1 : cur, ia + 1 < na_ ? cur + 1 : cur};
        for (std::size_t k = 0; k < 4; ++k) {
          const std::size_t n = nb[k];
          if (n == cur || label_[n] != 0 || count_[n] < threshold) continue;
          label_[n] = static_cast<std::uint16_t>(groups);
          stack_[top++] = static_cast<std::uint16_t>(n);
        }
      }
    }
    return groups;
  }
  std::uint16_t label(std::size_t cell) const { return label_[cell]; }

 private:
  std::size_t nr_ = 0, na_ = 0;
  std::array<std::uint16_t, MaxCells> count_{};
  std::array<std::uint16_t, MaxCells> label_{};
  std::array<std::uint16_t, MaxCells> stack_{};
};

}  // namespace mptrack::mfbp
