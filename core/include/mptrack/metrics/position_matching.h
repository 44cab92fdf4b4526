// The OSPA assignment between truth and estimated 2-D positions, exposed
// as a matching for the harness metrics that need it (docs/algorithms/metrics.md §CAR:
// CAR, NFT and RSE all match tracks to truths "by the OSPA assignment").
//
// The assignment minimises sum_i min(c, ||x_i - y_pi(i)||)^p over all
// assignments of the smaller set into the larger one (Schuhmacher, Vo, Vo
// 2008, eq. (3), the inner min of OSPA). The same assignment is optimal for
// GOSPA with alpha = 2 (Rahmathullah et al. 2017, Prop. 1: pairs at distance
// >= c cost exactly c^p = 2 * c^p / 2, the price of one miss plus one false
// target), so OspaMetric and GospaMetric share this class.
//
// A pair "within the cutoff" has distance < c; a pair assigned at distance
// >= c counts as unmatched for the harness (NFT: a confirmed track not
// assigned to any truth within c).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include <Eigen/Core>

#include "mptrack/metrics/assignment.h"
#include "mptrack/metrics/order_power.h"
#include "mptrack/status.h"
#include "mptrack/validate.h"

namespace mptrack {

/// Order and cutoff shared by OSPA and GOSPA.
template <class T>
struct MetricParams {
  T order_p = T(2);     ///< order p >= 1 [-] (seed 000 and 004: 2)
  T cutoff_m = T(10);   ///< cutoff c > 0 [m] (seed 004: 10 m; seed 000: 631 m)
};

template <class T, std::size_t MaxPoints>
class PositionMatcher {
 public:
  using Position = Eigen::Matrix<T, 2, 1>;  ///< [x m, y m]
  static constexpr std::size_t kMaxPoints = MaxPoints;
  static constexpr std::int32_t kUnassigned = -1;

  /// Validates p in [1, 64], c > 0 and MaxPoints * c^p finite in T (so no
  /// sum below can overflow). kInvalidArgument leaves the matcher unusable.
  Status init(const MetricParams<T>& params) {
    initialized_ = false;
    MPTRACK_TRY(check_range(params.order_p, T(1), T(64)));
    MPTRACK_TRY(check_positive(params.cutoff_m));
    const T c_pow = order_power(params.cutoff_m, params.order_p);
    MPTRACK_TRY(check(is_finite(c_pow * static_cast<T>(MaxPoints)) && c_pow > T(0)));
    params_ = params;
    cutoff_pow_ = c_pow;
    initialized_ = true;
    return Status::kOk;
  }

  /// Computes the optimal assignment. truths/estimates may be nullptr when
  /// their count is 0. kNotInitialized, kCapacityExceeded (a count >
  /// MaxPoints), kInvalidArgument (nullptr with a non-zero count) or
  /// kInvalidInput (a NaN/Inf coordinate) leave the previous result cleared.
  Status match(const Position* truths, std::size_t num_truths, const Position* estimates,
               std::size_t num_estimates) {
    num_truths_ = 0;
    num_estimates_ = 0;
    num_within_ = 0;
    cost_sum_ = T(0);
    if (!initialized_) return Status::kNotInitialized;
    if (num_truths > MaxPoints || num_estimates > MaxPoints) return Status::kCapacityExceeded;
    if ((num_truths > 0 && truths == nullptr) || (num_estimates > 0 && estimates == nullptr)) {
      return Status::kInvalidArgument;
    }
    for (std::size_t i = 0; i < num_truths; ++i) {
      if (!is_finite(truths[i](0)) || !is_finite(truths[i](1))) return Status::kInvalidInput;
    }
    for (std::size_t j = 0; j < num_estimates; ++j) {
      if (!is_finite(estimates[j](0)) || !is_finite(estimates[j](1))) return Status::kInvalidInput;
    }

    MPTRACK_TRY(solver_.resize(num_truths, num_estimates));
    const T c = params_.cutoff_m;
    const T p = params_.order_p;
    for (std::size_t i = 0; i < num_truths; ++i) {
      for (std::size_t j = 0; j < num_estimates; ++j) {
        const T d = distance(truths[i], estimates[j]);
        solver_.cost(i, j) = order_power(d < c ? d : c, p);  // min(c, d)^p
      }
    }
    MPTRACK_TRY(solver_.solve());

    for (std::size_t j = 0; j < num_estimates; ++j) estimate_within_[j] = false;
    for (std::size_t i = 0; i < num_truths; ++i) {
      truth_within_[i] = false;
      truth_distance_[i] = T(0);
      const std::int32_t j = solver_.row_assignment(i);
      if (j == kUnassigned) continue;
      const std::size_t ju = static_cast<std::size_t>(j);
      const T d = distance(truths[i], estimates[ju]);
      truth_distance_[i] = d;
      if (d < c) {
        truth_within_[i] = true;
        estimate_within_[ju] = true;
        ++num_within_;
      }
    }
    num_truths_ = num_truths;
    num_estimates_ = num_estimates;
    cost_sum_ = solver_.total_cost();
    return Status::kOk;
  }

  const MetricParams<T>& params() const { return params_; }
  /// c^p [m^p], computed once in init().
  T cutoff_pow() const { return cutoff_pow_; }

  std::size_t num_truths() const { return num_truths_; }
  std::size_t num_estimates() const { return num_estimates_; }
  /// Assigned pairs with distance < c.
  std::size_t num_within_cutoff() const { return num_within_; }
  /// sum over assigned pairs of min(c, d)^p [m^p] (the OSPA assignment cost).
  T assignment_cost() const { return cost_sum_; }

  /// Estimate assigned to truth i (i < num_truths()), or kUnassigned. The
  /// pair may be farther than c: see truth_within_cutoff().
  std::int32_t truth_to_estimate(std::size_t i) const { return solver_.row_assignment(i); }
  /// Truth assigned to estimate j (j < num_estimates()), or kUnassigned.
  std::int32_t estimate_to_truth(std::size_t j) const { return solver_.col_assignment(j); }
  /// Truth i is assigned to an estimate at distance < c.
  bool truth_within_cutoff(std::size_t i) const { return truth_within_[i]; }
  /// Estimate j is assigned to a truth at distance < c (false => a false
  /// track for NFT).
  bool estimate_within_cutoff(std::size_t j) const { return estimate_within_[j]; }
  /// Euclidean distance from truth i to its assigned estimate [m] (0 if unassigned).
  T truth_distance(std::size_t i) const { return truth_distance_[i]; }

 private:
  static T distance(const Position& a, const Position& b) {
    const T dx = a(0) - b(0);
    const T dy = a(1) - b(1);
    return std::sqrt(dx * dx + dy * dy);
  }

  AssignmentSolver<T, MaxPoints, MaxPoints> solver_;
  std::array<T, MaxPoints> truth_distance_{};
  std::array<bool, MaxPoints> truth_within_{};
  std::array<bool, MaxPoints> estimate_within_{};
  MetricParams<T> params_{};
  T cutoff_pow_ = T(0);
  T cost_sum_ = T(0);
  std::size_t num_truths_ = 0;
  std::size_t num_estimates_ = 0;
  std::size_t num_within_ = 0;
  bool initialized_ = false;
};

}  // namespace mptrack
