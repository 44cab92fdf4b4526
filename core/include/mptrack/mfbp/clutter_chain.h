// The clutter part of one MF sweep (seed 000 Algorithm 1 lines 4 and 6):
// the Dirichlet mixing weights (eq. (69)-(73)), then per component the
// Normal-Wishart spatial chain (eq. (50)-(61)) and the CNR inverse-gamma
// chain (eq. (62)-(63)), and the uniform component's CNR chain.
//
// Every chain is a forward filter over the window followed by a backward
// pass of forgotten sufficient statistics (the smoother of
// docs/algorithms/mfbp.md §Clutter chain): the smoothed belief at k is the
// filtered one updated with g * (stats(k+1) + g * (stats(k+2) + ...)), g
// the chain's forgetting gain. The statistics come from the association of
// each window scan (WindowStore's nw_stats / amp_stats per source slot).
#pragma once

#include <array>
#include <cstddef>

#include "mptrack/mfbp/clutter_slot.h"
#include "mptrack/mfbp/dirichlet.h"
#include "mptrack/mfbp/mfbp_params.h"
#include "mptrack/mfbp/model_constants.h"
#include "mptrack/mfbp/window_store.h"

namespace mptrack::mfbp {

/// Dirichlet forward filter (alpha_f, M_k) and backward statistics (alpha_s)
/// over the n window scans; source slots of dead components stay 0.
template <class T, class Caps>
void dirichlet_chain(ClutterTable<T, Caps>& cl, const WindowStore<T, Caps>& store, std::size_t n,
                     const MfbpParams<T>& p) {
  constexpr std::size_t kSources = ClutterTable<T, Caps>::kSources;
  std::array<T, kSources> alpha_prev{}, alpha_pred{}, counts{};
  for (std::size_t src = 0; src < kSources; ++src) {
    alpha_prev[src] = src == 0 ? cl.uniform.alpha0 : (cl.comps[src - 1].alive ? cl.comps[src - 1].alpha0 : T(0));
  }
  T m_prev = cl.m_prev;
  for (std::size_t k = 0; k < n; ++k) {
    dirichlet_predict(alpha_prev.data(), alpha_pred.data(), kSources, p.dirichlet_kappa, m_prev);
    T m_k = T(0);
    for (std::size_t src = 0; src < kSources; ++src) {
      const bool live = src == 0 || cl.comps[src - 1].alive;
      counts[src] = live ? store.win(k).amp_stats[src].w : T(0);
      if (!live) alpha_pred[src] = T(0);
      m_k += counts[src];
      cl.alpha_f[k][src] = live ? alpha_pred[src] + counts[src] : T(0);
    }
    // A scan without association results carries the predicted count.
    if (!store.win(k).has_beliefs) m_k = m_prev;
    cl.m[k] = m_k;
    m_prev = m_k;
    alpha_prev = cl.alpha_f[k];
  }
  // Backward statistics smoother for the Dirichlet, g = kappa/(kappa+1).
  const T g_d = p.dirichlet_kappa / (p.dirichlet_kappa + T(1));
  std::array<T, kSources> B{};
  for (std::size_t kk = n; kk-- > 0;) {
    if (kk + 1 < n) {
      for (std::size_t src = 0; src < kSources; ++src) B[src] = g_d * (B[src] + store.win(kk + 1).amp_stats[src].w);
    }
    for (std::size_t src = 0; src < kSources; ++src) {
      cl.alpha_s[kk][src] = cl.alpha_f[kk][src] > T(0) ? cl.alpha_f[kk][src] + B[src] : T(0);
    }
  }
}

/// CNR inverse-gamma chain of the uniform clutter (source slot 0).
template <class T, class Caps>
void uniform_cnr_chain(UniformSlot<T, Caps>& u, const WindowStore<T, Caps>& store, std::size_t n,
                       const MfbpParams<T>& p, int n_order) {
  using IG = model::InverseGamma<T>;
  const T g_ig = T(1) / p.forgetting_clutter;
  const T tn = T(n_order);
  IG prev = u.ig0;
  for (std::size_t k = 0; k < n; ++k) {
    IG f = prev.predicted(p.forgetting_clutter);
    if (p.amplitude.use_amplitude) {
      f.update(tn * store.win(k).amp_stats[0].w, tn * store.win(k).amp_stats[0].s);
    }
    u.igf[k] = f;
    prev = f;
  }
  AmplitudeStats<T> B_amp{};
  for (std::size_t kk = n; kk-- > 0;) {
    if (kk + 1 < n) {
      B_amp.w = g_ig * (B_amp.w + store.win(kk + 1).amp_stats[0].w);
      B_amp.s = g_ig * (B_amp.s + store.win(kk + 1).amp_stats[0].s);
    }
    IG s = u.igf[kk];
    if (p.amplitude.use_amplitude) s.update(tn * B_amp.w, tn * B_amp.s);
    u.igs[kk] = s;
  }
}

/// NW and CNR chains of one live component, source slot src.
template <class T, class Caps>
void component_chain(CompSlot<T, Caps>& cs, std::size_t src, const WindowStore<T, Caps>& store,
                     std::size_t n, const MfbpParams<T>& p, int n_order) {
  using IG = model::InverseGamma<T>;
  using NW = NormalWishart<T>;
  const T g_ig = T(1) / p.forgetting_clutter;
  const T tn = T(n_order);
  NW nw_prev = cs.nw0;
  IG ig_prev = cs.ig0;
  for (std::size_t k = 0; k < n; ++k) {
    NW nw = nw_prev.predicted(p.nw_forgetting_factor, p.nw_forgetting);
    nw.update(store.win(k).nw_stats[src]);
    cs.nwf[k] = nw;
    nw_prev = nw;
    IG ig = ig_prev.predicted(p.forgetting_clutter);
    if (p.amplitude.use_amplitude) {
      ig.update(tn * store.win(k).amp_stats[src].w, tn * store.win(k).amp_stats[src].s);
    }
    cs.igf[k] = ig;
    ig_prev = ig;
  }
  NwStats<T> B_nw{};
  AmplitudeStats<T> B_amp{};
  for (std::size_t kk = n; kk-- > 0;) {
    if (kk + 1 < n) {
      B_nw.accumulate(store.win(kk + 1).nw_stats[src]);
      B_nw.scale(p.nw_forgetting_factor);
      B_amp.w = g_ig * (B_amp.w + store.win(kk + 1).amp_stats[src].w);
      B_amp.s = g_ig * (B_amp.s + store.win(kk + 1).amp_stats[src].s);
    }
    NW s = cs.nwf[kk];
    s.update(B_nw);
    cs.nws[kk] = s;
    IG is = cs.igf[kk];
    if (p.amplitude.use_amplitude) is.update(tn * B_amp.w, tn * B_amp.s);
    cs.igs[kk] = is;
  }
}

/// The clutter sweep over the n window scans (Dirichlet, uniform CNR, and
/// the components when they are estimated).
template <class T, class Caps>
void clutter_sweep(ClutterTable<T, Caps>& cl, const WindowStore<T, Caps>& store, std::size_t n,
                   const MfbpParams<T>& p, int n_order) {
  dirichlet_chain(cl, store, n, p);
  uniform_cnr_chain(cl.uniform, store, n, p, n_order);
  if (!estimate_clutter(p)) return;
  for (std::size_t c = 0; c < ClutterTable<T, Caps>::kMaxComp; ++c) {
    if (cl.comps[c].alive) component_chain(cl.comps[c], c + 1, store, n, p, n_order);
  }
}

}  // namespace mptrack::mfbp
