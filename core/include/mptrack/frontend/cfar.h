// Stage 4: constant-false-alarm-rate detection along one line of a power map.
//
// Window around the cell under test (CUT) i: G guard cells each side, then
// T training cells each side (2T in all). The noise estimate z and the
// threshold factor alpha give the test  P[i] > alpha * z.
//   CA: z = (1/2T) sum of all training cells
//   GO: z = max(mean of left T, mean of right T)
//   SO: z = min(mean of left T, mean of right T)
//   OS: z = x_(k) / c_k, x_(k) the k-th smallest training cell and
//       c_k = sum_{i=2T-k+1}^{2T} 1/i = E[x_(k)] for unit Exp(1) noise, so z is
//       an unbiased noise-power estimate (used to normalise amplitudes).
// alpha is solved in init() (bisection in double, no libm) from the exact
// false-alarm probability in homogeneous exponential noise, with n = T, N = 2T
// and t the factor on the *sum* / order statistic:
//   CA: Pfa = (1 + alpha/N)^-N                                   (Richards 6.5)
//   SO: Pfa = 2 sum_{k=0}^{n-1} C(n-1+k, k) (2 + t)^-(n+k),  t = alpha/n
//   GO: Pfa = 2 (1 + t)^-n - Pfa_SO(t)                       (Gandhi-Kassam 1988)
//   OS: Pfa = prod_{i=0}^{k-1} (N - i) / (N - i + t),  t = alpha/c_k  (Rohling 1983)
// Edges (CfarEdge): kSkip leaves cells without a full two-sided window
// untested; kShift moves the missing training cells to the other side (still
// 2T cells, same threshold; GO/SO halves are the first and last T training
// cells in index order), kWrap indexes circularly.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>

#include "mptrack/frontend/frontend_params.h"
#include "mptrack/status.h"
#include "mptrack/validate.h"

namespace mptrack::frontend {

/// Outcome of testing one cell.
struct CfarResult {
  bool tested = false;    ///< false: the cell had no valid window (kSkip edge)
  bool detected = false;  ///< power > alpha * noise
  float noise = 0.0f;     ///< noise-power estimate z (same units as the map)
};

namespace cfar_detail {

inline double pow_int(double base, std::size_t n) {
  double r = 1.0;
  for (std::size_t i = 0; i < n; ++i) r *= base;
  return r;
}

/// Pfa_SO as a function of t (factor on the half sums), n cells per side.
inline double pfa_so_sum(double t, std::size_t n) {
  const double b = 2.0 + t;
  double term = 1.0 / pow_int(b, n);  // k = 0
  double sum = term;
  for (std::size_t k = 1; k < n; ++k) {
    term = term * static_cast<double>(n - 1 + k) / static_cast<double>(k) / b;
    sum += term;
  }
  return 2.0 * sum;
}

}  // namespace cfar_detail

/// Exact false-alarm probability of a variant for threshold factor alpha on
/// the noise estimate z (definitions above). Exposed for tests.
inline double cfar_pfa(CfarType type, std::size_t training_per_side, std::size_t os_rank,
                       double alpha) {
  const std::size_t n = training_per_side;
  const std::size_t big_n = 2 * n;
  switch (type) {
    case CfarType::kCellAveraging:
      return 1.0 / cfar_detail::pow_int(1.0 + alpha / static_cast<double>(big_n), big_n);
    case CfarType::kSmallestOf:
      return cfar_detail::pfa_so_sum(alpha / static_cast<double>(n), n);
    case CfarType::kGreatestOf: {
      const double t = alpha / static_cast<double>(n);
      return 2.0 / cfar_detail::pow_int(1.0 + t, n) - cfar_detail::pfa_so_sum(t, n);
    }
    case CfarType::kOrderedStatistic: {
      double ck = 0.0;
      for (std::size_t i = big_n - os_rank + 1; i <= big_n; ++i) ck += 1.0 / static_cast<double>(i);
      const double t = alpha / ck;
      double p = 1.0;
      for (std::size_t i = 0; i < os_rank; ++i) {
        p *= static_cast<double>(big_n - i) / (static_cast<double>(big_n - i) + t);
      }
      return p;
    }
  }
  return 1.0;
}

/// One-dimensional CFAR detector (lines up to 65535 cells).
class Cfar {
 public:
  static constexpr std::size_t kMaxTraining = 128;  ///< 2 * max training_cells

  /// Validates p and solves alpha. kInvalidArgument on bad params.
  Status init(const CfarParams& p) {
    initialized_ = false;
    MPTRACK_TRY(p.validate());
    params_ = p;
    if (params_.os_rank == 0) {
      // Rohling's recommendation k ~ 3N/4, rounded half up.
      params_.os_rank = (3 * 2 * p.training_cells + 2) / 4;
      if (params_.os_rank < 1) params_.os_rank = 1;
    }
    const std::size_t n = params_.training_cells;
    const std::size_t big_n = 2 * n;
    os_norm_ = 0.0f;
    {
      double ck = 0.0;
      for (std::size_t i = big_n - params_.os_rank + 1; i <= big_n; ++i) {
        ck += 1.0 / static_cast<double>(i);
      }
      os_norm_ = static_cast<float>(1.0 / ck);
    }
    // Bracket then bisect: Pfa(alpha) is continuous and strictly decreasing.
    double lo = 0.0;
    double hi = 1.0;
    int guard = 0;
    while (cfar_pfa(params_.type, n, params_.os_rank, hi) > params_.pfa) {
      lo = hi;
      hi *= 2.0;
      if (++guard > 200) return Status::kInvalidArgument;  // pfa unreachable
    }
    for (int it = 0; it < 200; ++it) {
      const double mid = 0.5 * (lo + hi);
      if (!(mid > lo && mid < hi)) break;  // interval at double resolution
      if (cfar_pfa(params_.type, n, params_.os_rank, mid) > params_.pfa) {
        lo = mid;
      } else {
        hi = mid;
      }
    }
    alpha_ = hi;
    alpha_f_ = static_cast<float>(hi);
    initialized_ = true;
    return Status::kOk;
  }

