// MF-BP's inverse-gamma SNR belief: model/inverse_gamma.h (forwarded), and
// the weighted amplitude statistics MF-BP feeds its conjugate update.
#pragma once

#include "mptrack/model/inverse_gamma.h"

namespace mptrack::mfbp {

using model::InverseGamma;

/// Weighted amplitude statistics of one scan for one source (docs/algorithms/mfbp.md
/// §Clutter chain, §Target chain):
/// w = sum a_j, s = sum a_j (m_j^2 - d^2). The IG update uses n w and n s.
template <class T>
struct AmplitudeStats {
  T w = T(0);
  T s = T(0);
};

}  // namespace mptrack::mfbp
