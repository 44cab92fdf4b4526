// IGG mixture components and fixed-capacity mixture reduction (seed 001 Sec. 4.6;
// docs/algorithms/gm-phd.md §Mixture reduction): prune, merge, cap.
//
// Policy (documented, deterministic):
//  1. components with weight < prune_threshold are dropped;
//  2. greedy merge in decreasing weight order (ties: lower index first):
//     the heaviest unused component absorbs every unused component within
//     Mahalanobis^2 <= U under its covariance AND (with amplitude) whose IG
//     symmetric KL to it is <= U_sigma (the bi-threshold rule, seed 001 eqs. (80)-(81));
//     kinematics are moment-matched, powers KL-projected (seed 001 eqs. (83)-(85)), the
//     label and measurement index are the heaviest's;
//  3. truncation to the output capacity J_max (Vo & Ma 2006, Table II:
//     "if more than J_max components, keep the J_max with the largest
//     weights"): while the output has room, merged components are appended
//     in order of their heads' weights; once it is full, a merged component
//     replaces the lightest kept one if it is heavier, and the output is
//     then re-sorted heaviest first (stable). Each component left out is
//     counted in the return value, and the largest weight left out is
//     reported; the caller adds the count to
//     TrackerCounters::mixture_truncated, which is not a capacity error
//     unless what was left out could have been a target (GM-PHD/CPHD: a
//     weight >= extract_threshold; docs/algorithms/gm-phd.md §Mixture
//     reduction). Nothing is dropped
//     silently. When nothing is truncated the operations are those of the
//     plain greedy merge, bit for bit.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "mptrack/model/inverse_gamma.h"
#include "mptrack/model/inverse_gamma_merge.h"
#include "mptrack/model/mahalanobis.h"
#include "mptrack/model/spd_guard.h"
#include "mptrack/rfs/measurement_model.h"
#include "mptrack/static_vector.h"

namespace mptrack::rfs {

/// One inverse-Gamma-Gaussian component: weight, kinematics, power.
template <class T>
struct TargetComponent {
  T weight = T(0);                 ///< PHD mass or Bernoulli mixture weight [-]
  Vec4<T> x = Vec4<T>::Zero();     ///< [px m, vx m/s, py m, vy m/s]
  Mat4<T> P = Mat4<T>::Identity(); ///< covariance of x
  model::InverseGamma<T> power;    ///< belief on varsigma = 1 + SNR
  std::uint32_t label = 0;         ///< display label (birth order)
  std::int32_t measurement = -1;   ///< measurement of the last update, -1 = missed
};

/// Mixture-reduction settings (a view of the filter params).
template <class T>
struct ReductionSettings {
  T prune_threshold = T(1e-5);
  T merge_threshold = T(4);
  T merge_threshold_power = T(4);
  bool use_power = true;
  T max_alpha = T(1e4);
  T min_variance = T(1e-6);
};

/// Scratch for reduce(), kept in the filter object (no stack arrays).
template <std::size_t NIn>
struct ReductionScratch {
  std::array<bool, NIn> used{};
  std::array<bool, NIn> member{};
};

/// Step 3 of the policy: appends m, or when out is full replaces its
/// lightest entry (ties: the later one) if m is heavier. Returns true if a
/// component was left out; its weight is then raised into max_dropped.
template <class T, std::size_t NOut>
bool keep_heaviest(StaticVector<TargetComponent<T>, NOut>& out, const TargetComponent<T>& m, T& max_dropped) {
  if (out.push_back(m) == Status::kOk) return false;
  std::size_t lightest = 0;
  for (std::size_t k = 1; k < out.size(); ++k) {
    if (!(out[k].weight > out[lightest].weight)) lightest = k;
  }
  T dropped = m.weight;
  if (m.weight > out[lightest].weight) {
    dropped = out[lightest].weight;
    out[lightest] = m;
  }
  if (dropped > max_dropped) max_dropped = dropped;
  return true;
}

/// Stable insertion sort, heaviest first (after a truncation only: the
/// extraction reads the mixture in this order).
template <class T, std::size_t NOut>
void sort_heaviest_first(StaticVector<TargetComponent<T>, NOut>& out) {
  for (std::size_t i = 1; i < out.size(); ++i) {
    const TargetComponent<T> c = out[i];
    std::size_t j = i;
    for (; j > 0 && out[j - 1].weight < c.weight; --j) out[j] = out[j - 1];
    out[j] = c;
  }
}

/// Reduces `in` into `out` (cleared first). Returns the number of
/// components left out by the truncation to out's capacity (step 3), and
/// the largest weight left out in max_dropped (0 if none); numerical
/// repairs are added to repairs.
template <class T, std::size_t NIn, std::size_t NOut>
std::size_t reduce_mixture(const StaticVector<TargetComponent<T>, NIn>& in,
                           StaticVector<TargetComponent<T>, NOut>& out,
                           const ReductionSettings<T>& s, ReductionScratch<NIn>& scratch,
                           std::uint64_t& repairs, T& max_dropped) {
  out.clear();
  max_dropped = T(0);
  const std::size_t n = in.size();
  for (std::size_t i = 0; i < n; ++i) scratch.used[i] = !(in[i].weight >= s.prune_threshold);
  std::size_t dropped = 0;
  for (;;) {
    std::size_t h = n;
    for (std::size_t i = 0; i < n; ++i) {
      if (!scratch.used[i] && (h == n || in[i].weight > in[h].weight)) h = i;
    }
    if (h == n) break;
    const TargetComponent<T>& head = in[h];
    T w = T(0);
    Vec4<T> xs = Vec4<T>::Zero();
    // First pass: membership and weighted mean.
    for (std::size_t j = 0; j < n; ++j) {
      if (scratch.used[j]) continue;
      bool member = j == h;
      if (!member) {
        const Vec4<T> d = in[j].x - head.x;
        T d2 = T(0);
        if (model::mahalanobis_n<T, 4>(d, head.P, d2) && d2 <= s.merge_threshold) {
          member = !s.use_power || model::ig_symmetric_kl(in[j].power, head.power) <= s.merge_threshold_power;
        }
      }
      if (!member) continue;
      scratch.used[j] = true;
      scratch.member[j] = true;
      w += in[j].weight;
      xs += in[j].weight * in[j].x;
    }
    TargetComponent<T> m = head;
    m.weight = w;
    m.x = xs / w;
    Mat4<T> P = Mat4<T>::Zero();
    model::IgMergeAccumulator<T> acc;
    for (std::size_t j = 0; j < n; ++j) {
      if (!scratch.member[j]) continue;
      scratch.member[j] = false;
      const Vec4<T> d = in[j].x - m.x;
      P += in[j].weight * (in[j].P + d * d.transpose());
      acc.add(in[j].weight, in[j].power);
    }
    m.P = P / w;
    if (model::keep_spd(m.P, s.min_variance)) ++repairs;
    if (s.use_power) m.power = acc.result(s.max_alpha);
    if (keep_heaviest(out, m, max_dropped)) ++dropped;
  }
  if (dropped > 0) sort_heaviest_first(out);
  return dropped;
}

}  // namespace mptrack::rfs