  /// Minimum line length for this window: 2(G + T) + 1 cells.
  std::size_t min_line_length() const { return params_.min_line_length(); }

  /// Tests cell i of line[0..len). len >= min_line_length() is the caller's
  /// precondition (FrontEnd::init checks it); otherwise the cell is untested.
  CfarResult test(const float* line, std::size_t len, std::size_t i) const {
    CfarResult r;
    if (!initialized_ || i >= len || len < min_line_length()) return r;
    std::array<float, kMaxTraining> cells;
    const std::size_t count = gather_training(line, len, i, cells.data());
    if (count == 0) return r;
    r.tested = true;
    r.noise = noise_estimate(cells.data(), count);
    r.detected = line[i] > alpha_f_ * r.noise;
    return r;
  }

  /// Copies the 2T training cells of cell i, in index order (the first T
  /// form the left half of GO/SO), into cells[0..2T) and returns 2T; 0 if
  /// the cell has no window (kSkip edge). Preconditions as for test().
  std::size_t gather_training(const float* line, std::size_t len, std::size_t i, float* cells) const {
    const std::size_t g = params_.guard_cells;
    const std::size_t t = params_.training_cells;
    std::size_t count = 0;
    const std::size_t reach = g + t;
    if (params_.edge == CfarEdge::kWrap) {
      for (std::size_t k = 0; k < t; ++k) cells[count++] = line[(i + len - reach + k) % len];
      for (std::size_t k = 0; k < t; ++k) cells[count++] = line[(i + g + 1 + k) % len];
      return count;
    }
    const bool left_ok = i >= reach;
    const bool right_ok = i + reach < len;
    if (left_ok && right_ok) {
      for (std::size_t k = 0; k < t; ++k) cells[count++] = line[i - reach + k];
      for (std::size_t k = 0; k < t; ++k) cells[count++] = line[i + g + 1 + k];
    } else if (params_.edge == CfarEdge::kSkip) {
      return 0;
    } else if (!left_ok) {
      // Left side short: take what exists, the deficit extends the right run.
      const std::size_t have = i > g ? i - g : 0;  // cells [0, i-g)
      const std::size_t from = have > t ? have - t : 0;
      for (std::size_t k = from; k < have; ++k) cells[count++] = line[k];
      const std::size_t need = 2 * t - count;
      for (std::size_t k = 0; k < need; ++k) cells[count++] = line[i + g + 1 + k];
    } else {
      // Right side short: the deficit extends the left run.
      const std::size_t start_r = i + g + 1;
      const std::size_t have = start_r < len ? len - start_r : 0;
      const std::size_t take_r = have < t ? have : t;
      const std::size_t need_l = 2 * t - take_r;
      for (std::size_t k = 0; k < need_l; ++k) cells[count++] = line[i - g - need_l + k];
      for (std::size_t k = 0; k < take_r; ++k) cells[count++] = line[start_r + k];
    }
    return count;
  }

  /// Threshold factor alpha as float (the factor test() applies) [-].
  float alpha_f() const { return alpha_f_; }
  /// 1 / c_k, the OS normalisation (header comment) [-].
  float os_norm() const { return os_norm_; }

  /// Threshold factor alpha on the noise estimate [-].
  double alpha() const { return alpha_; }
  const CfarParams& params() const { return params_; }
  bool initialized() const { return initialized_; }

 private:
  float noise_estimate(float* cells, std::size_t count) const {
    const std::size_t t = params_.training_cells;
    switch (params_.type) {
      case CfarType::kCellAveraging: {
        float s = 0.0f;
        for (std::size_t k = 0; k < count; ++k) s += cells[k];
        return s / static_cast<float>(count);
      }
      case CfarType::kGreatestOf:
      case CfarType::kSmallestOf: {
        float sl = 0.0f;
        float sr = 0.0f;
        for (std::size_t k = 0; k < t; ++k) sl += cells[k];
        for (std::size_t k = t; k < count; ++k) sr += cells[k];
        const float ml = sl / static_cast<float>(t);
        const float mr = sr / static_cast<float>(count - t);
        if (params_.type == CfarType::kGreatestOf) return ml > mr ? ml : mr;
        return ml < mr ? ml : mr;
      }
      case CfarType::kOrderedStatistic: {
        // k-th smallest (1-based): a value, so the selection algorithm cannot
        // change the result; nth_element is in place (no allocation).
        const std::size_t k = params_.os_rank - 1;
        std::nth_element(cells, cells + k, cells + count);
        return cells[k] * os_norm_;
      }
    }
    return 0.0f;
  }

  CfarParams params_{};
  double alpha_ = 0.0;
  float alpha_f_ = 0.0f;
  float os_norm_ = 1.0f;
  bool initialized_ = false;
};

}  // namespace mptrack::frontend
