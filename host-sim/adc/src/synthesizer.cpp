// Raw-ADC frame synthesizer; see synthesizer.h for the signal model.
#include "mptrack/adc/synthesizer.h"

#include <cmath>

#include "mptrack/frontend/frontend_params.h"
#include "mptrack/math/constants.h"
#include "mptrack/math/detmath.h"
#include "mptrack/scenario/rng.h"

namespace mptrack::adc {

namespace {

constexpr std::uint64_t kLayoutTag = 0x6c61796f75740004ULL;  // "layout" stream, seed 004
constexpr double kPi = dmath::kPi<double>;

double deg(double d) { return d * (kPi / 180.0); }

/// Swerling RCS draw: Gamma(shape, mean/shape), shape 1 (SW I) or 2 (SW III).
double draw_rcs(scenario::Rng& rng, int swerling, double mean) {
  const int shape = swerling == 3 ? 2 : 1;
  return rng.gamma_int(shape, mean / static_cast<double>(shape));
}

bool alive(std::uint32_t birth, std::uint32_t death, std::uint32_t n) { return n >= birth && n <= death; }

}  // namespace

Status FrameSynthesizer::init(const AdcScenario& s, std::uint64_t seed, std::uint32_t run, const SynthOptions& opt) {
  ready_ = false;
  error_ = validate(s);
  if (!error_.empty()) return Status::kInvalidArgument;
  spec_ = s;
  opt_ = opt;
  seed_ = seed;
  run_ = run;
  const RadarSpec& r = s.radar;
  lambda_m_ = frontend::kSpeedOfLight_mps / r.carrier_hz;
  kappa_ = r.bandwidth_hz / r.chirp_duration_s;
  // Same L as the front end's reference (frontend_params.h chirp_samples()).
  chirp_len_ = static_cast<std::size_t>(r.chirp_duration_s * r.sample_rate_hz + 0.5);
  if (chirp_len_ < 1 || chirp_len_ + 30 > AdcCaps::kNumSamples) {
    error_ = "radar.chirp_duration_s: chirp does not fit the " + std::to_string(AdcCaps::kNumSamples) +
             "-sample slot with room for 100 m of delay";
    return Status::kInvalidArgument;
  }
  t_mid_s_ = 0.5 * static_cast<double>(chirp_len_ - 1) / r.sample_rate_hz;
  const double noise_bw = r.noise_model == NoiseModel::kModelA ? r.sample_rate_hz : r.bandwidth_hz;
  noise_var_ = kBoltzmann_J_per_K * r.noise_temperature_k * noise_bw;

  // Scatterer layouts, fixed for the run.
  scenario::Rng rng(scenario::derive_seed(seed ^ kLayoutTag, run, 0));
  patches_.assign(s.clutter_patches.size(), {});
  for (std::size_t p = 0; p < s.clutter_patches.size(); ++p) {
    const ClutterPatchSpec& c = s.clutter_patches[p];
    for (std::uint32_t k = 0; k < c.scatterers; ++k) {
      // Uniform in area over the annular sector: r^2 uniform.
      const double u = rng.uniform();
      const double r2 = c.range_min_m * c.range_min_m + u * (c.range_max_m * c.range_max_m - c.range_min_m * c.range_min_m);
      const double rr = std::sqrt(r2);
      const double b = deg(c.bearing_min_deg + rng.uniform() * (c.bearing_max_deg - c.bearing_min_deg));
      double sb = 0.0, cb = 1.0;
      dmath::dsincos(b, sb, cb);
      patches_[p].push_back(Scatterer{rr * sb, rr * cb});
    }
  }
  chaff_.assign(s.chaff_clouds.size(), {});
  for (std::size_t q = 0; q < s.chaff_clouds.size(); ++q) {
    for (std::uint32_t k = 0; k < s.chaff_clouds[q].scatterers; ++k) {
      const double ox = rng.normal();
      const double oy = rng.normal();
      chaff_[q].push_back(Scatterer{ox, oy});
    }
  }
  ready_ = true;
  return Status::kOk;
}

double FrameSynthesizer::range_gain(double range_m) const {
  const double four_pi = 4.0 * kPi;
  return spec_.radar.tx_amplitude * spec_.radar.antenna_gain * lambda_m_ /
         (four_pi * std::sqrt(four_pi) * range_m * range_m);
}

void FrameSynthesizer::add_echo(AdcCube& cube, double range_m, double bearing_rad, double amp_re,
                                double amp_im) const {
  const double fs = spec_.radar.sample_rate_hz;
  const double tau = 2.0 * range_m / frontend::kSpeedOfLight_mps;
  // Steering phases, centred reference (docs/algorithms/scenarios.md §Seed 004):
  // 2 pi d (v - 4) sin(theta).
  const double u = dmath::dsin(bearing_rad);
  double a_re[kNumVirtual];
  double a_im[kNumVirtual];
  for (std::size_t v = 0; v < kNumVirtual; ++v) {
    const double ph = 2.0 * kPi * spec_.radar.element_spacing_wavelengths *
                      (static_cast<double>(v) - 4.0) * u;
    double s = 0.0, c = 1.0;
    dmath::dsincos(ph, s, c);
    a_re[v] = amp_re * c - amp_im * s;
    a_im[v] = amp_re * s + amp_im * c;
  }
  const double t_lo = -0.5 / fs;
  const double t_hi = (static_cast<double>(chirp_len_) - 0.5) / fs;
  for (std::size_t i = 0; i < AdcCaps::kNumSamples; ++i) {
    const double t = static_cast<double>(i) / fs - tau;
    if (t < t_lo || !(t < t_hi)) continue;
    const double dt = t - t_mid_s_;
    double s = 0.0, c = 1.0;
    dmath::dsincos(kPi * kappa_ * dt * dt, s, c);
    for (std::size_t v = 0; v < kNumVirtual; ++v) {
      const std::size_t m = v / AdcCaps::kNumRx;
      const std::size_t j = v % AdcCaps::kNumRx;
      const std::size_t o = AdcCube::offset(0, m, j, i);
      cube.iq[o] += static_cast<float>(a_re[v] * c - a_im[v] * s);
      cube.iq[o + 1] += static_cast<float>(a_re[v] * s + a_im[v] * c);
    }
  }
}

Status FrameSynthesizer::synthesize(std::uint32_t n, AdcCube& cube, std::vector<DroneTruth>& truth) const {
  truth.clear();
  if (!ready_ || n < 1 || n > spec_.num_frames) return Status::kInvalidArgument;
  const double dt = spec_.frame_period_s;
  const double t_s = static_cast<double>(n - 1) * dt;
  cube.time_us = static_cast<std::uint64_t>(t_s * 1e6 + 0.5);
  for (float& x : cube.iq) x = 0.0f;
  scenario::Rng rng(scenario::derive_seed(seed_, run_, n));

  // Order of draws is fixed: drones, patches, chaff, jammer, noise.
  for (const DroneSpec& d : spec_.drones) {
    if (!alive(d.birth_frame, d.death_frame, n)) continue;
    DroneTruth t;
    t.id = d.id;
    t.state = drone_state_at(d, n, dt);
    t.range_m = std::sqrt(t.state.x * t.state.x + t.state.y * t.state.y);
    t.bearing_rad = dmath::datan2(t.state.x, t.state.y);
    t.snr_mean = mean_component_snr(spec_, t.range_m, d.mean_rcs_m2);
    double phase = 0.0;
    t.rcs_m2 = d.mean_rcs_m2;
    if (opt_.fluctuate) {
      t.rcs_m2 = draw_rcs(rng, d.swerling, d.mean_rcs_m2);
      phase = 2.0 * kPi * rng.uniform();
    }
    const double a = std::sqrt(t.rcs_m2) * range_gain(t.range_m);
    double s = 0.0, c = 1.0;
    dmath::dsincos(phase, s, c);
    if (t.state.y > 0.0 && t.range_m > 0.0) add_echo(cube, t.range_m, t.bearing_rad, a * c, a * s);
    truth.push_back(t);
  }
  // Swerling-1 scatterer: complex Gaussian amplitude, E|a|^2 = rcs rho^2.
  const auto scatter = [&](double x, double y, double mean_rcs) {
    const double r = std::sqrt(x * x + y * y);
    if (!(y > 0.0) || !(r > 0.5)) return;
    const double sd = std::sqrt(0.5 * mean_rcs) * range_gain(r);
    const double re = sd * rng.normal();
    const double im = sd * rng.normal();
    add_echo(cube, r, dmath::datan2(x, y), re, im);
  };
  for (std::size_t p = 0; p < patches_.size(); ++p) {
    const ClutterPatchSpec& c = spec_.clutter_patches[p];
    if (!alive(c.birth_frame, c.death_frame, n)) continue;
    for (const Scatterer& sc : patches_[p]) scatter(sc.x, sc.y, c.mean_rcs_m2);
  }
  for (std::size_t q = 0; q < chaff_.size(); ++q) {
    const ChaffCloudSpec& c = spec_.chaff_clouds[q];
    if (!alive(c.birth_frame, c.death_frame, n)) continue;
    const double age = static_cast<double>(n - c.birth_frame) * dt;
    const double cx = c.centre_m[0] + c.drift_mps[0] * age;
    const double cy = c.centre_m[1] + c.drift_mps[1] * age;
    const double sig = c.sigma0_m + c.growth_mps * age;
    for (const Scatterer& sc : chaff_[q]) scatter(cx + sig * sc.x, cy + sig * sc.y, c.mean_rcs_m2);
  }
  for (const JammerSpec& j : spec_.jammers) {
    if (!alive(j.birth_frame, j.death_frame, n)) continue;
    const double total = noise_var_ * dmath::dexp(j.jnr_db * (dmath::kLn10<double> / 10.0));
    const double sd = std::sqrt(0.5 * total / static_cast<double>(j.sources));
    for (std::uint32_t q = 0; q < j.sources; ++q) {
      const double f = j.sources == 1 ? 0.5 : static_cast<double>(q) / static_cast<double>(j.sources - 1);
      const double u = dmath::dsin(deg(j.bearing_min_deg + f * (j.bearing_max_deg - j.bearing_min_deg)));
      double st_re[kNumVirtual], st_im[kNumVirtual];
      for (std::size_t v = 0; v < kNumVirtual; ++v) {
        dmath::dsincos(2.0 * kPi * spec_.radar.element_spacing_wavelengths * (static_cast<double>(v) - 4.0) * u,
                       st_im[v], st_re[v]);
      }
      for (std::size_t m = 0; m < AdcCaps::kNumTx; ++m) {
        for (std::size_t i = 0; i < AdcCaps::kNumSamples; ++i) {
          const double gr = sd * rng.normal();
          const double gi = sd * rng.normal();
          for (std::size_t jr = 0; jr < AdcCaps::kNumRx; ++jr) {
            const std::size_t v = m * AdcCaps::kNumRx + jr;
            const std::size_t o = AdcCube::offset(0, m, jr, i);
            cube.iq[o] += static_cast<float>(gr * st_re[v] - gi * st_im[v]);
            cube.iq[o + 1] += static_cast<float>(gr * st_im[v] + gi * st_re[v]);
          }
        }
      }
    }
  }
  if (opt_.noise) {
    const double sd = std::sqrt(0.5 * noise_var_);
    for (float& x : cube.iq) x += static_cast<float>(sd * rng.normal());
  }
  return Status::kOk;
}

}  // namespace mptrack::adc
