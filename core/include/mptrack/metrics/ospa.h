// OSPA metric on 2-D positions (Schuhmacher, Vo, Vo, "A consistent metric
// for performance evaluation of multi-object filters", IEEE TSP 2008).
// Seed 000 Sec. IV-A (p = 2, c = 631 m), seed 004 Sec. V-A (p = 2, c = 10 m):
//
//   d_c^(p)(X, Y) = ( (1/n) [ min_pi sum_{i=1}^m min(c, ||x_i - y_pi(i)||)^p
//                             + c^p (n - m) ] )^(1/p),   m <= n,
//
// d(empty, empty) = 0 and d = c when exactly one set is empty. The two
// components of Ristic et al. (2011) are reported with it:
//   localisation = ( (1/n) sum min(c, d)^p )^(1/p),
//   cardinality  = ( (1/n) c^p (n - m) )^(1/p),
// so total^p = localisation^p + cardinality^p.
//
// Allocation-free: the matcher (and its assignment solver, ~MaxPoints^2
// scalars) lives in the object; place big ones statically.
#pragma once

#include <cstddef>

#include "mptrack/metrics/position_matching.h"
#include "mptrack/status.h"

namespace mptrack {

template <class T>
struct OspaResult {
  T total = T(0);         ///< OSPA distance [m]
  T localisation = T(0);  ///< localisation component [m]
  T cardinality = T(0);   ///< cardinality component [m]
};

template <class T, std::size_t MaxPoints>
class OspaMetric {
 public:
  using Matcher = PositionMatcher<T, MaxPoints>;
  using Position = typename Matcher::Position;

  /// Validates p and c once (see PositionMatcher::init).
  Status init(const MetricParams<T>& params) { return matcher_.init(params); }

  /// OSPA between truths X and estimates Y (the metric is symmetric; the
  /// matching() keeps truths as rows for the harness). On failure (see
  /// PositionMatcher::match) result is set to zero.
  Status compute(const Position* truths, std::size_t num_truths, const Position* estimates,
                 std::size_t num_estimates, OspaResult<T>& result) {
    result = OspaResult<T>{};
    MPTRACK_TRY(matcher_.match(truths, num_truths, estimates, num_estimates));
    const std::size_t n = num_truths > num_estimates ? num_truths : num_estimates;
    if (n == 0) return Status::kOk;
    const std::size_t m = num_truths > num_estimates ? num_estimates : num_truths;
    const T p = matcher_.params().order_p;
    const T inv_n = T(1) / static_cast<T>(n);
    const T loc_pow = matcher_.assignment_cost() * inv_n;
    const T card_pow = matcher_.cutoff_pow() * static_cast<T>(n - m) * inv_n;
    result.localisation = order_root(loc_pow, p);
    result.cardinality = order_root(card_pow, p);
    result.total = order_root(loc_pow + card_pow, p);
    return Status::kOk;
  }

  /// The assignment behind the last compute() (truths = rows).
  const Matcher& matching() const { return matcher_; }

 private:
  Matcher matcher_;
};

}  // namespace mptrack
