// Sea-clutter scene synthesis (docs/algorithms/sea_clutter.md §Scene model).
#include "mptrack/sea/sea_generator.h"

#include <cmath>
#include <stdexcept>

#include "mptrack/math/detmath.h"

namespace mptrack::sea {

namespace {

using mptrack::scenario::derive_seed;
using mptrack::scenario::Rng;

constexpr double kTwoPi = 6.283185307179586;

/// Stream tags for derive_seed, so each random quantity has its own stream.
enum Stream : std::uint64_t { kTargets = 1, kTexture = 2, kSpeckle = 3, kNoise = 4, kAmplitude = 5 };

/// exp(j 2 pi cycles) without a large argument: the integer part of
/// `cycles` is dropped in double first.
void unit_phasor(double cycles, double& c, double& s) {
  const double frac = cycles - static_cast<double>(static_cast<long long>(cycles));
  mptrack::dmath::dsincos(kTwoPi * frac, s, c);
}

/// Fraction of [lo, hi) that falls in [a, b).
double overlap(double lo, double hi, double a, double b) {
  const double l = lo > a ? lo : a;
  const double h = hi < b ? hi : b;
  return h > l ? (h - l) / (hi - lo) : 0.0;
}

}  // namespace

SeaSceneGenerator::SeaSceneGenerator(const SeaScenario& scenario, std::uint64_t seed)
    : sc_(scenario), seed_(seed) {
  const std::string bad = sc_.validate();
  if (!bad.empty()) throw std::invalid_argument("sea scenario '" + sc_.name + "': invalid " + bad);
  (void)fft_.init();
  const std::size_t comps = static_cast<std::size_t>(2.0 * sc_.k_shape);
  gauss_.assign(comps * sc_.range_bins, 0.0);
  texture_.assign(sc_.range_bins, 1.0);
  place_targets();
}

void SeaSceneGenerator::place_targets() {
  Rng rng(derive_seed(seed_, kTargets));
  drift_phase_rad_ = kTwoPi * rng.uniform();
  const double lambda = sc_.wavelength_m();
  const double duration = (sc_.num_scans - 1) * sc_.scan_period_s + sc_.pulses / sc_.prf_hz;
  const double lo = sc_.edge_margin_bins * sc_.range_bin_m;
  const double hi = (sc_.range_bins - 1 - sc_.edge_margin_bins) * sc_.range_bin_m;
  targets_.clear();
  for (std::uint32_t i = 0; i < sc_.num_targets; ++i) {
    Target t;
    double travel = 0.0;
    for (int attempt = 0; attempt < 1000; ++attempt) {
      const double f = sc_.target_doppler_min_hz +
                       (sc_.target_doppler_max_hz - sc_.target_doppler_min_hz) * rng.uniform();
      t.rdot_mps = -f * lambda / 2.0;
      travel = t.rdot_mps * duration;
      if ((travel < 0.0 ? -travel : travel) < hi - lo) break;
    }
    // Start so that the whole track stays within [lo, hi].
    const double start_lo = travel < 0.0 ? lo - travel : lo;
    const double start_hi = travel < 0.0 ? hi : hi - travel;
    t.r0_m = start_lo + (start_hi > start_lo ? (start_hi - start_lo) * rng.uniform() : 0.0);
    t.length_m = sc_.target_length_min_m + (sc_.target_length_max_m - sc_.target_length_min_m) * rng.uniform();
    t.phase_rad = kTwoPi * rng.uniform() - kTwoPi / 2.0;
    t.log_amp = sc_.target_amp_log_sd * rng.normal();
    targets_.push_back(t);
  }
}

// Texture tau(m, k) = (1 / 2nu) sum_c g_c(m, k)^2 with each g_c a unit
// Gaussian, AR(1) along range (coefficient texture_range_corr) and AR(1)
// across scans (exp(-T / texture_corr_time)): a chi-square with 2nu degrees
// of freedom over 2nu, i.e. Gamma(nu, 1/nu) with mean 1, correlated in range
// and time (docs/algorithms/sea_clutter.md eq. (2)).
void SeaSceneGenerator::step_texture(std::uint32_t scan) {
  Rng rng(derive_seed(seed_, kTexture, scan));
  const std::size_t comps = gauss_.size() / sc_.range_bins;
  const double rho_t = scan == 0 ? 0.0 : mptrack::dmath::dexp(-sc_.scan_period_s / sc_.texture_corr_time_s);
  const double rho_r = sc_.texture_range_corr;
  const double a_t = std::sqrt(1.0 - rho_t * rho_t);
  const double a_r = std::sqrt(1.0 - rho_r * rho_r);
  for (std::size_t c = 0; c < comps; ++c) {
    double e = rng.normal();
    for (std::size_t m = 0; m < sc_.range_bins; ++m) {
      if (m > 0) e = rho_r * e + a_r * rng.normal();
      double& g = gauss_[c * sc_.range_bins + m];
      g = rho_t * g + a_t * e;
    }
  }
  for (std::size_t m = 0; m < sc_.range_bins; ++m) {
    double s = 0.0;
    for (std::size_t c = 0; c < comps; ++c) s += gauss_[c * sc_.range_bins + m] * gauss_[c * sc_.range_bins + m];
    texture_[m] = s / static_cast<double>(comps);
  }
}

// Speckle of each range bin: a unit-power complex Gaussian sequence with a
// Gaussian Doppler spectrum S(f) ~ exp(-(f - f0)^2 / (2 sigma^2)) (wrapped at
// +-PRF/2), drawn in the frequency domain (X_b = sqrt(S_b) CN(0, 1)) and
// inverse transformed; then x = sqrt(P_c tau) s + n
// (docs/algorithms/sea_clutter.md eqs. (1), (3)).
void SeaSceneGenerator::synthesize_clutter(SeaScan& out, double time_s) {
  const std::size_t n_p = sc_.pulses;
  const double pc = mptrack::dmath::dexp(sc_.cnr_db / 10.0 * 2.302585092994046);
  const double df = sc_.doppler_bin_hz();
  Rng speckle(derive_seed(seed_, kSpeckle, scan_));
  Rng noise(derive_seed(seed_, kNoise, scan_));
  const double drift = sc_.doppler_drift_hz * mptrack::dmath::dsin(kTwoPi * time_s / sc_.doppler_drift_period_s +
                                                                   drift_phase_rad_);
  std::vector<double> spec(n_p);
  float re[512];
  float im[512];
  double power_sum = 0.0;
  for (std::size_t m = 0; m < sc_.range_bins; ++m) {
    const double pos = static_cast<double>(m) / static_cast<double>(sc_.range_bins - 1) - 0.5;
    const double f0 = sc_.doppler_centre_hz + sc_.doppler_centre_slope_hz * pos + drift +
                      sc_.doppler_jitter_hz * speckle.normal();
    const double sigma =
        sc_.doppler_width_hz * mptrack::dmath::dexp(sc_.doppler_width_log_sd * gauss_[m]);
    double total = 0.0;
    for (std::size_t b = 0; b < n_p; ++b) {
      // FFT bin b is frequency b * df for b < N/2, (b - N) * df above.
      double f = (b < n_p / 2 ? static_cast<double>(b) : static_cast<double>(b) - static_cast<double>(n_p)) * df - f0;
      while (f > sc_.prf_hz / 2.0) f -= sc_.prf_hz;
      while (f < -sc_.prf_hz / 2.0) f += sc_.prf_hz;
      spec[b] = mptrack::dmath::dexp(-f * f / (2.0 * sigma * sigma));
      total += spec[b];
    }
    const double amp = std::sqrt(pc * texture_[m] / total / 2.0);
    for (std::size_t b = 0; b < n_p; ++b) {
      const double a = amp * std::sqrt(spec[b]);
      re[b] = static_cast<float>(a * speckle.normal());
      im[b] = static_cast<float>(a * speckle.normal());
    }
    fft_.inverse(re, im);
    const double sn = std::sqrt(out.noise_power / 2.0);
    for (std::size_t p = 0; p < n_p; ++p) {
      const double cr = static_cast<double>(re[p]);
      const double ci = static_cast<double>(im[p]);
      power_sum += cr * cr + ci * ci;
      out.re[m * n_p + p] = static_cast<float>(cr + sn * noise.normal());
      out.im[m * n_p + p] = static_cast<float>(ci + sn * noise.normal());
    }
  }
  out.clutter_power = power_sum / static_cast<double>(sc_.range_bins * n_p);
}

// Target echo (seed 003 eq. (3)): s(m, p) = sqrt(P_t omega(m)) a(p)
// exp(j phi - j 4 pi R(p) / lambda), P_t = 10^(SCR/10) P_c, omega(m) the
// fraction of the target's radial length in bin m (at the CPI centre), a(p)
// = exp(l(p) - sd^2) with l a Gauss-Markov log amplitude (E a^2 = 1).
void SeaSceneGenerator::inject_targets(SeaScan& out, double time_s) {
  const std::size_t n_p = sc_.pulses;
  const double lambda = sc_.wavelength_m();
  const double pri = 1.0 / sc_.prf_hz;
  const double pt = mptrack::dmath::dexp(sc_.scr_db / 10.0 * 2.302585092994046) * out.clutter_power;
  const double rho_p = mptrack::dmath::dexp(-pri / sc_.target_amp_corr_s);
  const double rho_scan = mptrack::dmath::dexp(-(sc_.scan_period_s - static_cast<double>(n_p) * pri) / sc_.target_amp_corr_s);
  const double sd = sc_.target_amp_log_sd;
  Rng rng(derive_seed(seed_, kAmplitude, scan_));
  const double t_mid = time_s + 0.5 * static_cast<double>(n_p) * pri;
  out.truth.clear();
  for (std::size_t i = 0; i < targets_.size(); ++i) {
    Target& t = targets_[i];
    SeaTruth truth;
    truth.id = static_cast<std::uint32_t>(i + 1);
    truth.range_m = t.r0_m + t.rdot_mps * t_mid;
    truth.range_rate_mps = t.rdot_mps;
    truth.doppler_hz = -2.0 * t.rdot_mps / lambda;
    truth.range_bin = truth.range_m / sc_.range_bin_m;
    truth.doppler_bin = static_cast<double>(n_p) / 2.0 + truth.doppler_hz / sc_.doppler_bin_hz();
    out.truth.push_back(truth);
    if (scan_ > 0) t.log_amp = rho_scan * t.log_amp + std::sqrt(1.0 - rho_scan * rho_scan) * sd * rng.normal();
    const double half = t.length_m / 2.0;
    for (std::size_t m = 0; m < sc_.range_bins; ++m) {
      const double c = static_cast<double>(m) * sc_.range_bin_m;
      const double omega = overlap(truth.range_m - half, truth.range_m + half, c - sc_.range_bin_m / 2.0,
                                   c + sc_.range_bin_m / 2.0);
      if (omega <= 0.0) continue;
      double l = t.log_amp;
      Rng amp_rng(derive_seed(seed_, kAmplitude + 16 * (i + 1), scan_));  // same a(p) in every bin
      const double a0 = std::sqrt(pt * omega);
      for (std::size_t p = 0; p < n_p; ++p) {
        if (p > 0) l = rho_p * l + std::sqrt(1.0 - rho_p * rho_p) * sd * amp_rng.normal();
        const double range = t.r0_m + t.rdot_mps * (time_s + static_cast<double>(p) * pri);
        double c_ph = 0.0;
        double s_ph = 0.0;
        unit_phasor(t.phase_rad / kTwoPi - 2.0 * range / lambda, c_ph, s_ph);
        const double a = a0 * mptrack::dmath::dexp(l - sd * sd);
        out.re[m * n_p + p] += static_cast<float>(a * c_ph);
        out.im[m * n_p + p] += static_cast<float>(a * s_ph);
      }
    }
  }
}

bool SeaSceneGenerator::next(SeaScan& out) {
  if (scan_ >= sc_.num_scans) return false;
  const double time_s = scan_ * sc_.scan_period_s;
  out.index = scan_;
  out.time_s = time_s;
  out.noise_power = 1.0;
  out.re.assign(static_cast<std::size_t>(sc_.range_bins) * sc_.pulses, 0.0f);
  out.im.assign(out.re.size(), 0.0f);
  step_texture(scan_);
  synthesize_clutter(out, time_s);
  inject_targets(out, time_s);
  ++scan_;
  return true;
}

}  // namespace mptrack::sea
