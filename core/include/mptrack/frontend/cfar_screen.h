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
// of them sum below 2^31. An interior cell's two half sums are box sums of
// T cells, built for the whole line by doubling (log2 T vector passes, two
// loads a cell each, at most 6), two loads per cell; an edge cell, within
// G + T of an end, takes its runs as differences of a running (modular,
// uint32) sum over the two edge regions: for CA and GO under kShift (the
// default) in closed form, three loads in cell order (shift_lower_edge),
// otherwise up to six loads for CA and GO, twelve for SO, from segment
// tables planned once per parameter set (docs/algorithms/frontend.md
// §Peaks, "Threshold first"). Exact integers either way. On x86-64 hosts it runs compiled for AVX2 or AVX-512 where
// the CPU has them (run_copy; the same cells). Truncation
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

#include "mptrack/dsp/fft_config.h"
#include "mptrack/frontend/cfar.h"
#include "mptrack/frontend/cfar_shift_edges_avx512.h"

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
  /// Runs the widest copy this CPU has (run_copy).
  std::size_t run(const Cfar& cfar, const float* line, std::size_t lo, std::size_t hi) {
    return run_copy(dsp::widest_fft_copy(), cfar, line, lo, hi);
  }

  /// The screen compiled for one ISA: on x86-64 hosts, the FFT's copies
  /// (dsp/fft_config.h: baseline SSE2, AVX2, AVX-512, never FMA). Integer
  /// sums and one float product and compare per cell, so every copy keeps
  /// the same cells (tests/unit/cfar_screen_test.cpp). A copy this build or
  /// CPU lacks falls back to the baseline.
  std::size_t run_copy(dsp::FftCopy copy, const Cfar& cfar, const float* line, std::size_t lo,
                       std::size_t hi) {
#if MPTRACK_FFT_X86_DISPATCH
    if (dsp::fft_copy_available(copy)) {
      if (copy == dsp::FftCopy::kAvx512) return run_avx512(cfar, line, lo, hi);
      if (copy == dsp::FftCopy::kAvx2) return run_avx2(cfar, line, lo, hi);
    }
#else
    static_cast<void>(copy);
#endif
    return screen<dsp::FftCopy::kBaseline>(cfar, line, lo, hi);
  }

  std::size_t size() const { return count_; }
  const std::uint16_t* cells() const { return cells_.data(); }

  /// Tests only: true routes CA and GO under kShift through the planned
  /// segment tables too, instead of their closed-form edge sums.
  void set_planned_edges_only(bool on) { planned_only_ = on; }

 private:
#if MPTRACK_FFT_X86_DISPATCH
  __attribute__((target("avx2"), noinline)) std::size_t run_avx2(const Cfar& cfar,
                                                                 const float* line, std::size_t lo,
                                                                 std::size_t hi) {
    return screen<dsp::FftCopy::kAvx2>(cfar, line, lo, hi);
  }
  __attribute__((target("avx512f,avx512vl,prefer-vector-width=512"), noinline)) std::size_t
  run_avx512(const Cfar& cfar, const float* line, std::size_t lo, std::size_t hi) {
    const std::size_t n = screen<dsp::FftCopy::kAvx512>(cfar, line, lo, hi);
    if (!shift_pending_) return n;
    // The closed-form kShift edges, here where the AVX-512 target applies
    // (cfar_shift_edges_avx512.h), then the collection screen() left.
    shift_pending_ = false;
    const CfarParams& p = cfar.params();
    const cfar_detail::ShiftEdgeGeometry geo{prefix_.data(), kLen, p.guard_cells, p.training_cells};
    cfar_detail::shift_lower_edge_avx512(geo, line, flags_.data(), lo, shift_lo_end_, shift_k_);
    cfar_detail::shift_upper_edge_avx512(geo, line, flags_.data(), shift_hi_begin_, hi, shift_k_);
    collect(lo, hi);
    return count_;
  }
