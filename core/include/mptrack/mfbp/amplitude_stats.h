// The weighted amplitude statistics MF-BP feeds the conjugate update of an
// inverse-gamma power belief (model/inverse_gamma.h), one per scan and source.
#pragma once

namespace mptrack::mfbp {

/// Weighted amplitude statistics of one scan for one source
/// (docs/algorithms/mfbp.md §Clutter chain): w = sum a_j,
/// s = sum a_j (m_j^2 - d^2). The IG update uses n w and n s.
template <class T>
struct AmplitudeStats {
  T w = T(0);
  T s = T(0);
};

}  // namespace mptrack::mfbp
