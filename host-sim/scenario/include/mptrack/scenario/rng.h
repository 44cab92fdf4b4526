// Deterministic random numbers for the scenario generator.
//
// xoshiro256** (Blackman & Vigna 2018) seeded by splitmix64, with our own
// transforms built only on + - * / sqrt and mptrack::dmath (never libm), so
// x86-64, aarch64 and armhf draw identical bits from the same seed: the
// golden scenario test runs under qemu and compares S2's measurements.
#pragma once

#include <array>
#include <cstdint>

namespace mptrack::scenario {

/// splitmix64 finaliser: a bijective 64-bit mixer (also used to derive seeds).
constexpr std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

/// Seed of one independent stream, e.g. derive_seed(user_seed, run, scan):
/// every (run, scan) pair gets its own stream, so any scan can be generated
/// alone and runs do not depend on how many draws earlier scans made.
constexpr std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t a, std::uint64_t b = 0) {
  return splitmix64(splitmix64(splitmix64(seed) ^ (a * 0xd1b54a32d192ed03ULL)) ^
                    (b * 0xabc98388fb8fac03ULL));
}

class Rng {
 public:
  explicit Rng(std::uint64_t seed = 1) { reseed(seed); }

  /// Restarts the stream; the four state words come from splitmix64 so that
  /// the all-zero state (a fixed point of xoshiro) cannot occur.
  void reseed(std::uint64_t seed);

  /// Next raw 64-bit output.
  std::uint64_t next();

  /// Uniform on [0, 1) with 53 random bits.
  double uniform();
  /// Uniform on (0, 1] (safe argument for a logarithm).
  double uniform_pos() { return 1.0 - uniform(); }
  /// Uniform integer in [0, bound) without modulo bias (rejection); bound >= 1.
  std::uint64_t below(std::uint64_t bound);
  /// Standard normal N(0, 1), Box-Muller (pairs; the second value is cached).
  double normal();
  /// Exponential with mean 1: -ln U, U in (0, 1].
  double exponential();
  /// Poisson(mean): Knuth's product method on chunks of mean <= 30 (a sum of
  /// independent Poissons is Poisson), so exp(-chunk) never underflows.
  /// Means above kMaxPoissonMean (and +inf) draw with kMaxPoissonMean.
  std::uint32_t poisson(double mean);
  static constexpr double kMaxPoissonMean = 1e7;
  /// Gamma(shape n, scale) for integer n >= 1: a sum of n exponentials.
  double gamma_int(int shape, double scale);
  /// Gamma(shape n, scale) conditioned on X > t, n in {1, 2}, exact:
  /// X = t + Y with density of Y proportional to (t + y)^(n-1) exp(-y/scale),
  /// i.e. Exp(scale) for n = 1, and for n = 2 the mixture
  /// t/(t+scale) Exp(scale) + scale/(t+scale) Gamma(2, scale).
  double gamma_int_above(int shape, double scale, double t);
  /// Weibull amplitude (docs/algorithms/models.md §Amplitude likelihoods),
  /// p(a) = (2b/sigma0) a^(2b-1)
  /// exp(-a^(2b)/sigma0), conditioned on a > t (t > 0), exact:
  /// a^(2b) = t^(2b) + sigma0 E with E ~ Exp(1). b = 1 uses sqrt only.
  double weibull_above(double b, double sigma0, double t);

 private:
  std::array<std::uint64_t, 4> s_{};
  double cached_normal_ = 0.0;
  bool has_cached_normal_ = false;
};

}  // namespace mptrack::scenario
