// DBSCAN on the range-Doppler detection grid (seed 003 Sec. III-A step 3,
// Ester et al. 1996) with a Chebyshev neighbourhood of half-widths
// (eps_range, eps_doppler) bins. On a grid DBSCAN needs no distance search:
// a detected cell is a core cell if at least min_points detected cells
// (itself included) lie in its neighbourhood; clusters are the connected
// sets of core cells plus the non-core detections next to them (border
// cells, given to the first cluster that reaches them in scan order).
// Why eps = 1 bin by default (docs/algorithms/sea_clutter.md §Clustering):
// with P_FA = 0.28 per cell, a 3 x 3 neighbourhood keeps independent false
// alarms below the site-percolation threshold of the 8-connected square
// lattice (0.407), so clutter clusters stay small; wider neighbourhoods
// (the paper's 45 m / 0.3 Hz are 3 bins each in its 0.1 Hz grid) merge a
// 28 % detection density into one grid-wide cluster.
//
// Allocation-free: labels live in a fixed grid, the flood fill uses a
// fixed stack of Caps::kMaxClusterCells cells (overflow: the cluster stops
// growing, later cells start new clusters; reported as overflowed()).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace mptrack::seaclutter {

/// Running sums of one cluster while it is flood-filled.
struct ClusterSums {
  float weight = 0.0f;       ///< sum of amplitudes sqrt(P)
  float range_sum = 0.0f;    ///< sum of amplitude * range bin
  float doppler_sum = 0.0f;  ///< sum of amplitude * Doppler bin
  float peak_power = 0.0f;
  std::uint16_t peak_range = 0;
  std::uint16_t peak_doppler = 0;
  std::uint32_t cells = 0;
};

template <class Caps>
class GridDbscan {
 public:
  static constexpr std::size_t kRange = Caps::kRangeBins;
  static constexpr std::size_t kDoppler = Caps::kDopplerBins;
  static constexpr std::int16_t kEmpty = -2;   ///< not detected
  static constexpr std::int16_t kBorder = -1;  ///< detected, not core, not yet in a cluster
  static constexpr std::int16_t kCore = 0;     ///< core, not yet in a cluster

  void configure(std::size_t eps_range, std::size_t eps_doppler, std::size_t min_points) {
    eps_r_ = eps_range;
    eps_d_ = eps_doppler;
    min_points_ = min_points;
  }

  /// Starts a new scan: no detections.
  void clear() {
    for (auto& row : label_) row.fill(kEmpty);
    next_id_ = 1;
    overflowed_ = false;
  }
  void mark_detection(std::size_t m, std::size_t d) { label_[m][d] = kBorder; }
  bool detected(std::size_t m, std::size_t d) const { return label_[m][d] != kEmpty; }

  /// Marks the core cells; call once after every mark_detection(). Marking
  /// a cell core keeps it "detected", so the counts of later cells are the same.
  void find_core_cells() {
    for (std::size_t m = 0; m < kRange; ++m) {
      for (std::size_t d = 0; d < kDoppler; ++d) {
        if (label_[m][d] == kEmpty) continue;
        std::size_t count = 0;
        for_neighbours(m, d, [&](std::size_t mm, std::size_t dd) { count += label_[mm][dd] != kEmpty; });
        if (count >= min_points_) label_[m][d] = kCore;
      }
    }
  }

  /// Grows the next cluster from the next unvisited core cell at or after
  /// *cursor (row-major); false when none is left. `power(m, d)` gives the map.
  template <class Power>
  bool next_cluster(std::size_t* cursor, const Power& power, ClusterSums& sums) {
    std::size_t c = *cursor;
    while (c < kRange * kDoppler && label_[c / kDoppler][c % kDoppler] != kCore) ++c;
    *cursor = c;
    if (c >= kRange * kDoppler) return false;
    const std::int16_t id = next_id_;
    if (next_id_ < 32767) ++next_id_;
    sums = ClusterSums{};
    std::size_t top = 0;
    take(c / kDoppler, c % kDoppler, id, power, sums);
    stack_[top++] = static_cast<std::uint32_t>(c);
    while (top > 0) {
      const std::uint32_t cell = stack_[--top];
      for_neighbours(cell / kDoppler, cell % kDoppler, [&](std::size_t mm, std::size_t dd) {
        const std::int16_t l = label_[mm][dd];
        if (l == kBorder) {
          take(mm, dd, id, power, sums);  // border: joins, does not expand
        } else if (l == kCore) {
          if (top < stack_.size()) {
            take(mm, dd, id, power, sums);
            stack_[top++] = static_cast<std::uint32_t>(mm * kDoppler + dd);
          } else {
            overflowed_ = true;  // left for a later cluster
          }
        }
      });
    }
    return true;
  }

  bool overflowed() const { return overflowed_; }

 private:
  template <class F>
  void for_neighbours(std::size_t m, std::size_t d, const F& f) const {
    const std::size_t m0 = m >= eps_r_ ? m - eps_r_ : 0;
    const std::size_t m1 = m + eps_r_ < kRange ? m + eps_r_ : kRange - 1;
    const std::size_t d0 = d >= eps_d_ ? d - eps_d_ : 0;
    const std::size_t d1 = d + eps_d_ < kDoppler ? d + eps_d_ : kDoppler - 1;
    for (std::size_t mm = m0; mm <= m1; ++mm) {
      for (std::size_t dd = d0; dd <= d1; ++dd) f(mm, dd);
    }
  }

  template <class Power>
  void take(std::size_t m, std::size_t d, std::int16_t id, const Power& power, ClusterSums& s) {
    label_[m][d] = id;
    const float p = power(m, d);
    const float a = std::sqrt(p);
    s.weight += a;
    s.range_sum += a * static_cast<float>(m);
    s.doppler_sum += a * static_cast<float>(d);
    ++s.cells;
    if (p > s.peak_power || s.cells == 1) {
      s.peak_power = p;
      s.peak_range = static_cast<std::uint16_t>(m);
      s.peak_doppler = static_cast<std::uint16_t>(d);
    }
  }

  std::array<std::array<std::int16_t, kDoppler>, kRange> label_{};
  std::array<std::uint32_t, Caps::kMaxClusterCells> stack_{};
  std::size_t eps_r_ = 1;
  std::size_t eps_d_ = 1;
  std::size_t min_points_ = 5;
  std::int16_t next_id_ = 1;
  bool overflowed_ = false;
};

}  // namespace mptrack::seaclutter
