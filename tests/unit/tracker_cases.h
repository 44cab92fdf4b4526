// Per-tracker test fixtures shared by the tests that run one behaviour over
// every tracker (validation_trackers_test.cpp, tracker_contract_test.cpp):
// for each tracker a Case with its params for a small polar scene, a target
// inside the region, points outside it, and its scan period; helpers that
// build scans and compare outputs bit for bit.
#pragma once

#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <vector>

#include "mptrack/cbmember/cbmember_filter.h"
#include "mptrack/gnn/gnn_tracker.h"
#include "mptrack/mfbp/mfbp_tracker.h"
#include "mptrack/multipath/multipath_tracker.h"
#include "mptrack/mptf/mptf_tracker.h"
#include "mptrack/phd/phd_filter.h"

namespace tracker_cases {

using mptrack::Status;


constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

inline mptrack::Measurement<float> meas(float r, float az, float amp) {
  mptrack::Measurement<float> m;
  m.range_m = r;
  m.azimuth_rad = az;
  m.amplitude = amp;
  return m;
}

// Per tracker: params, a target position (measurement space), a point
// outside the region, the scan period, and whether amplitude is checked.
struct GnnCase {
  using Tracker = mptrack::GnnTracker<float, mptrack::SmallBoardCaps>;
  static constexpr const char* kName = "gnn";
  static Tracker::Params params() { return Tracker::Params{}; }
  static mptrack::Measurement<float> target() { return meas(50.0f, 0.3f, 10.0f); }
  /// Point i of a 10 x 4 grid of well-separated targets (15 sigma apart).
  static mptrack::Measurement<float> grid(int i) {
    return meas(20.0f + 3.0f * float(i % 10), -0.5f + 0.25f * float(i / 10), 10.0f);
  }
  static constexpr float kOutsideRange = 500.0f;   // max_range_m = 200
  static constexpr float kOutsideAz = 3.5f;        // > pi
  static constexpr bool kChecksAmplitude = false;  // GNN does not use amplitude
  static constexpr std::uint64_t kDtUs = 100000;
};
struct MfbpCase {
  using Tracker = mptrack::MfbpTracker<float, mptrack::SmallBoardCaps>;
  static constexpr const char* kName = "mfbp";
  static Tracker::Params params() {
    Tracker::Params p;
    p.window_length = 1;  // online filter: one finalised scan per step
    p.slide = 1;
    return p;
  }
  static mptrack::Measurement<float> target() { return meas(30000.0f, 0.6f, 6.0f); }
  static mptrack::Measurement<float> grid(int i) {
    return meas(12000.0f + 3000.0f * float(i % 10), 0.3f + 0.15f * float(i / 10), 6.0f);
  }
  static constexpr float kOutsideRange = 60000.0f;  // r_max_m = 50000
  static constexpr float kOutsideAz = 1.5f;         // az_max_rad = 60 deg
  static constexpr bool kChecksAmplitude = true;    // amplitude > threshold 0.715
  static constexpr std::uint64_t kDtUs = 1250000;
};
/// MF-BP as a window smoother (window 4, slide 2: the largest window of
/// SmallBoardCaps): finalises scans in batches with a lag.
struct MfbpSmootherCase : MfbpCase {
  static constexpr const char* kName = "mfbp-window4";
  static Tracker::Params params() {
    Tracker::Params p;
    p.window_length = 4;
    p.slide = 2;
    return p;
  }
};
/// Multipath MF-BP in its single-path configuration (heights and baseline
/// 0: h(x) = [g, g_dot, theta]), births from single detections.
struct MultipathCase {
  using Tracker = mptrack::MultipathMfbpTracker<float, mptrack::SmallBoardCaps>;
  static constexpr const char* kName = "mfbp-multipath";
  static Tracker::Params params() {
    Tracker::Params p;
    p.num_paths = 1;
    p.paths[0] = {0.0f, 0.0f};
    p.baseline_km = 0.0f;
    p.region = {10000.0f, 50000.0f, 0.2f, 1.2f};
    p.noise.range_std_m = 50.0f;
    p.clutter_mean_count = 1.0f;
    p.min_group_size = 1;
    p.birth_existence_scale = 0.5f;
    return p;
  }
  static mptrack::Measurement<float> target() { return meas(30000.0f, 0.6f, 6.0f); }
  static mptrack::Measurement<float> grid(int i) {
    return meas(12000.0f + 3000.0f * float(i % 10), 0.3f + 0.15f * float(i / 10), 6.0f);
  }
  static constexpr float kOutsideRange = 60000.0f;  // region.range_max_m = 50000
  static constexpr float kOutsideAz = 1.5f;         // region.azimuth_max_rad = 1.2
  static constexpr bool kChecksAmplitude = false;   // amplitude is not modelled
  static constexpr std::uint64_t kDtUs = 16000000;
};
/// Multipath track fusion in its single-path configuration (heights and
/// baseline 0: slant = ground), a fused track from one path track.
struct MptfCase {
  using Tracker = mptrack::MptfTracker<float, mptrack::SmallBoardCaps>;
  static constexpr const char* kName = "mptf";
  static Tracker::Params params() {
    Tracker::Params p;
    p.num_paths = 1;
    p.paths[0] = {0.0f, 0.0f};
    p.baseline_km = 0.0f;
    p.region = {10000.0f, 50000.0f, 0.2f, 1.2f};
    p.noise.range_std_m = 50.0f;
    p.clutter_mean_count = 1.0f;
    p.fuse_min_paths = 1;
    return p;
  }
  static mptrack::Measurement<float> target() { return meas(30000.0f, 0.6f, 6.0f); }
  static mptrack::Measurement<float> grid(int i) {
    return meas(12000.0f + 3000.0f * float(i % 10), 0.3f + 0.15f * float(i / 10), 6.0f);
  }
  static constexpr float kOutsideRange = 60000.0f;  // region.range_max_m = 50000
  static constexpr float kOutsideAz = 1.5f;         // region.azimuth_max_rad = 1.2
  static constexpr bool kChecksAmplitude = false;   // amplitude is not modelled
  static constexpr std::uint64_t kDtUs = 16000000;
};
template <class Filter, const char* Name>
struct IggmCase {
  using Tracker = Filter;
  static constexpr const char* kName = Name;
  static typename Tracker::Params params() {
    typename Tracker::Params p;
    // Polar measurement space, so both range and azimuth have bounds (in
    // the Cartesian default the region is an x/y box: any azimuth is inside).
    p.space = mptrack::MeasurementSpace::kPolar;
    p.region.range_min_m = 10.0f;
    p.region.range_max_m = 1000.0f;
    p.region.azimuth_min_rad = -1.0f;
    p.region.azimuth_max_rad = 1.0f;
    return p;
  }
  static mptrack::Measurement<float> target() { return meas(300.0f, 0.5f, 8.0f); }
  static mptrack::Measurement<float> grid(int i) {
    return meas(100.0f + 60.0f * float(i % 10), -0.6f + 0.3f * float(i / 10), 8.0f);
  }
  static constexpr float kOutsideRange = 1500.0f;  // region_max0 = 1000 m
  static constexpr float kOutsideAz = 1.3f;        // region_max1 = 1 rad
  static constexpr bool kChecksAmplitude = true;   // amplitude >= threshold 1.5174
  static constexpr std::uint64_t kDtUs = 1000000;
};
constexpr char kPhdName[] = "gmphd";
constexpr char kCphdName[] = "gmcphd";
constexpr char kCbmName[] = "cbmember";
using PhdCase = IggmCase<mptrack::GmPhdFilter<float, mptrack::SmallBoardCaps>, kPhdName>;
using CphdCase = IggmCase<mptrack::GmCphdFilter<float, mptrack::SmallBoardCaps>, kCphdName>;
using CbmCase = IggmCase<mptrack::CbMemberFilter<float, mptrack::SmallBoardCaps>, kCbmName>;

template <class Estimate>
bool identical(const Estimate& a, const Estimate& b) {
  if (a.time_us != b.time_us || a.tracks.size() != b.tracks.size() ||
      a.clutter.size() != b.clutter.size()) {
    return false;
  }
  for (std::size_t i = 0; i < a.tracks.size(); ++i) {
    const auto& x = a.tracks[i];
    const auto& y = b.tracks[i];
    if (x.id != y.id || x.measurement_index != y.measurement_index || x.confirmed != y.confirmed ||
        std::memcmp(x.state.data(), y.state.data(), sizeof(x.state)) != 0 ||
        std::memcmp(x.covariance.data(), y.covariance.data(), sizeof(x.covariance)) != 0 ||
        std::memcmp(&x.existence, &y.existence, sizeof(x.existence)) != 0) {
      return false;
    }
  }
  for (std::size_t i = 0; i < a.clutter.size(); ++i) {
    if (std::memcmp(&a.clutter[i].expected_count, &b.clutter[i].expected_count,
                    sizeof(a.clutter[i].expected_count)) != 0) {
      return false;
    }
  }
  return true;
}

template <class Tracker>
bool all_outputs_identical(const Tracker& a, const Tracker& b) {
  if (a.outputs().size() != b.outputs().size()) return false;
  for (std::size_t k = 0; k < a.outputs().size(); ++k) {
    if (!identical(a.outputs()[k], b.outputs()[k])) return false;
  }
  return true;
}

template <class Tracker>
bool outputs_finite(const Tracker& t) {
  for (const auto& e : t.outputs()) {
    for (const auto& r : e.tracks) {
      for (int i = 0; i < 4; ++i) {
        if (!mptrack::is_finite(r.state(i))) return false;
        for (int j = 0; j < 4; ++j) {
          if (!mptrack::is_finite(r.covariance(i, j))) return false;
        }
      }
    }
  }
  return true;
}

template <class Case>
std::unique_ptr<typename Case::Tracker> make_tracker() {
  auto t = std::make_unique<typename Case::Tracker>();
  REQUIRE(t->init(Case::params()) == Status::kOk);
  return t;
}

template <class Case>
typename Case::Tracker::ScanType scan_at(std::uint64_t k, std::vector<mptrack::Measurement<float>> ms) {
  typename Case::Tracker::ScanType s;
  s.time_us = 1000000 + k * Case::kDtUs;
  for (const auto& m : ms) REQUIRE(s.measurements.push_back(m) == Status::kOk);
  return s;
}

}  // namespace tracker_cases

#define MPTRACK_TRACKER_CASES GnnCase, MfbpCase, PhdCase, CphdCase, CbmCase
