// Test-side signal synthesis for the front-end tests (not part of core).
//
// Everything here is deterministic across targets (integer PRNG, dmath for
// transcendental functions), so golden tests can use it too: the inputs are
// bit-identical on x86-64, aarch64 and armhf.
#pragma once

#include <cstddef>
#include <cstdint>

#include "mptrack/frontend/frontend_params.h"
#include "mptrack/frontend/radar_cube.h"
#include "mptrack/math/constants.h"
#include "mptrack/math/detmath.h"

namespace mptrack::test {

/// xorshift64* PRNG with Box-Muller normals (dmath), identical everywhere.
class DetRng {
 public:
  explicit DetRng(std::uint64_t seed) : state_(seed ? seed : 0x9e3779b97f4a7c15ull) {}
  std::uint64_t next_u64() {
    state_ ^= state_ >> 12;
    state_ ^= state_ << 25;
    state_ ^= state_ >> 27;
    return state_ * 0x2545f4914f6cdd1dull;
  }
  /// Uniform in (0, 1), 53 bits.
  double uniform() { return (static_cast<double>(next_u64() >> 11) + 0.5) * 0x1.0p-53; }
  /// Pair of independent N(0, 1) values.
  void normal_pair(double& a, double& b) {
    const double r = mptrack::dmath::kSqrt2<double> * sqrt_det(-mptrack::dmath::dlog(uniform()));
    double s = 0.0;
    double c = 1.0;
    mptrack::dmath::dsincos(mptrack::dmath::kTwoPi<double> * uniform(), s, c);
    a = r * c;
    b = r * s;
  }

 private:
  static double sqrt_det(double x) {  // IEEE sqrt is correctly rounded everywhere
    return __builtin_sqrt(x);
  }
  std::uint64_t state_;
};

/// One point target for the synthesizer.
struct SynthTarget {
  double range_m = 0.0;
  double bearing_rad = 0.0;  ///< from boresight (+y) towards +x
  double radial_mps = 0.0;   ///< positive receding
  double amplitude = 1.0;    ///< echo amplitude per sample [linear]
  double phase_rad = 0.0;
};

/// Reference chirp sample at (possibly fractional) index i; zero outside [0, L).
inline void chirp_sample(const mptrack::frontend::FrontEndParams& p, double i, double& re,
                         double& im) {
  const std::size_t len = mptrack::frontend::chirp_samples(p);
  if (i < 0.0 || i >= static_cast<double>(len)) {
    re = 0.0;
    im = 0.0;
    return;
  }
  const double kappa = p.bandwidth_hz / p.chirp_duration_s;
  const double t = (i - 0.5 * static_cast<double>(len - 1)) / p.sample_rate_hz;
  mptrack::dmath::dsincos(mptrack::dmath::kPi<double> * kappa * t * t, im, re);
}

/// Adds targets (and complex white noise of per-sample variance noise_var, if > 0) to a
/// float cube: the seed 004 signal model with the Doppler extension
/// (docs/algorithms/frontend.md §Signal model, §Doppler), far field, stop-and-hop within a
/// chirp.
template <class Caps>
void synthesize(const mptrack::frontend::FrontEndParams& p, const SynthTarget* targets,
                std::size_t num_targets, double noise_var, std::uint64_t seed,
                mptrack::frontend::RadarCube<Caps>& cube) {
  using mptrack::dmath::dsincos;
  using mptrack::dmath::kTwoPi;
  const double lambda = mptrack::frontend::wavelength_m(p);
  DetRng rng(seed);
  const double sigma = __builtin_sqrt(noise_var > 0.0 ? noise_var / 2.0 : 0.0);
  for (std::size_t c = 0; c < Caps::kNumChirps; ++c) {
    for (std::size_t m = 0; m < Caps::kNumTx; ++m) {
      for (std::size_t j = 0; j < Caps::kNumRx; ++j) {
        const std::size_t v = m * Caps::kNumRx + j;
        for (std::size_t s = 0; s < Caps::kNumSamples; ++s) {
          double acc_re = 0.0;
          double acc_im = 0.0;
          for (std::size_t k = 0; k < num_targets; ++k) {
            const SynthTarget& t = targets[k];
            double delay = 2.0 * t.range_m / mptrack::frontend::kSpeedOfLight_mps *
                           p.sample_rate_hz;
            // Snap round-off (range = integer * bin) to the integer delay.
            const double nearest = static_cast<double>(static_cast<long long>(delay + 0.5));
            if (delay - nearest < 1e-9 && nearest - delay < 1e-9) delay = nearest;
            double ur = 0.0;
            double ui = 0.0;
            chirp_sample(p, static_cast<double>(s) - delay, ur, ui);
            double sb = 0.0;
            double cb = 1.0;
            dsincos(t.bearing_rad, sb, cb);
            const double ph = t.phase_rad +
                              kTwoPi<double> * p.element_spacing_wavelengths *
                                  static_cast<double>(v) * sb -
                              2.0 * kTwoPi<double> * t.radial_mps * static_cast<double>(c) *
                                  p.chirp_repetition_s / lambda;
            double sp = 0.0;
            double cp = 1.0;
            dsincos(ph, sp, cp);
            acc_re += t.amplitude * (ur * cp - ui * sp);
            acc_im += t.amplitude * (ur * sp + ui * cp);
          }
          if (sigma > 0.0) {
            double a = 0.0;
            double b = 0.0;
            rng.normal_pair(a, b);
            acc_re += sigma * a;
            acc_im += sigma * b;
          }
          const std::size_t o = mptrack::frontend::RadarCube<Caps>::offset(c, m, j, s);
          cube.iq[o] = static_cast<float>(acc_re);
          cube.iq[o + 1] = static_cast<float>(acc_im);
        }
      }
    }
  }
}

}  // namespace mptrack::test

namespace mptrack::test {

/// Parameters that fit SmallDopplerRadarCaps (64 samples, 32 range bins):
/// 1 us chirp at 32 MHz = 32 samples, 100 us chirp repetition.
inline mptrack::frontend::FrontEndParams small_doppler_params() {
  mptrack::frontend::FrontEndParams p;
  p.chirp_duration_s = 1e-6;
  p.chirp_repetition_s = 100e-6;
  p.doppler_window = mptrack::frontend::WindowType::kRectangular;
  p.max_range_m = 150.0;
  p.cfar.guard_cells = 1;
  p.cfar.training_cells = 4;
  p.max_detections = 16;
  return p;
}

}  // namespace mptrack::test
