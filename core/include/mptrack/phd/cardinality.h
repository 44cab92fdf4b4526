// Cardinality distribution of the GM-CPHD (Vo, Vo, Cantoni 2007, "Analytic
// implementations of the cardinalized PHD filter", eqs. 13-14 and 19-21)
// with Poisson clutter, in the form that cancels the clutter rate:
//
//   A^u(n; Z) = sum_{j=0}^{min(|Z|, n-u)} e_j(R') n!/(n-j-u)! phi^(n-j-u)
//
// where R'_z = sum_i w_i P_D g_i(z) / (kappa(z) W), W = sum_i w_i,
// phi = sum_i w_i (1 - P_D,i) / W, and e_j the elementary symmetric
// functions. Then (derivation in phd_filter.h):
//   p+(n)            proportional to A^0(n; Z) p(n)
//   missed weight    w (1 - P_D) <A^1(Z), p> / (W <A^0(Z), p>)
//   detected weight  w P_D g(z) / kappa(z) <A^1(Z \ z), p> / (W <A^0(Z), p>)
// Everything is in the log domain: R' spans e^-100 .. e^+100 with
// amplitude, and n! overflows float past n = 34 (docs/algorithms/gm-phd.md §Update).
// Only orders j <= N (the support) are ever needed, so an ESF costs O(|Z| N).
#pragma once

#include <array>
#include <cstddef>

#include "mptrack/math/detmath.h"
#include "mptrack/rfs/log_sum.h"

namespace mptrack::phd {

template <class T, std::size_t N>
class Cardinality {
 public:
  static constexpr T kLogZero = T(-1e30);

  void init() {
    p_.fill(T(0));
    p_[0] = T(1);
    log_fact_[0] = T(0);
    for (std::size_t n = 1; n <= N; ++n) log_fact_[n] = log_fact_[n - 1] + dmath::dlog(T(n));
  }

  /// Survival thinning (binomial, p_S) then convolution with Poisson births
  /// of mean birth_mean; mass beyond N is dropped and the rest renormalised.
  void predict(T survival, T birth_mean) {
    const T ls = dmath::dlog(survival);
    const T ld = dmath::dlog(T(1) - survival);
    for (std::size_t n = 0; n <= N; ++n) {
      T acc = T(0);
      for (std::size_t l = n; l <= N; ++l) {
        if (!(p_[l] > T(0))) continue;
        const T lb = log_fact_[l] - log_fact_[n] - log_fact_[l - n] + T(n) * ls + T(l - n) * ld;
        acc += p_[l] * dmath::dexp(lb);
      }
      tmp_[n] = acc;
    }
    const T lbm = birth_mean > T(0) ? dmath::dlog(birth_mean) : kLogZero;
    T total = T(0);
    for (std::size_t n = 0; n <= N; ++n) {
      T acc = T(0);
      for (std::size_t j = 0; j <= n; ++j) {
        const std::size_t b = n - j;
        if (!(tmp_[j] > T(0))) continue;
        if (b > 0 && !(birth_mean > T(0))) continue;
        const T lp = -birth_mean + (b > 0 ? T(b) * lbm : T(0)) - log_fact_[b];
        acc += tmp_[j] * dmath::dexp(lp);
      }
      p_[n] = acc;
      total += acc;
    }
    normalize(total);
  }

  /// Log-domain ESF of the values lr[0..count) up to order N into out.
  /// Returns the highest order filled.
  std::size_t esf(const T* lr, std::size_t count, std::size_t skip, std::array<T, N + 1>& out) const {
    out.fill(kLogZero);
    out[0] = T(0);
    std::size_t top = 0;
    for (std::size_t i = 0; i < count; ++i) {
      if (i == skip) continue;
      if (top < N) ++top;
      for (std::size_t j = top; j >= 1; --j) {
        if (out[j - 1] <= kLogZero) continue;
        out[j] = out[j] <= kLogZero ? lr[i] + out[j - 1] : rfs::log_add(out[j], lr[i] + out[j - 1]);
      }
    }
    return top;
  }

  /// ln A^u(n) for every n (kLogZero where undefined).
  void log_a(const std::array<T, N + 1>& le, std::size_t top, std::size_t u, T log_phi,
             std::array<T, N + 1>& out) const {
    for (std::size_t n = 0; n <= N; ++n) {
      out[n] = kLogZero;
      if (n < u) continue;
      rfs::LogSum<T> s;
      const std::size_t jmax = top < n - u ? top : n - u;
      for (std::size_t j = 0; j <= jmax; ++j) {
        if (le[j] <= kLogZero) continue;
        const std::size_t rest = n - j - u;
        s.add(le[j] + log_fact_[n] - log_fact_[rest] + T(rest) * log_phi);
      }
      if (s.any) out[n] = s.value();
    }
  }

  /// ln <A, p>.
  T log_inner(const std::array<T, N + 1>& la) const {
    rfs::LogSum<T> s;
    for (std::size_t n = 0; n <= N; ++n) {
      if (!(p_[n] > T(0)) || la[n] <= kLogZero) continue;
      s.add(dmath::dlog(p_[n]) + la[n]);
    }
    return s.any ? s.value() : kLogZero;
  }

  /// p(n) <- A^0(n) p(n), normalised.
  void update(const std::array<T, N + 1>& la0, T log_norm) {
    T total = T(0);
    for (std::size_t n = 0; n <= N; ++n) {
      if (!(p_[n] > T(0)) || la0[n] <= kLogZero) {
        p_[n] = T(0);
        continue;
      }
      p_[n] = dmath::dexp(dmath::dlog(p_[n]) + la0[n] - log_norm);
      total += p_[n];
    }
    normalize(total);
  }

  /// MAP cardinality (ties: the smaller n).
  std::size_t map() const {
    std::size_t best = 0;
    for (std::size_t n = 1; n <= N; ++n) {
      if (p_[n] > p_[best]) best = n;
    }
    return best;
  }

  T mean() const {
    T m = T(0);
    for (std::size_t n = 0; n <= N; ++n) m += T(n) * p_[n];
    return m;
  }

  T probability(std::size_t n) const { return p_[n]; }

 private:
  void normalize(T total) {
    if (!(total > T(0))) {
      p_.fill(T(0));
      p_[0] = T(1);
      return;
    }
    for (std::size_t n = 0; n <= N; ++n) p_[n] /= total;
  }

  std::array<T, N + 1> p_{};
  std::array<T, N + 1> tmp_{};
  std::array<T, N + 1> log_fact_{};
};

}  // namespace mptrack::phd
