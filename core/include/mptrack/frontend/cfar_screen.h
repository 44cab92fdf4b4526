// Threshold screen for the detector: the cells of one power-map line that
// can pass Cfar::test(), found at constant cost per cell, so that the
// local-maximum test and the exact CFAR test run only on those cells.
//
// The screen returns a superset: every cell that Cfar::test() detects is
// among its cells (a few more may be, they then fail the exact test), so
// the detections, their noise estimates and their order are those of
// testing every cell exactly.
//
// CA, GO, SO: each cell is quantised once, q = trunc(x 2^s), with 2^s chosen
// from the line's maximum so that a quantised cell is below 2^24 and 2T <= 128
// of them sum below 2^31; the training sums W are differences of a running
// (modular, uint32) sum, so each costs four loads whatever T. Truncation
// only lowers a cell, so W 2^-s <= the exact training sum S. Cfar::test()
// computes z = fl(fl(sum in index order) / n) and detects P > fl(alpha z);
// over n <= 128 non-negative terms the float sum is >= S (1 - 127 u), so
// fl(alpha z) >= alpha S/n (1 - 129 u), u = 2^-24 (Higham, Accuracy and
// Stability of Numerical Algorithms, 2nd ed., eq. (4.4); a sum whose terms
// quantise to W > 0 holds a term >= 2^-s, normal, so the bound applies).
// The screen keeps P > fl(float(W) k), k = fl(alpha/n (1 - 2^-12) 2^-s) a
// normal float: three more roundings, and the 2^-12 margin covers them and
// the 129 u, so every detected cell is kept. W = 0 keeps exactly the cells
// with P > 0, which every detected cell has. Cells far below the line's
// maximum quantise to 0 and lower W further: more cells kept, never fewer.
//   CA: n = 2T on the whole window.
//   GO: z = max(left mean, right mean) >= the whole-window mean: CA's bound.
//   SO: z = min(left mean, right mean): the smaller half sum with n = T.
// Halves and edges follow Cfar::gather_training(): the training cells are
// two runs in gather order, the first T of them form the left half.
//
// OS (a rank, no sum to bound cheaply), a line holding a negative or
// non-finite value, a maximum outside [2^-60, 2^60] or a factor k outside
// the normal floats: every cell in the range is kept, the exact tests decide
// as before.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>

#include "mptrack/frontend/cfar.h"

namespace mptrack::frontend {

template <std::size_t kLen>
class CfarScreen {
  static_assert(kLen >= 1 && kLen <= 65535, "cell indices are 16-bit");

 public:
  /// Bits of the largest quantised cell: 2T <= 2^7 cells sum below 2^31.
  static constexpr int kQuantBits = 24;
  /// Relative margin of the screen threshold below the exact one (header).
  static constexpr double kMargin = 1.0 / 4096.0;

