// CFAR over a whole line at constant cost per cell (the detector of cfar.h,
// every cell instead of one).
//
// Cfar::test() gathers the 2T training cells of one cell: O(T) per cell.
// cfar_line() slides the window along the line instead:
//   * CA / GO / SO keep the left and right training sums as integers. Each
//     cell is quantised once, q = trunc(x 2^s) with 2^s chosen from the
//     line's largest value so that 2T quantised cells fit in 62 bits, and
//     the window sums are updated by one add and one subtract per side.
//     Integer addition is associative, so the slid sum equals the sum
//     recomputed from scratch exactly, at every cell, on every target: no
//     drift (a float running sum accumulates a rounding error per update
//     and its value depends on the whole history of the line) and no
//     periodic re-summation. The cost is a quantisation step of
//     max(line) 2^-55 (cells 165 dB below the line's maximum count as 0).
//     The sum is then rounded once: noise = float(double(sum) 2^-s / n).
//     So CA/GO/SO noise can differ from Cfar::test() (a float sum in index
//     order) in the last bits; the detection rule is the same.
//   * OS: per cell two training values leave and two enter (one per side).
//     Windows of 2T > 64 cells are kept in two heaps split at rank k
//     (cfar_order_window.h): each replacement O(log T), the k-th smallest
//     is the root of the lower heap. Narrower windows are kept sorted: each
//     replacement counts the ranks of the leaving and entering values
//     (branch-free compares) and shifts only the cells between the two
//     ranks, O(T) but faster than the heaps' branches at that size
//     (kSortedWindowMax). Selection returns a value, so OS noise equals
//     Cfar::test()'s bit for bit either way.
//   * Cells without a full two-sided window (the first and last G + T of a
//     kShift line) use Cfar::gather_training() and the same sums (O(T) each,
//     a fixed 2(G + T) cells per line); kSkip leaves them untested; kWrap
//     slides with circular indices.
// Lines that contain a non-finite value fall back to Cfar::test() per cell.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "mptrack/frontend/cfar.h"
#include "mptrack/frontend/cfar_order_window.h"
#include "mptrack/validate.h"

