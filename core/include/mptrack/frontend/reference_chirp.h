// The reference chirp every raw-frame stage correlates with: the matched
// filter of the front end (range_matched_filter.h) and the whitened spectrum of
// the raw-frame methods (mimo_spectrum.h) must use the same samples as the
// synthesiser, so they are written once here (docs/algorithms/frontend.md
// §Range matched filter): L = round(T_Tx f_s) samples,
//   u[i] = e^{j pi kappa t_i^2},  t_i = (i - (L-1)/2) / f_s,  kappa = BW / T_Tx,
// centred so that it sweeps -BW/2..+BW/2. Double precision, init() only.
#pragma once

#include <cstddef>

#include "mptrack/math/constants.h"
#include "mptrack/math/detmath.h"

namespace mptrack::frontend {

/// L = round(T_Tx f_s); 0 for NaN or a length beyond any cap ("does not fit":
/// casting an out-of-range double is undefined, fuzz finding F6).
inline std::size_t chirp_length(double chirp_duration_s, double sample_rate_hz) {
  const double x = chirp_duration_s * sample_rate_hz + 0.5;
  return (x >= 1.0 && x < 1e9) ? static_cast<std::size_t>(x) : std::size_t{0};
}

class ReferenceChirp {
 public:
  /// len = chirp_length(chirp_duration_s, sample_rate_hz), >= 1.
  ReferenceChirp(double bandwidth_hz, double chirp_duration_s, double sample_rate_hz, std::size_t len)
      : kappa_(bandwidth_hz / chirp_duration_s), centre_(0.5 * static_cast<double>(len - 1)), fs_(sample_rate_hz) {}

  /// u[i] as (re, im), i < len.
  void sample(std::size_t i, double& re, double& im) const {
    const double t = (static_cast<double>(i) - centre_) / fs_;
    im = 0.0;
    re = 1.0;
    dmath::dsincos(dmath::kPi<double> * kappa_ * t * t, im, re);
  }

  /// The continuous chirp at a fractional sample position x (sidelobe
  /// envelopes, sidelobe_filter.h); equals sample(i) at x = i.
  void sample_at(double x, double& re, double& im) const {
    const double t = (x - centre_) / fs_;
    im = 0.0;
    re = 1.0;
    dmath::dsincos(dmath::kPi<double> * kappa_ * t * t, im, re);
  }

 private:
  double kappa_;   ///< chirp rate BW / T_Tx [Hz/s]
  double centre_;  ///< (L - 1) / 2 [samples]
  double fs_;      ///< [Hz]
};

}  // namespace mptrack::frontend