  /// Screens cells [lo, hi) of line[0..kLen) for `cfar`; returns how many
  /// are kept (cells(), ascending). Precondition: cfar initialised with
  /// min_line_length() <= kLen (FrontEnd::validate), hi <= kLen.
  std::size_t run(const Cfar& cfar, const float* line, std::size_t lo, std::size_t hi) {
    count_ = 0;
    const CfarParams& p = cfar.params();
    if (p.type == CfarType::kOrderedStatistic || !cfar.initialized() ||
        kLen < cfar.min_line_length()) {
      return keep_all(lo, hi);
    }
    // Largest and smallest bit pattern: for floats >= +0 the patterns order
    // as the values; a negative value (sign bit) is below 0, Inf and NaN are
    // at or above 0x7f800000. Integer max/min vectorise.
    std::int32_t bmax = 0;
    std::int32_t bmin = 0;
    for (std::size_t i = 0; i < kLen; ++i) {
      std::int32_t b = 0;
      std::memcpy(&b, line + i, sizeof b);
      bmax = b > bmax ? b : bmax;
      bmin = b < bmin ? b : bmin;
    }
    if (bmin < 0 || bmax >= kInfBits) return keep_all(lo, hi);
    if (bmax == 0) return 0;  // every cell +0: no cell has power > 0, none can pass
    float max_value = 0.0f;
    std::memcpy(&max_value, &bmax, sizeof max_value);
    if (!(max_value >= 0x1p-60f && max_value <= 0x1p60f)) return keep_all(lo, hi);
    // max = m 2^e, m in [0.5, 1), from the (normal) bit pattern: no libm
    // call (nor its first-call symbol binding, which the stack test sees).
    const int e = static_cast<int>((static_cast<std::uint32_t>(bmax) >> 23) & 0xffu) - 126;
    const bool so = p.type == CfarType::kSmallestOf;
    const double n = static_cast<double>(so ? p.training_cells : 2 * p.training_cells);
    // Factor on W: alpha/n (1 - margin) 2^-s; normal float or no screen.
    const double kd = static_cast<double>(cfar.alpha_f()) / n * (1.0 - kMargin) * pow2(e - kQuantBits);
    if (!(kd >= static_cast<double>(kFloatMin) && kd <= static_cast<double>(kFloatMax))) return keep_all(lo, hi);
    const float k = static_cast<float>(kd);
    const float scale = static_cast<float>(pow2(kQuantBits - e));  // exact power of two, normal
    // Quantise (vectorises), then the running sum (one add per cell).
    for (std::size_t i = 0; i < kLen; ++i) {
      prefix_[i + 1] = static_cast<std::uint32_t>(static_cast<std::int32_t>(line[i] * scale));
    }
    prefix_[0] = 0;
    for (std::size_t i = 1; i <= kLen; ++i) prefix_[i] += prefix_[i - 1];
    const std::size_t reach = p.guard_cells + p.training_cells;
    const std::size_t first = lo > reach ? lo : reach;  // interior cells: [first, last)
    const std::size_t last = hi < kLen - reach ? hi : kLen - reach;
    if (so) {
      interior_flags<true>(line, first, last, k, p);
    } else {
      interior_flags<false>(line, first, last, k, p);
    }
    const std::size_t edge_lo_end = first < hi ? first : hi;  // [lo, edge_lo_end): lower edge
    for (std::size_t i = lo; i < edge_lo_end; ++i) flags_[i] = edge_flag(line, i, k, p, so);
    for (std::size_t i = (last > edge_lo_end ? last : edge_lo_end); i < hi; ++i) {
      flags_[i] = edge_flag(line, i, k, p, so);
    }
    collect(lo, hi);
    return count_;
  }

  std::size_t size() const { return count_; }
  const std::uint16_t* cells() const { return cells_.data(); }

 private:
  static constexpr float kFloatMax = std::numeric_limits<float>::max();
  static constexpr float kFloatMin = std::numeric_limits<float>::min();  ///< smallest normal
  static constexpr std::int32_t kInfBits = 0x7f800000;                   ///< bit pattern of +Inf

  /// 2^k as a double, exact, for |k| <= 1000 (here |k| <= 90).
  static double pow2(int k) {
    const std::uint64_t bits = static_cast<std::uint64_t>(k + 1023) << 52;
    double x = 0.0;
    std::memcpy(&x, &bits, sizeof x);
    return x;
  }

  std::size_t keep_all(std::size_t lo, std::size_t hi) {
    for (std::size_t i = lo; i < hi; ++i) cells_[count_++] = static_cast<std::uint16_t>(i);
    return count_;
  }

  // Kept cells in ascending order. Flags are read eight at a time: on noise
  // nearly every word is zero, so the per-cell branch runs only near targets.
  void collect(std::size_t lo, std::size_t hi) {
    std::size_t i = lo;
    for (; i + 8 <= hi; i += 8) {
      std::uint64_t word = 0;
      std::memcpy(&word, flags_.data() + i, sizeof word);
      if (word == 0) continue;
      for (std::size_t j = i; j < i + 8; ++j) {
        if (flags_[j] != 0) cells_[count_++] = static_cast<std::uint16_t>(j);
      }
    }
    for (; i < hi; ++i) {
      if (flags_[i] != 0) cells_[count_++] = static_cast<std::uint16_t>(i);
    }
  }

