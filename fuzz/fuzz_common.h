// Shared helpers of the libFuzzer harnesses (docs/reliability.md).
//
// FuzzReader turns the fuzzer's bytes into values; once the input is used
// up every take_*() returns 0, so a harness never reads past the end.
// Scans are decoded by decode_scan(): each measurement is either raw float
// bits (NaN, Inf, denormals, anything), a quantised point near the
// surveillance region, or a small perturbation of a measurement of the
// previous scan, so the fuzzer can both throw garbage at the input checks
// and build persistent tracks that reach the deep code paths.
// Invariant violations call FUZZ_CHECK, which prints and aborts: libFuzzer
// records the input as a crash.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <type_traits>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "mptrack/measurement.h"
#include "mptrack/status.h"
#include "mptrack/track_report.h"
#include "mptrack/validate.h"

#define FUZZ_CHECK(cond)                                                             \
  do {                                                                               \
    if (!(cond)) {                                                                   \
      std::fprintf(stderr, "FUZZ_CHECK failed: %s at %s:%d\n", #cond, __FILE__, __LINE__); \
      std::abort();                                                                  \
    }                                                                                \
  } while (false)

namespace mptrack::fuzz {

class FuzzReader {
 public:
  FuzzReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  bool empty() const { return pos_ >= size_; }
  std::size_t remaining() const { return size_ - pos_; }

  std::uint8_t u8() { return pos_ < size_ ? data_[pos_++] : std::uint8_t{0}; }
  std::uint16_t u16() {
    const auto lo = static_cast<std::uint16_t>(u8());
    return static_cast<std::uint16_t>(lo | static_cast<std::uint16_t>(u8() << 8));
  }
  std::uint32_t u32() {
    const std::uint32_t lo = u16();
    return lo | (static_cast<std::uint32_t>(u16()) << 16);
  }
  std::uint64_t u64() {
    const std::uint64_t lo = u32();
    return lo | (static_cast<std::uint64_t>(u32()) << 32);
  }
  /// Any float bit pattern (NaN, Inf, denormals included).
  float raw_float() {
    const std::uint32_t bits = u32();
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
  }
  double raw_double() {
    const std::uint64_t bits = u64();
    double d;
    std::memcpy(&d, &bits, sizeof d);
    return d;
  }
  /// [0, 1] in 65536 steps.
  float unit() { return static_cast<float>(u16()) * (1.0f / 65535.0f); }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

/// The region a decoded "structured" measurement is drawn near.
struct Region {
  float r_min_m;
  float r_max_m;
  float az_min_rad;
  float az_max_rad;
};

/// Special values a field may be set to (the classic bad inputs).
inline float special_float(std::uint8_t k) {
  switch (k % 8u) {
    case 0: return __builtin_nanf("");
    case 1: return __builtin_inff();
    case 2: return -__builtin_inff();
    case 3: return -1.0f;
    case 4: return 0.0f;
    case 5: return 3.4e38f;
    case 6: return 1e-40f;  // denormal
    default: return -0.0f;
  }
}

/// Next scan time: mostly forward, sometimes equal, backwards or a jump.
/// Input shapes a harness may still mask for a tracker that has not got
/// the fix yet (docs/reliability.md). GNN, GM-PHD/CPHD and CBMeMBer take
/// everything since F1 (max-gap rule) and F4/F8 (amplitude ceiling, CPHD
/// ratio cap). MF-BP (fuzz_mfbp.cpp) masks both until mfbp_tracker.h uses
/// ScanClock's max-gap rule and an amplitude ceiling; defining
/// MPTRACK_FUZZ_KNOWN_ISSUES lifts every mask.
struct DecodeMasks {
  bool short_gaps = false;        ///< time jumps stay within 60 s
  bool moderate_amplitude = false;  ///< finite amplitudes capped at 1e3
};
inline DecodeMasks g_masks{};

/// Next scan time: usually forward by 1..200 ms, sometimes equal, back,
/// a jump of up to 18 h, or any 64-bit value.
inline std::uint64_t next_time_us(FuzzReader& in, std::uint64_t last) {
  const std::uint8_t mode = in.u8();
  if (mode < 200) return last + 1000u * (1u + mode);                       // 1..200 ms
  if (mode < 215) return last;                                             // equal
  if (mode < 230) return last - (last < 1000000u ? last : 1000000u);      // back <= 1 s
#if !defined(MPTRACK_FUZZ_KNOWN_ISSUES)
  if (g_masks.short_gaps) {
    if (mode < 245) return last + 1000u * (1u + in.u16() % 60000u);       // jump <= 60 s
    const std::uint64_t back = last < 60000000u ? last : 60000000u;
    return last - back + in.u32() % 120000000u;  // within 60 s either way
  }
#endif
  if (mode < 245) return last + 1000000u * (1u + in.u16());               // jump <= 18 h
  return in.u64();                                                         // anything
}

/// Decodes one scan of at most Cap measurements. prev is the previous
/// decoded scan (source of "persistent" points).
template <class ScanT>
void decode_scan(FuzzReader& in, const Region& reg, const ScanT& prev, std::uint64_t last_time,
                 ScanT& out) {
  constexpr std::size_t kCap = std::remove_reference_t<decltype(out.measurements)>::kCapacity;
  out.measurements.clear();
  out.time_us = next_time_us(in, last_time);
  const std::uint8_t head = in.u8();
  out.has_doppler = (head & 0x80u) != 0;
  const std::size_t count = static_cast<std::size_t>(head & 0x7Fu) % (kCap + 1);
  const float span_r = reg.r_max_m - reg.r_min_m;
  const float span_a = reg.az_max_rad - reg.az_min_rad;
  for (std::size_t j = 0; j < count && !in.empty(); ++j) {
    Measurement<float> m;
    const std::uint8_t kind = in.u8();
    if (kind < 16) {  // raw bits
      m.range_m = in.raw_float();
      m.azimuth_rad = in.raw_float();
      m.amplitude = in.raw_float();
      m.doppler_mps = in.raw_float();
#if !defined(MPTRACK_FUZZ_KNOWN_ISSUES)
      if (g_masks.moderate_amplitude && is_finite(m.amplitude) && m.amplitude > 1e3f) {
        m.amplitude = 1e3f;
      }
#endif
    } else if (kind < 32) {  // one special value in one field of a sane point
      m.range_m = reg.r_min_m + 0.5f * span_r;
      m.azimuth_rad = reg.az_min_rad + 0.5f * span_a;
      m.amplitude = 3.0f;
      float v = special_float(in.u8());
#if !defined(MPTRACK_FUZZ_KNOWN_ISSUES)
      if (g_masks.moderate_amplitude && kind % 4u == 2 && v > 1e30f) v = 1e3f;
#endif
      switch (kind % 4u) {
        case 0: m.range_m = v; break;
        case 1: m.azimuth_rad = v; break;
        case 2: m.amplitude = v; break;
        default: m.doppler_mps = v; break;
      }
    } else if (kind < 128 && j < prev.measurements.size()) {  // persistent point
      m = prev.measurements[j];
      m.range_m += 0.001f * span_r * static_cast<float>(static_cast<std::int8_t>(in.u8()));
      m.azimuth_rad += 0.001f * span_a * static_cast<float>(static_cast<std::int8_t>(in.u8()));
    } else {  // quantised, 10 % beyond the region on each side
      m.range_m = reg.r_min_m + span_r * (1.2f * in.unit() - 0.1f);
      m.azimuth_rad = reg.az_min_rad + span_a * (1.2f * in.unit() - 0.1f);
      m.amplitude = 0.05f * static_cast<float>(in.u8());
      m.doppler_mps = 1.5f * static_cast<float>(static_cast<std::int8_t>(in.u8()));
    }
    static_cast<void>(out.measurements.push_back(m));  // count <= kCap
  }
}

/// Symmetric (relative 1e-3) and positive definite as far as the working
/// precision T can tell: Eigen's LLT in T succeeds. (A double LLT is too
/// strict an oracle: after a long time jump a float CV covariance has a
/// condition number ~1e12, whose float rounding is PD but not exactly so.)
template <class T>
bool is_spd(const Eigen::Matrix<T, 4, 4>& P) {
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      if (!is_finite(P(i, j))) return false;
      const double pij = static_cast<double>(P(i, j));
      const double pji = static_cast<double>(P(j, i));
      const double tol = 1e-3 * (std::abs(static_cast<double>(P(i, i))) +
                                 std::abs(static_cast<double>(P(j, j)))) + 1e-30;
      if (std::abs(pij - pji) > tol) return false;
    }
  }
  const Eigen::Matrix<T, 4, 4> S = (P + P.transpose()) * T(0.5);
  Eigen::LLT<Eigen::Matrix<T, 4, 4>> llt(S);
  if (llt.info() != Eigen::Success) return false;
  for (int i = 0; i < 4; ++i) {
    if (!(llt.matrixLLT()(i, i) > T(0))) return false;
  }
  return true;
}

/// Every reported number finite, covariances SPD.
template <class Estimate>
void check_estimate_sane(const Estimate& e) {
  for (const auto& r : e.tracks) {
    for (int i = 0; i < 4; ++i) FUZZ_CHECK(is_finite(r.state(i)));
    if (!is_spd(r.covariance)) {
      std::fprintf(stderr, "track %u covariance:\n", static_cast<unsigned>(r.id));
      for (int i = 0; i < 4; ++i) {
        std::fprintf(stderr, "  %.9g %.9g %.9g %.9g\n", static_cast<double>(r.covariance(i, 0)),
                     static_cast<double>(r.covariance(i, 1)), static_cast<double>(r.covariance(i, 2)),
                     static_cast<double>(r.covariance(i, 3)));
      }
    }
    FUZZ_CHECK(is_spd(r.covariance));
    FUZZ_CHECK(is_finite(r.existence) && r.existence >= 0 && r.existence <= 1);
    FUZZ_CHECK(is_finite(r.snr));
  }
  for (const auto& c : e.clutter) {
    if (!is_finite(c.expected_count) || !is_finite(c.mean(0)) || !is_finite(c.mean(1))) {
      std::fprintf(stderr, "clutter %u uniform=%d mean=(%g, %g) count=%g cnr=%g\n",
                   static_cast<unsigned>(c.id), c.uniform ? 1 : 0, static_cast<double>(c.mean(0)),
                   static_cast<double>(c.mean(1)), static_cast<double>(c.expected_count),
                   static_cast<double>(c.cnr));
    }
    FUZZ_CHECK(is_finite(c.mean(0)) && is_finite(c.mean(1)));
    FUZZ_CHECK(is_finite(c.expected_count));
  }
}

template <class T>
bool same_bits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

/// Bit-for-bit equality of two estimates (field by field: no padding).
template <class Estimate>
bool estimates_identical(const Estimate& a, const Estimate& b) {
  if (a.time_us != b.time_us || a.tracks.size() != b.tracks.size() ||
      a.clutter.size() != b.clutter.size()) {
    return false;
  }
  for (std::size_t i = 0; i < a.tracks.size(); ++i) {
    const auto& x = a.tracks[i];
    const auto& y = b.tracks[i];
    if (x.id != y.id || x.confirmed != y.confirmed || x.measurement_index != y.measurement_index ||
        !same_bits(x.existence, y.existence) || !same_bits(x.snr, y.snr) ||
        std::memcmp(x.state.data(), y.state.data(), sizeof(x.state)) != 0 ||
        std::memcmp(x.covariance.data(), y.covariance.data(), sizeof(x.covariance)) != 0) {
      return false;
    }
  }
  for (std::size_t i = 0; i < a.clutter.size(); ++i) {
    const auto& x = a.clutter[i];
    const auto& y = b.clutter[i];
    if (x.id != y.id || !same_bits(x.expected_count, y.expected_count) ||
        std::memcmp(x.mean.data(), y.mean.data(), sizeof(x.mean)) != 0) {
      return false;
    }
  }
  return true;
}

}  // namespace mptrack::fuzz
