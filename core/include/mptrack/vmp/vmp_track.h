// One potential object of the VMP tracker: identity, chain, existence, and the
// per-frame quantities of the current frame (docs/algorithms/vmp.md §Per-frame schedule).
#pragma once

#include <cstddef>
#include <cstdint>

#include "mptrack/model/mimo_atom.h"
#include "mptrack/vmp/track_chain.h"

namespace mptrack::vmp {

template <class T, std::size_t W, std::size_t NV, std::size_t KB>
struct VmpTrack {
  std::uint32_t id = 0;
  TrackChain<T, W> chain;
  T logit_xi = T(0);      ///< log-odds of xi at the current frame
  T xi_prev = T(0);       ///< xi of the previous frame (eq. (17) input)
  T g = T(0);             ///< prior log-odds this frame (eq. (17))
  Vec4<T> x_gamma = Vec4<T>::Zero();  ///< state whose position the atom is at
  Mat4<T> p_gamma = Mat4<T>::Zero();  ///< its covariance (delta-method trace of Gamma_kk)
  model::Cx<T> mu{};      ///< amplitude mean (whitened, normalised)
  T snr = T(0);           ///< (|mu|^2 + C_kk) Gamma_kk
  model::MimoAtom<T, NV, KB> atom;  ///< at (x_gamma(0), x_gamma(2))
};

}  // namespace mptrack::vmp