  /// Sum of the quantised cells [a, a + n) (indices taken mod kLen).
  std::uint32_t run_sum(std::size_t a, std::size_t n) const {
    if (a + n <= kLen) return prefix_[a + n] - prefix_[a];
    return (prefix_[kLen] - prefix_[a]) + prefix_[a + n - kLen];
  }

  // Interior cells (both runs inside the line, unwrapped), the bulk of the
  // line: two runs at fixed offsets, straight-line arithmetic that vectorises.
  template <bool kSo>
  void interior_flags(const float* line, std::size_t first, std::size_t last, float k, const CfarParams& p) {
    const std::size_t g = p.guard_cells;
    const std::size_t reach = g + p.training_cells;
    const std::uint32_t* q = prefix_.data();
    for (std::size_t i = first; i < last; ++i) {
      const std::uint32_t wl = q[i - g] - q[i - reach];
      const std::uint32_t wr = q[i + reach + 1] - q[i + g + 1];
      std::uint32_t w = wl + wr;
      if constexpr (kSo) w = wl < wr ? wl : wr;
      flags_[i] = static_cast<std::uint8_t>(line[i] > static_cast<float>(static_cast<std::int32_t>(w)) * k);
    }
  }

  // A cell within G + T of an end: its two runs as Cfar::gather_training()
  // takes them (kShift: the deficit moves to the other side; kWrap:
  // circular; kSkip: untested, never detected).
  std::uint8_t edge_flag(const float* line, std::size_t i, float k, const CfarParams& p, bool so) const {
    const std::size_t g = p.guard_cells;
    const std::size_t t = p.training_cells;
    const std::size_t reach = g + t;
    std::size_t a = 0;  // run 1 [a, a + na), then run 2 [c, c + nc), gather order
    std::size_t na = 0;
    std::size_t c = 0;
    std::size_t nc = 0;
    if (p.edge == CfarEdge::kWrap) {
      a = (i + kLen - reach) % kLen;
      na = t;
      c = (i + g + 1) % kLen;
      nc = t;
    } else if (p.edge == CfarEdge::kSkip) {
      return 0;
    } else if (i < reach) {
      const std::size_t have = i > g ? i - g : 0;
      a = have > t ? have - t : 0;
      na = have - a;
      c = i + g + 1;
      nc = 2 * t - na;
    } else {
      c = i + g + 1;
      const std::size_t have = c < kLen ? kLen - c : 0;
      nc = have < t ? have : t;
      na = 2 * t - nc;
      a = i - g - na;
    }
    std::uint32_t w = 0;
    if (!so) {
      w = run_sum(a, na) + (nc > 0 ? run_sum(c, nc) : 0u);
    } else {
      // First T cells of the gather order (left half) against the rest.
      const std::size_t from_c = na >= t ? 0 : t - na;
      const std::uint32_t wl = run_sum(a, na < t ? na : t) + (from_c > 0 ? run_sum(c, from_c) : 0u);
      const std::uint32_t wr = (na > t ? run_sum(a + t, na - t) : 0u) +
                               (nc > from_c ? run_sum(c + from_c, nc - from_c) : 0u);
      w = wl < wr ? wl : wr;
    }
    return static_cast<std::uint8_t>(line[i] > static_cast<float>(static_cast<std::int32_t>(w)) * k);
  }

  std::array<std::uint32_t, kLen + 1> prefix_{};  ///< running sums of the quantised cells (mod 2^32)
  std::array<std::uint8_t, kLen> flags_{};        ///< 1: cell kept
  std::array<std::uint16_t, kLen> cells_{};       ///< kept cells, ascending
  std::size_t count_ = 0;
};

}  // namespace mptrack::frontend
