// GOSPA metric with alpha = 2 on 2-D positions (Rahmathullah,
// Garcia-Fernandez, Svensson, "Generalized optimal sub-pattern assignment
// metric", FUSION 2017, eq. (2) and Prop. 1):
//
//   d_p^(c,2)(X, Y) = ( min_gamma [ sum_{(i,j) in gamma} d(x_i, y_j)^p
//                                   + (c^p / 2) (|X| + |Y| - 2 |gamma|) ] )^(1/p),
//
// gamma ranging over partial assignments with every pair at distance < c.
// Unlike OSPA it is not normalised by max(|X|, |Y|), so it grows with the
// number of errors. The minimising gamma is the OSPA assignment with pairs at
// distance >= c dropped (see position_matching.h), which gives the split
//   total^p = localisation + missed + false   (all in m^p, as the authors'
//   reference implementation reports them),
// with missed = (c^p/2) * #truths left unmatched and false = (c^p/2) *
// #estimates left unmatched.
#pragma once

#include <cstddef>

#include "mptrack/metrics/position_matching.h"
#include "mptrack/status.h"

namespace mptrack {

template <class T>
struct GospaResult {
  T total = T(0);              ///< GOSPA distance [m]
  T localisation_pow = T(0);   ///< sum of d^p over matched pairs [m^p]
  T missed_pow = T(0);         ///< (c^p / 2) * num_missed [m^p]
  T false_pow = T(0);          ///< (c^p / 2) * num_false [m^p]
  std::size_t num_matched = 0; ///< pairs at distance < c
  std::size_t num_missed = 0;  ///< truths without an estimate within c
  std::size_t num_false = 0;   ///< estimates without a truth within c
};

template <class T, std::size_t MaxPoints>
class GospaMetric {
 public:
  using Matcher = PositionMatcher<T, MaxPoints>;
  using Position = typename Matcher::Position;

  /// Validates p and c once (see PositionMatcher::init).
  Status init(const MetricParams<T>& params) { return matcher_.init(params); }

  /// GOSPA between truths X and estimates Y. On failure (see
  /// PositionMatcher::match) result is set to zero.
  Status compute(const Position* truths, std::size_t num_truths, const Position* estimates,
                 std::size_t num_estimates, GospaResult<T>& result) {
    result = GospaResult<T>{};
    MPTRACK_TRY(matcher_.match(truths, num_truths, estimates, num_estimates));
    const T p = matcher_.params().order_p;
    // Localisation: matched pairs only, summed in truth order.
    T loc = T(0);
    for (std::size_t i = 0; i < num_truths; ++i) {
      if (matcher_.truth_within_cutoff(i)) loc += order_power(matcher_.truth_distance(i), p);
    }
    const std::size_t matched = matcher_.num_within_cutoff();
    const T half_c_pow = matcher_.cutoff_pow() / T(2);
    result.num_matched = matched;
    result.num_missed = num_truths - matched;
    result.num_false = num_estimates - matched;
    result.localisation_pow = loc;
    result.missed_pow = half_c_pow * static_cast<T>(result.num_missed);
    result.false_pow = half_c_pow * static_cast<T>(result.num_false);
    result.total = order_root(loc + result.missed_pow + result.false_pow, p);
    return Status::kOk;
  }

  /// The assignment behind the last compute() (truths = rows).
  const Matcher& matching() const { return matcher_; }

 private:
  Matcher matcher_;
};

}  // namespace mptrack