#endif

  // The screen itself; every helper is force-inlined (MPTRACK_FFT_INLINE), so
  // each copy compiles all of it for its own ISA.
  template <dsp::FftCopy kCopy>
  MPTRACK_FFT_INLINE std::size_t screen(const Cfar& cfar, const float* line, std::size_t lo,
                                        std::size_t hi) {
    count_ = 0;
    const CfarParams& p = cfar.params();
    if (p.type == CfarType::kOrderedStatistic || !cfar.initialized() ||
        kLen < cfar.min_line_length()) {
      return keep_all(lo, hi);
    }
    // Largest bit pattern and any sign bit: for floats >= +0 the patterns order
    // as the values; a negative value (sign bit) is below 0, Inf and NaN are
    // at or above 0x7f800000. Any sign bit is found by OR-ing the patterns
    // (one instruction per vector: SSE2 has no integer min), and with none
    // set the integer max is the largest value. Both vectorise.
    std::int32_t bmax = 0;
    std::int32_t sign_or = 0;
    for (std::size_t i = 0; i < kLen; ++i) {
      std::int32_t b = 0;
      std::memcpy(&b, line + i, sizeof b);
      bmax = b > bmax ? b : bmax;
      sign_or |= b;
    }
    if (sign_or < 0 || bmax >= kInfBits) return keep_all(lo, hi);
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
    // Quantise (vectorises); the edge cells' prefix sums; the interior's box sums.
    for (std::size_t i = 0; i < kLen; ++i) {
      level_a_[i] = static_cast<std::uint32_t>(static_cast<std::int32_t>(line[i] * scale));
    }
    const std::size_t reach = p.guard_cells + p.training_cells;
    if (p.edge != CfarEdge::kSkip) edge_prefix(level_a_.data(), reach);
    if (p.training_cells > kRunPad) return keep_all(lo, hi);  // not a valid Cfar (T <= 64)
    const std::uint32_t* box = box_sums(p.training_cells);
    const std::size_t first = lo > reach ? lo : reach;  // interior cells: [first, last)
    const std::size_t last = hi < kLen - reach ? hi : kLen - reach;
    if (so) {
      interior_flags<true>(line, box, first, last, k, p);
    } else {
      interior_flags<false>(line, box, first, last, k, p);
    }
    const std::size_t edge_lo_end = first < hi ? first : hi;  // [lo, edge_lo_end): lower edge
    const std::size_t edge_hi_begin = last > edge_lo_end ? last : edge_lo_end;
    if (p.edge == CfarEdge::kSkip) {  // untested, never detected
      for (std::size_t i = lo; i < edge_lo_end; ++i) flags_[i] = 0;
      for (std::size_t i = edge_hi_begin; i < hi; ++i) flags_[i] = 0;
    } else if (p.edge == CfarEdge::kShift && !so && !planned_only_) {
#if MPTRACK_FFT_X86_DISPATCH
      if constexpr (kCopy == dsp::FftCopy::kAvx512) {  // finished by run_avx512
        shift_pending_ = true;
        shift_lo_end_ = edge_lo_end;
        shift_hi_begin_ = edge_hi_begin;
        shift_k_ = k;
        return 0;
      }
#endif
      shift_lower_edge(line, lo, edge_lo_end, k, p.guard_cells, p.training_cells);
      shift_upper_edge(line, edge_hi_begin, hi, k, p.guard_cells, p.training_cells);
    } else {
      plan_edges(p);
      edges(line, lo, edge_lo_end, k, p.edge == CfarEdge::kWrap, so);
      edges(line, edge_hi_begin, hi, k, p.edge == CfarEdge::kWrap, so);
    }
    collect(lo, hi);
    return count_;
  }

  static constexpr float kFloatMax = std::numeric_limits<float>::max();
  static constexpr float kFloatMin = std::numeric_limits<float>::min();  ///< smallest normal
  static constexpr std::int32_t kInfBits = 0x7f800000;                   ///< bit pattern of +Inf
  /// Edge cells per end: G + T <= 128 (CfarParams::validate) and a screened
  /// line holds 2 (G + T) + 1 cells (min_line_length), so G + T <= (kLen - 1) / 2.
  static constexpr std::size_t kEdgeHalf = (kLen - 1) / 2 < 128 ? (kLen - 1) / 2 : 128;

  /// 2^k as a double, exact, for |k| <= 1000 (here |k| <= 90).
  MPTRACK_FFT_INLINE static double pow2(int k) {
    const std::uint64_t bits = static_cast<std::uint64_t>(k + 1023) << 52;
    double x = 0.0;
    std::memcpy(&x, &bits, sizeof x);
    return x;
  }

  // prefix_ over the cells the edge segments read, q: the quantised line.
  // Those are [0, E) and [kLen - E, kLen), E = 2(G + T) + 1 (the windows of
  // the cells within G + T of an end, wrapped or shifted): two chains of E
  // adds, interleaved, instead of one of kLen. The upper region's sums start
  // from 0 at its own first cell: every planned segment lies in one region
  // (plan_edges), so its difference is the same integer. Where the regions
  // meet (kLen <= 2E), one running sum over the whole line.
  MPTRACK_FFT_INLINE void edge_prefix(const std::uint32_t* q, std::size_t reach) {
    const std::size_t e = 2 * reach + 1;
    prefix_[0] = 0;
    if (kLen <= 2 * e) {
      for (std::size_t i = 0; i < kLen; ++i) prefix_[i + 1] = prefix_[i] + q[i];
      return;
    }
    const std::size_t base = kLen - e;
    prefix_[base] = 0;
    std::uint32_t low = 0;
    std::uint32_t high = 0;
    for (std::size_t j = 0; j < e; ++j) {
      low += q[j];
      prefix_[j + 1] = low;
      high += q[base + j];
      prefix_[base + j + 1] = high;
    }
  }

  // Sums of T consecutive quantised cells, B[j] = q_j + ... + q_{j+T-1} for
  // j <= kLen - T (q in level_a_): T in binary, the runs of widths 1, 2, 4,
  // ... built by doubling (each pass w -> 2w adds two loads a cell and
  // vectorises) and each set bit's run added into box_. log2 T passes, at
  // most 6 (T <= 64), against a running sum's one dependent add a cell; the
  // same integers (exact: below 2^30). Returns the array holding B.
  MPTRACK_FFT_INLINE const std::uint32_t* box_sums(std::size_t t) {
    std::uint32_t* cur = level_a_.data();
    std::uint32_t* next = level_b_.data();
    std::size_t w = 1;     // width of cur's sums
    std::size_t have = 0;  // width of box_'s sums so far
    for (;;) {
      if ((t & w) != 0) {
        if (have == 0 && t == w) return cur;  // T a power of two: the level itself
        add_run_sums(cur, have);
        have += w;
        if (have == t) return box_.data();
      }
      double_width(cur, next, w);
      std::uint32_t* tmp = cur;
      cur = next;
      next = tmp;
      w *= 2;
    }
  }

  // box_[j] = (have ? box_[j] : 0) + run[j + have], j < kLen. Entries past
  // the valid ones (j > kLen - width) hold sums with the zero padding and
  // are never read: a trip count fixed at compile time leaves no scalar tail.
  MPTRACK_FFT_INLINE void add_run_sums(const std::uint32_t* __restrict run, std::size_t have) {
    std::uint32_t* __restrict b = box_.data();
    if (have == 0) {
      for (std::size_t j = 0; j < kLen; ++j) b[j] = run[j];
    } else {
      for (std::size_t j = 0; j < kLen; ++j) b[j] += run[j + have];
    }
  }

  // out[j] = in[j] + in[j + w], j < kLen: runs of width 2w from runs of width w.
  MPTRACK_FFT_INLINE static void double_width(const std::uint32_t* __restrict in,
                                              std::uint32_t* __restrict out, std::size_t w) {
    for (std::size_t j = 0; j < kLen; ++j) out[j] = in[j] + in[j + w];
  }

  MPTRACK_FFT_INLINE std::size_t keep_all(std::size_t lo, std::size_t hi) {
    for (std::size_t i = lo; i < hi; ++i) cells_[count_++] = static_cast<std::uint16_t>(i);
    return count_;
  }

  // The screen's test of cell i against window sum w (every path: interior,
  // planned and closed-form edges): P > fl(float(W) k), header.
  MPTRACK_FFT_INLINE void flag_cell(const float* line, std::size_t i, std::uint32_t w, float k) {
    flags_[i] = static_cast<std::uint8_t>(line[i] > static_cast<float>(static_cast<std::int32_t>(w)) * k);
  }

  // Kept cells in ascending order. Flags are read eight at a time: on noise
  // nearly every word is zero, so the per-cell branch runs only near targets.
  MPTRACK_FFT_INLINE void collect(std::size_t lo, std::size_t hi) {
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

  // Interior cells (both runs inside the line, unwrapped), the bulk of the
  // line: two runs at fixed offsets, straight-line arithmetic that vectorises.
  template <bool kSo>
  MPTRACK_FFT_INLINE void interior_flags(const float* line, const std::uint32_t* box,
                                         std::size_t first, std::size_t last, float k,
                                         const CfarParams& p) {
    const std::size_t g = p.guard_cells;
    const std::size_t reach = g + p.training_cells;
    for (std::size_t i = first; i < last; ++i) {
      const std::uint32_t wl = box[i - reach];  // cells [i - G - T, i - G)
      const std::uint32_t wr = box[i + g + 1];  // cells (i + G, i + G + T]
      std::uint32_t w = wl + wr;
      if constexpr (kSo) w = wl < wr ? wl : wr;
      flag_cell(line, i, w, k);
    }
  }

  // kShift, CA and GO: the whole window of an edge cell in closed form on
  // prefix_ (P[x] = q_0 + ... + q_{x-1} over the lower region, E = 2(G + T)
  // + 1), the same integers as its planned segments but with contiguous
  // loads, so the loops vectorise (the table loop was a scalar gather,
  // ~28 % of a 128-cell line's screen; bench/README.md session 15).
  // Lower edge, cell i < G + T: the window is [0, h) and (i + G, i + G + 2T - h],
  // h = max(0, i - G) < T cells on the left.
  MPTRACK_FFT_INLINE void shift_lower_edge(const float* line, std::size_t from, std::size_t to, float k,
                                           std::size_t g, std::size_t t) {
    const std::uint32_t* q = prefix_.data();
    const std::size_t e = 2 * (g + t) + 1;
    const std::size_t mid = to < g + 1 ? to : g + 1;  // cells i <= G: h = 0
    for (std::size_t i = from; i < mid; ++i) {
      const std::uint32_t w = q[i + g + 1 + 2 * t] - q[i + g + 1];
      flag_cell(line, i, w, k);
    }
    for (std::size_t i = from > mid ? from : mid; i < to; ++i) {  // h = i - G
      const std::uint32_t w = q[i - g] + q[e] - q[i + g + 1];
      flag_cell(line, i, w, k);
    }
  }

  // Upper edge, cell i >= kLen - G - T: the window is [i - G - 2T + h, i - G)
  // and (i + G, kLen), h = kLen - (i + G + 1) < T cells on the right (0 once
  // i + G + 1 >= kLen). Differences of prefix_ within the upper region (it
  // starts from 0 at cell kLen - E; one running sum where the regions meet).
  MPTRACK_FFT_INLINE void shift_upper_edge(const float* line, std::size_t from, std::size_t to, float k,
                                           std::size_t g, std::size_t t) {
    const std::uint32_t* q = prefix_.data();
    const std::size_t base = kLen - (2 * (g + t) + 1);  // = i - G - 2T + h while h > 0
    const std::size_t split = kLen - g - 1;             // first cell with h = 0
    const std::size_t mid = to < split ? to : split;
    for (std::size_t i = from; i < mid; ++i) {
      const std::uint32_t w = (q[i - g] - q[base]) + (q[kLen] - q[i + g + 1]);
      flag_cell(line, i, w, k);
    }
    for (std::size_t i = from > mid ? from : mid; i < to; ++i) {
      const std::uint32_t w = q[i - g] - q[i - g - 2 * t];
      flag_cell(line, i, w, k);
    }
  }

  /// Training cells of one edge cell as prefix-sum segments: half h's sum is
  /// the sum over s of q[end[h][s]] - q[begin[h][s]]; unused segments are
  /// [0, 0). Half 0 is the left half (the first T cells of the gather order).
  /// Segments per half: two runs, and only run 1 (lower edge) or run 2
  /// (upper edge) can wrap, since G + T <= (kLen - 1) / 2: at most three,
  /// and two where nothing wraps (kShift).
  static constexpr std::size_t kSegments = 3;
  static constexpr std::size_t kShiftSegments = 2;
  /// Row kWhole: the whole window (both runs; under kWrap one of them may
  /// wrap, so at most three segments too), what CA's and GO's bound sums.
  static constexpr std::size_t kWhole = 2;
  /// One cell's plan (edge_runs); stored per segment in cell order (runs_begin_).
  struct EdgeRuns {
    std::array<std::array<std::uint16_t, kSegments>, 3> begin{};
    std::array<std::array<std::uint16_t, kSegments>, 3> end{};
  };

  // A cell within G + T of an end: its two runs as Cfar::gather_training()
  // takes them (kShift: the deficit moves to the other side; kWrap:
  // circular), as prefix-sum segments, computed once per (G, T, edge) and
  // reused for every line until the parameters change.
  MPTRACK_FFT_INLINE void plan_edges(const CfarParams& p) {
    if (planned_ && p.guard_cells == plan_guard_ && p.training_cells == plan_training_ && p.edge == plan_edge_) {
      return;
    }
    const std::size_t reach = p.guard_cells + p.training_cells;
    // Slots in cell order at each end (lower: i; upper: kEdgeHalf + i - (kLen - reach)),
    // so each edge loop reads every table as a run.
    upper_offset_ = kLen - reach - kEdgeHalf;
    for (std::size_t i = 0; i < reach; ++i) {
      store_runs(i, edge_runs(i, p));
      store_runs(kEdgeHalf + i, edge_runs(kLen - reach + i, p));
    }
    plan_guard_ = p.guard_cells;
    plan_training_ = p.training_cells;
    plan_edge_ = p.edge;
    planned_ = true;
  }

  void store_runs(std::size_t slot, const EdgeRuns& e) {
    for (std::size_t h = 0; h < 3; ++h) {
      for (std::size_t m = 0; m < kSegments; ++m) {
        runs_begin_[h][m][slot] = e.begin[h][m];
        runs_end_[h][m][slot] = e.end[h][m];
      }
    }
  }

  static EdgeRuns edge_runs(std::size_t i, const CfarParams& p) {
    const std::size_t g = p.guard_cells;
    const std::size_t t = p.training_cells;
    const std::size_t reach = g + t;
    std::size_t a = 0;  // run 1 [a, a + na), then run 2 [c, c + nc), gather order, mod kLen
    std::size_t na = 0;
    std::size_t c = 0;
    std::size_t nc = 0;
    if (p.edge == CfarEdge::kWrap) {
      a = (i + kLen - reach) % kLen;
      na = t;
      c = (i + g + 1) % kLen;
      nc = t;
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
    // Left half: run 1's first min(na, T) cells, then run 2's first T - that.
    const std::size_t na_left = na < t ? na : t;
    const std::size_t nc_left = t - na_left;
    EdgeRuns e;
    std::array<std::size_t, 3> used{};
    add_run(e, 0, used, a, na_left);
    add_run(e, 0, used, c, nc_left);
    add_run(e, 1, used, (a + na_left) % kLen, na - na_left);
    add_run(e, 1, used, (c + nc_left) % kLen, nc - nc_left);
    add_run(e, kWhole, used, a, na);  // CA, GO: the two runs, half as many loads
    add_run(e, kWhole, used, c, nc);
    return e;
  }

  /// Appends the cells [from, from + n) mod kLen to half h: one segment, or
  /// two where the run wraps past the end of the line.
  static void add_run(EdgeRuns& e, std::size_t h, std::array<std::size_t, 3>& used,
                      std::size_t from, std::size_t n) {
    if (n == 0) return;
    const std::size_t to = from + n <= kLen ? from + n : kLen;
    add_segment(e, h, used, from, to);
    if (from + n > kLen) add_segment(e, h, used, 0, from + n - kLen);
  }

  static void add_segment(EdgeRuns& e, std::size_t h, std::array<std::size_t, 3>& used,
                          std::size_t b, std::size_t en) {
    // Never more than kSegments; were one dropped, W would only be lower
    // (every segment sums cells >= 0): more cells kept, never fewer.
    if (used[h] == kSegments) return;
    e.begin[h][used[h]] = static_cast<std::uint16_t>(b);
    e.end[h][used[h]] = static_cast<std::uint16_t>(en);
    ++used[h];
  }

  /// Flags of edge cells [from, to), with the loop shape fixed per policy.
  MPTRACK_FFT_INLINE void edges(const float* line, std::size_t from, std::size_t to, float k,
                                bool wrap, bool so) {
    if (wrap && so) {
      edge_flags<kSegments, true>(line, from, to, k);
    } else if (wrap) {
      edge_flags<kSegments, false>(line, from, to, k);
    } else if (so) {
      edge_flags<kShiftSegments, true>(line, from, to, k);
    } else {
      edge_flags<kShiftSegments, false>(line, from, to, k);
    }
  }

  /// The interior's test on the planned runs, edge cells [from, to) of one
  /// end (table slot i - offset): SO the smaller half, CA and GO the whole
  /// window. Modular sums of exact integer sums (each < 2^31): the same
  /// number however the window's cells are grouped.
  template <std::size_t kSegs, bool kSo>
  MPTRACK_FFT_INLINE void edge_flags(const float* line, std::size_t from, std::size_t to, float k) {
    const std::size_t offset = from < kEdgeHalf ? 0 : upper_offset_;
    const std::uint32_t* q = prefix_.data();
    for (std::size_t i = from; i < to; ++i) {
      const std::size_t slot = i - offset;
      std::uint32_t w = 0;
      if constexpr (kSo) {
        const std::uint32_t wl = run_sum<kSegs>(q, 0, slot);
        const std::uint32_t wr = run_sum<kSegs>(q, 1, slot);
        w = wl < wr ? wl : wr;
      } else {
        w = run_sum<kSegs>(q, kWhole, slot);
      }
      flag_cell(line, i, w, k);
    }
  }

  /// Row h's sum for the edge cell in `slot`: kSegs prefix differences.
  template <std::size_t kSegs>
  MPTRACK_FFT_INLINE std::uint32_t run_sum(const std::uint32_t* q, std::size_t h,
                                            std::size_t slot) const {
    std::uint32_t w = 0;
    for (std::size_t m = 0; m < kSegs; ++m) {
      w += q[runs_end_[h][m][slot]] - q[runs_begin_[h][m][slot]];
    }
    return w;
  }

  /// Zeros after the kLen cells of a level: the doubling and box passes read
  /// up to T - 1 <= 63 entries past j (Cfar: T <= 64).
  static constexpr std::size_t kRunPad = 64;
  alignas(64) std::array<std::uint32_t, kLen + kRunPad> level_a_{};  ///< quantised cells, then runs
  alignas(64) std::array<std::uint32_t, kLen + kRunPad> level_b_{};  ///< the doubling's other buffer
  alignas(64) std::array<std::uint32_t, kLen> box_{};  ///< sums of T cells (T not a power of two)
  std::array<std::uint32_t, kLen + 1> prefix_{};  ///< running sums over the edge regions (mod 2^32)
  std::array<std::uint8_t, kLen> flags_{};        ///< 1: cell kept
  std::array<std::uint16_t, kLen> cells_{};       ///< kept cells, ascending
  /// Planned segments [row][segment][slot] of the edge cells, rows left,
  /// right, whole (plan_edges), slots in cell order at each end.
  using RunTable = std::array<std::array<std::array<std::int32_t, 2 * kEdgeHalf>, kSegments>, 3>;
  RunTable runs_begin_{};
  RunTable runs_end_{};
  std::size_t upper_offset_ = 0;  ///< slot = cell - upper_offset_ at the upper end
  std::size_t plan_guard_ = 0;    ///< parameters the tables were planned for
  std::size_t plan_training_ = 0;
  CfarEdge plan_edge_ = CfarEdge::kShift;
  bool planned_ = false;
  bool planned_only_ = false;  ///< set_planned_edges_only()
  // AVX-512 copy: kShift edges screen() left to run_avx512 (it returns 0 then).
  bool shift_pending_ = false;
  std::size_t shift_lo_end_ = 0;
  std::size_t shift_hi_begin_ = 0;
  float shift_k_ = 0.0f;
  std::size_t count_ = 0;
};

}  // namespace mptrack::frontend
