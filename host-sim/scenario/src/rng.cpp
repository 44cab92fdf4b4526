// Deterministic RNG transforms; see rng.h for the why.
#include "mptrack/scenario/rng.h"

#include <cmath>

#include "mptrack/math/detmath.h"

namespace mptrack::scenario {

namespace {
constexpr double kTwoPi = 6.283185307179586476925286766559;
constexpr double kPoissonChunk = 30.0;  // exp(-30) = 9.4e-14: far from underflow

constexpr std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
}  // namespace

void Rng::reseed(std::uint64_t seed) {
  std::uint64_t x = seed;
  for (auto& w : s_) {
    x += 0x9e3779b97f4a7c15ULL;
    w = splitmix64(x);
  }
  has_cached_normal_ = false;
  cached_normal_ = 0.0;
}

std::uint64_t Rng::next() {
  // xoshiro256** 1.0, reference implementation order.
  const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
  const std::uint64_t t = s_[1] << 17;
  s_[2] ^= s_[0];
  s_[3] ^= s_[1];
  s_[1] ^= s_[2];
  s_[0] ^= s_[3];
  s_[2] ^= t;
  s_[3] = rotl(s_[3], 45);
  return result;
}

double Rng::uniform() {
  // Top 53 bits scaled by 2^-53: exact, every value a multiple of 2^-53.
  return static_cast<double>(next() >> 11) * 0x1.0p-53;
}

std::uint64_t Rng::below(std::uint64_t bound) {
  if (bound <= 1) return 0;
  // Reject the top partial block so every residue is equally likely.
  const std::uint64_t limit = ~std::uint64_t{0} - (~std::uint64_t{0} % bound);
  std::uint64_t x = next();
  while (x >= limit) x = next();
  return x % bound;
}

double Rng::normal() {
  if (has_cached_normal_) {
    has_cached_normal_ = false;
    return cached_normal_;
  }
  const double u1 = uniform_pos();
  const double u2 = uniform();
  const double r = std::sqrt(-2.0 * dmath::dlog(u1));
  double s = 0.0;
  double c = 0.0;
  dmath::dsincos(kTwoPi * u2, s, c);
  cached_normal_ = r * s;
  has_cached_normal_ = true;
  return r * c;
}

double Rng::exponential() { return -dmath::dlog(uniform_pos()); }

std::uint32_t Rng::poisson(double mean) {
  if (!(mean > 0.0)) return 0;
  // Bounded work: a draw is O(mean) uniforms; callers refuse larger means
  // (scenario_spec.h kMaxPoissonMean), this guards the rest (and +inf).
  if (!(mean <= kMaxPoissonMean)) mean = kMaxPoissonMean;
  std::uint32_t total = 0;
  double rest = mean;
  while (rest > 0.0) {
    const double chunk = rest > kPoissonChunk ? kPoissonChunk : rest;
    rest -= chunk;
    // Knuth: count uniforms until their product drops below exp(-chunk).
    const double limit = dmath::dexp(-chunk);
    double p = uniform_pos();
    while (p > limit) {
      ++total;
      p *= uniform_pos();
    }
  }
  return total;
}

double Rng::gamma_int(int shape, double scale) {
  double sum = 0.0;
  for (int i = 0; i < shape; ++i) sum += exponential();
  return scale * sum;
}

double Rng::gamma_int_above(int shape, double scale, double t) {
  if (shape <= 1) return t + scale * exponential();
  // shape 2: mixture weights t*scale and scale^2 (integrals of the two terms).
  const double p_exp = t / (t + scale);
  if (uniform() < p_exp) return t + scale * exponential();
  return t + scale * (exponential() + exponential());
}

double Rng::weibull_above(double b, double sigma0, double t) {
  // With X = a^(2b), P(X > x) = exp(-x / sigma0): X is Exp(sigma0), and
  // given X > t^(2b) the excess is again Exp(sigma0) (docs/algorithms/scenarios.md
  // §Measurement generation).
  if (b == 1.0) return std::sqrt(t * t + sigma0 * exponential());
  const double two_b = 2.0 * b;
  const double x = dmath::dexp(two_b * dmath::dlog(t)) + sigma0 * exponential();
  return dmath::dexp(dmath::dlog(x) / two_b);
}

}  // namespace mptrack::scenario
