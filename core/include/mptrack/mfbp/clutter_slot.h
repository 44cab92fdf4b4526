// The MF-BP clutter state: one slot per Gaussian clutter component, the
// uniform component, and the Dirichlet mixing weights over all of them.
//
// A component holds its Normal-Wishart spatial belief (seed 000 eq. (50))
// and CNR inverse gamma (eq. (62)) at the scan before the window and per
// window scan (forward and smoothed); the uniform component only the CNR.
// The Dirichlet statistics alpha (eq. (69)) are kept per window scan and
// source slot (0 = uniform, 1 + c = component c), with the clutter count M_k
// they were computed from. Each slot shifts itself when the window slides
// (docs/algorithms/mfbp.md §Window schedule).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "mptrack/mfbp/amplitude_stats.h"
#include "mptrack/model/inverse_gamma.h"
#include "mptrack/mfbp/normal_wishart.h"

namespace mptrack::mfbp {

template <class T, class Caps>
struct CompSlot {
  static constexpr std::size_t kMaxWindow = Caps::kMaxWindow;
  using NW = NormalWishart<T>;
  using IG = model::InverseGamma<T>;

  bool alive = false;
  std::uint32_t id = 0;
  std::uint32_t low_windows = 0;
  NW nw0{};
  IG ig0{};
  T alpha0 = T(1);
  std::array<NW, kMaxWindow> nwf{}, nws{};
  std::array<IG, kMaxWindow> igf{}, igs{};

  /// The filtered beliefs at the last finalised scan become the prior
  /// (alpha_last: its Dirichlet statistic, floored so that a component that
  /// explained nothing stays a valid Dirichlet parameter).
  void shift(std::size_t fc, std::size_t n, T alpha_last) {
    const std::size_t last = fc - 1;
    nw0 = nwf[last];
    ig0 = igf[last];
    alpha0 = alpha_last;
    if (!(alpha0 > T(1e-3))) alpha0 = T(1e-3);
    for (std::size_t k = fc; k < n; ++k) {
      nwf[k - fc] = nwf[k];
      nws[k - fc] = nws[k];
      igf[k - fc] = igf[k];
      igs[k - fc] = igs[k];
    }
  }

  /// Its beliefs on every window scan are the prior until the next sweep.
  void fill_window_with_prior() {
    for (std::size_t k = 0; k < kMaxWindow; ++k) {
      nwf[k] = nw0;
      nws[k] = nw0;
      igf[k] = ig0;
      igs[k] = ig0;
    }
  }
};

template <class T, class Caps>
struct UniformSlot {
  static constexpr std::size_t kMaxWindow = Caps::kMaxWindow;
  using IG = model::InverseGamma<T>;

  IG ig0{};
  T alpha0 = T(30);
  std::array<IG, kMaxWindow> igf{}, igs{};

  void shift(std::size_t fc, std::size_t n, T alpha_last) {
    ig0 = igf[fc - 1];
    alpha0 = alpha_last;
    for (std::size_t k = fc; k < n; ++k) {
      igf[k - fc] = igf[k];
      igs[k - fc] = igs[k];
    }
  }
};

/// Every clutter source and the Dirichlet chain over them.
template <class T, class Caps>
struct ClutterTable {
  static constexpr std::size_t kMaxComp = Caps::kMaxClutterComponents;
  static constexpr std::size_t kMaxWindow = Caps::kMaxWindow;
  static constexpr std::size_t kSources = kMaxComp + 1;  ///< + the uniform component
  using Alphas = std::array<T, kSources>;

  std::array<CompSlot<T, Caps>, kMaxComp> comps{};
  UniformSlot<T, Caps> uniform{};
  std::array<Alphas, kMaxWindow> alpha_f{}, alpha_s{};  ///< Dirichlet, forward / smoothed
  std::array<T, kMaxWindow> m{};  ///< clutter count M_k per window scan
  T m_prev = T(30);               ///< M at the scan before the window

  /// M_tau,k = M_k E[pi_tau] (docs/algorithms/mfbp.md §Clutter chain: the
  /// paper's M_k alpha_tau is not normalised).
  T component_count(std::size_t k, std::size_t src) const {
    T total = T(0);
    for (std::size_t q = 0; q < kSources; ++q) total += alpha_s[k][q];
    return total > T(0) ? m[k] * alpha_s[k][src] / total : T(0);
  }

  std::size_t live() const {
    std::size_t n = 0;
    for (const auto& c : comps) {
      if (c.alive) ++n;  // a branch: see mptf/ground_fusion.h FusedTrack::members()
    }
    return n;
  }

  /// The window slides by fc scans (n held).
  void shift(std::size_t fc, std::size_t n) {
    const std::size_t last = fc - 1;
    uniform.shift(fc, n, alpha_f[last][0]);
    for (std::size_t c = 0; c < kMaxComp; ++c) {
      if (comps[c].alive) comps[c].shift(fc, n, alpha_f[last][c + 1]);
    }
    m_prev = m[last];
    for (std::size_t k = fc; k < n; ++k) {
      alpha_f[k - fc] = alpha_f[k];
      alpha_s[k - fc] = alpha_s[k];
      m[k - fc] = m[k];
    }
  }
};

}  // namespace mptrack::mfbp