namespace mptrack::frontend {

namespace cfar_line_detail {

/// Bits of the largest quantised cell: 2T <= 128 = 2^7 cells sum below 2^62.
constexpr int kQuantBits = 55;

/// Scale 2^s (double, exact) that maps the line's maximum below 2^kQuantBits.
inline double quant_scale(float max_value) {
  if (!(max_value > 0.0f)) return 1.0;
  int e = 0;
  (void)std::frexp(static_cast<double>(max_value), &e);  // max = m 2^e, m in [0.5, 1)
  return std::ldexp(1.0, kQuantBits - e);
}

inline std::int64_t quantise(float x, double scale) {
  return static_cast<std::int64_t>(static_cast<double>(x) * scale);
}

/// Replaces one occurrence of `out` by `in` in the ascending run w[0..n).
/// Both ranks are counted by branch-free compares over the run (one vector
/// pass; a binary search mispredicts about half of its branches on noise
/// and measured 3x slower at 2T = 64), then only the cells between the two
/// ranks move (memmove).
inline void sorted_replace(float* w, std::size_t n, float out, float in) {
  std::uint32_t lt_out = 0;  // cells below out; w[lt_out] == out (out is in the run)
  std::uint32_t lt_in = 0;
  for (std::size_t i = 0; i < n; ++i) {
    lt_out += static_cast<std::uint32_t>(w[i] < out);
    lt_in += static_cast<std::uint32_t>(w[i] < in);
  }
  if (in > out) {  // out counts among the cells below in
    const std::uint32_t to = lt_in - 1;
    std::memmove(w + lt_out, w + lt_out + 1, (to - lt_out) * sizeof(float));
    w[to] = in;
  } else {
    std::memmove(w + lt_in + 1, w + lt_in, (lt_out - lt_in) * sizeof(float));
    w[lt_in] = in;
  }
}

/// Widest OS window (2T cells) kept as a sorted run; wider ones use the
/// heaps of cfar_order_window.h. Measured per cell (bench cfar/line/os,
/// 65 535 cells, 2-core x86-64 host, bench/README.md issue 16 section): the
/// sorted run's vector rank count and short memmove beat the heaps'
/// data-dependent branches up to 2T = 64 (T = 32: 69 against 73-83 ns), the
/// heaps are ahead at 2T = 128 (81 against 92) and grow as log T where the
/// sorted run grows as T.
constexpr std::size_t kSortedWindowMax = 64;

}  // namespace cfar_line_detail

/// Runs `cfar` over every cell of line[0..len) into out[0..len); returns the
/// number of detections. len >= cfar.min_line_length() is the caller's
/// precondition (otherwise every cell is untested, as with test()).
/// Allocation-free: O(T) stack for the OS window (about 2.5 KB).
inline std::size_t cfar_line(const Cfar& cfar, const float* line, std::size_t len, CfarResult* out) {
  using namespace cfar_line_detail;
  for (std::size_t i = 0; i < len; ++i) out[i] = CfarResult{};
  if (!cfar.initialized() || len < cfar.min_line_length()) return 0;
  const CfarParams& p = cfar.params();
  const std::size_t g = p.guard_cells;
  const std::size_t t = p.training_cells;
  const std::size_t reach = g + t;
  float max_value = 0.0f;
  bool finite = true;
  for (std::size_t i = 0; i < len; ++i) {
    finite = finite && mptrack::is_finite(line[i]);
    max_value = line[i] > max_value ? line[i] : max_value;
  }
  std::size_t detections = 0;
  if (!finite) {
    for (std::size_t i = 0; i < len; ++i) {
      out[i] = cfar.test(line, len, i);
      detections += out[i].detected ? 1u : 0u;
    }
    return detections;
  }
  const double scale = quant_scale(max_value);
  const double inv_scale = 1.0 / scale;  // a power of two: exact
  const float alpha = cfar.alpha_f();
  const bool os = p.type == CfarType::kOrderedStatistic;
  const std::size_t os_k = p.os_rank - 1;
  // Noise from integer half sums (CA/GO/SO) or the k-th smallest (OS).
  auto noise_of = [&](std::int64_t sl, std::int64_t sr, float kth) -> float {
    if (os) return kth * cfar.os_norm();
    if (p.type == CfarType::kCellAveraging) {
      return static_cast<float>(static_cast<double>(sl + sr) * inv_scale / static_cast<double>(2 * t));
    }
    const double ml = static_cast<double>(sl) * inv_scale / static_cast<double>(t);
    const double mr = static_cast<double>(sr) * inv_scale / static_cast<double>(t);
    if (p.type == CfarType::kGreatestOf) return static_cast<float>(ml > mr ? ml : mr);
    return static_cast<float>(ml < mr ? ml : mr);
  };
  auto finish = [&](std::size_t i, float noise) {
    out[i].tested = true;
    out[i].noise = noise;
    out[i].detected = line[i] > alpha * noise;
    detections += out[i].detected ? 1u : 0u;
  };
  // Cells tested one by one (edges of a kShift line): gathered window.
  std::array<float, Cfar::kMaxTraining> cells;
  auto gathered = [&](std::size_t i) {
    const std::size_t n = cfar.gather_training(line, len, i, cells.data());
    if (n == 0) return;
    std::int64_t sl = 0;
    std::int64_t sr = 0;
    for (std::size_t k = 0; k < t; ++k) sl += quantise(cells[k], scale);
    for (std::size_t k = t; k < n; ++k) sr += quantise(cells[k], scale);
    if (os) std::nth_element(cells.data(), cells.data() + os_k, cells.data() + n);
    finish(i, noise_of(sl, sr, cells[os_k]));
  };
  const bool wrap = p.edge == CfarEdge::kWrap;
  // Slid cells: [first, last); circular indices for kWrap.
  const std::size_t first = wrap ? 0 : reach;
  const std::size_t last = wrap ? len : len - reach;
  for (std::size_t i = 0; i < first; ++i) gathered(i);
  if (first < last) {
    auto at = [&](std::size_t i, std::size_t plus, std::size_t minus) {
      std::size_t j = i + plus + len - minus;  // plus, minus <= reach <= len
      while (j >= len) j -= len;
      return line[j];
    };
    // Window of cell `first`: left [first - reach, first - g), right (first + g, first + reach].
    // OS cells are named by their unwrapped position + len (never negative).
    std::array<float, Cfar::kMaxTraining> cells0;
    std::array<std::size_t, Cfar::kMaxTraining> pos0;
    std::int64_t sl = 0;
    std::int64_t sr = 0;
    for (std::size_t k = 0; k < t; ++k) {
      cells0[k] = at(first, k, reach);
      cells0[t + k] = at(first, g + 1 + k, 0);
      pos0[k] = first + len + k - reach;
      pos0[t + k] = first + len + g + 1 + k;
      sl += quantise(cells0[k], scale);
      sr += quantise(cells0[t + k], scale);
    }
    const bool heaps = os && 2 * t > kSortedWindowMax;
    const bool sorted = os && !heaps;
    CfarOrderWindow window;
    if (heaps) window.reset(cells0.data(), pos0.data(), 2 * t, os_k + 1);
    if (sorted) std::sort(cells0.data(), cells0.data() + 2 * t);
    auto kth = [&]() { return heaps ? window.kth() : cells0[os_k]; };
    finish(first, noise_of(sl, sr, kth()));
    for (std::size_t i = first + 1; i < last; ++i) {
      const float l_out = at(i - 1, 0, reach);
      const float l_in = at(i - 1, 0, g);
      const float r_out = at(i - 1, g + 1, 0);
      const float r_in = at(i - 1, reach + 1, 0);
      sl += quantise(l_in, scale) - quantise(l_out, scale);
      sr += quantise(r_in, scale) - quantise(r_out, scale);
      if (heaps) {
        const std::size_t at_prev = i - 1 + len;  // unwrapped position of cell i - 1
        window.replace(at_prev - reach, at_prev - g, l_in);
        window.replace(at_prev + g + 1, at_prev + reach + 1, r_in);
      } else if (sorted) {
        sorted_replace(cells0.data(), 2 * t, l_out, l_in);
        sorted_replace(cells0.data(), 2 * t, r_out, r_in);
      }
      finish(i, noise_of(sl, sr, kth()));
    }
  }
  for (std::size_t i = last > first ? last : first; i < len; ++i) gathered(i);
  return detections;
}

}  // namespace mptrack::frontend
