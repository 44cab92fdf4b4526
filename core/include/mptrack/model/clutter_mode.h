// How a tracker models clutter: the one ClutterMode of every tracker.
// Clutter is Poisson in measurement space with intensity
//   kappa(z, a) = lambda_0 / V g_0(a) + sum_c lambda_c N(z; mu_c, C_c) g_c(a)
// (a uniform part over the region of volume V plus Gaussian sources; seed
// 000 Sec. II, seed 001 Sec. III). A mode says which parts exist and which
// of their rates and amplitude scales are known or estimated online.
// Not every tracker implements every mode; each tracker's validate()
// rejects the ones it does not (MF-BP: kEstimatedMap, kKnownRateUniform,
// kKnownMap; GM-PHD, GM-CPHD, CBMeMBer: kEstimatedMap, kEstimatedUniform,
// kKnownUniform).
#pragma once

#include <cstdint>

namespace mptrack::model {

enum class ClutterMode : std::uint8_t {
  /// Uniform + Gaussian sources, all estimated online (MP-RMTT; the IGGM
  /// filters' clutter map). The default of every tracker.
  kEstimatedMap,
  /// Uniform only; rate and amplitude scale estimated online (lambda-CPHD style).
  kEstimatedUniform,
  /// Uniform only; known rate, amplitude scale (CNR) estimated online (MP-RMTT-NCE).
  kKnownRateUniform,
  /// Uniform only; known rate and known amplitude scale (GM-CPHD of Vo 2007).
  kKnownUniform,
  /// Uniform + Gaussian sources given exactly (MP-RMTT-KCE).
  kKnownMap,

  // MF-BP's earlier spellings (same enumerators).
  kEstimate = kEstimatedMap,
  kUniformKnownRate = kKnownRateUniform,
  kKnown = kKnownMap,
};

}  // namespace mptrack::model
