// The seed002-othr detections file (tests/golden/data/seed002_othr_run0.scans):
// the 30 scans of run 0 (seed 1) of the four Table IV cells as float tracker
// input, with the multipath tracker's Params as the harness configures them.
// Written on the host by tests/golden/seed002_scans_golden_test.cpp and read
// by the Cortex-M7 scan-cost report (tests/baremetal/multipath_scan_cost.cpp).
//
// Layout: 32-bit words, least significant byte first, assembled byte by byte
// (the same file on little- and big-endian readers); floats as their bit
// patterns. "MPS1", cell count, then per cell:
//   pd x 1000, clutter scale x 1000, scans,
//   num_paths, (tx height km, rx height km, pd) per path, baseline km,
//   region (range min m, range max m, azimuth min rad, azimuth max rad),
//   range-rate span m/s, noise (range m, azimuth rad, range rate m/s),
//   clutter mean count, max gap s, bearing PSD rad^2/s^3, smoothing lag scans,
//   then per scan: time_us (low word, high word), count, and per detection
//   range m, azimuth rad, range rate m/s.
// Amplitudes are not stored: the multipath tracker does not read them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

#include "mptrack/caps.h"
#include "mptrack/measurement.h"
#include "mptrack/multipath/multipath_params.h"

namespace mptrack::test::othr_file {

inline constexpr std::uint32_t kMagic = 0x3153504du;  // "MPS1" read as a little-endian word

/// Sequential reader over the file's bytes; ok() turns false on a short read.
class Reader {
 public:
  Reader(const unsigned char* begin, const unsigned char* end) : p_(begin), end_(end) {}

  std::uint32_t u32() {
    if (end_ - p_ < 4) {
      ok_ = false;
      return 0;
    }
    const std::uint32_t v = static_cast<std::uint32_t>(p_[0]) | (static_cast<std::uint32_t>(p_[1]) << 8) |
                            (static_cast<std::uint32_t>(p_[2]) << 16) | (static_cast<std::uint32_t>(p_[3]) << 24);
    p_ += 4;
    return v;
  }
  float f32() {
    const std::uint32_t bits = u32();
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
  }
  bool ok() const { return ok_; }

 private:
  const unsigned char* p_;
  const unsigned char* end_;
  bool ok_ = true;
};

/// One cell's header: its labels and the tracker's Params.
struct Cell {
  std::uint32_t pd_milli = 0;
  std::uint32_t clutter_scale_milli = 0;
  std::uint32_t num_scans = 0;
  MultipathParams<float> params;
};

/// Reads a cell header into `c` (Params fields not in the file keep their defaults).
inline bool read_cell(Reader& r, Cell& c) {
  c = Cell{};
  c.pd_milli = r.u32();
  c.clutter_scale_milli = r.u32();
  c.num_scans = r.u32();
  MultipathParams<float>& p = c.params;
  p.num_paths = r.u32();
  if (!r.ok() || p.num_paths > p.paths.size()) return false;
  for (std::uint32_t i = 0; i < p.num_paths; ++i) {
    p.paths[i].tx_height_km = r.f32();
    p.paths[i].rx_height_km = r.f32();
    p.pd[i] = r.f32();
  }
  p.baseline_km = r.f32();
  p.region.range_min_m = r.f32();
  p.region.range_max_m = r.f32();
  p.region.azimuth_min_rad = r.f32();
  p.region.azimuth_max_rad = r.f32();
  p.range_rate_span_mps = r.f32();
  p.noise.range_std_m = r.f32();
  p.noise.azimuth_std_rad = r.f32();
  p.noise.doppler_std_mps = r.f32();
  p.clutter_mean_count = r.f32();
  p.max_gap_s = r.f32();
  p.bearing_psd_rad2ps3 = r.f32();
  p.smoothing_lag_scans = r.u32();
  return r.ok();
}

/// Reads the next scan; false on a short file or a scan beyond N detections.
template <std::size_t N>
bool read_scan(Reader& r, Scan<float, N>& scan) {
  scan.measurements.clear();
  const std::uint32_t lo = r.u32();
  const std::uint32_t hi = r.u32();
  scan.time_us = (static_cast<std::uint64_t>(hi) << 32) | lo;
  scan.has_doppler = true;
  const std::uint32_t count = r.u32();
  for (std::uint32_t j = 0; j < count && r.ok(); ++j) {
    Measurement<float> m;
    m.range_m = r.f32();
    m.azimuth_rad = r.f32();
    m.doppler_mps = r.f32();
    m.amplitude = 1.0f;
    if (scan.measurements.push_back(m) != Status::kOk) return false;
  }
  return r.ok();
}

/// DefaultCaps with room for an Nc 400 scan (Poisson(400) clutter plus up
/// to 16 target detections; DefaultCaps holds 256) and its tentative tracks
/// (run 0 at Nc 400 refused 64 / 310 births at DefaultCaps' 64 tracks, none
/// at 128, measured with the paper's bearing PSD).
struct Nc400Caps : DefaultCaps {
  static constexpr std::size_t kMaxMeasurements = 512;
  static constexpr std::size_t kMaxTargets = 128;
};

/// A step the tracker accepted: kOk, or kPartial / kCapacityExceeded, whose
/// causes the counters record (tracker_contract.h, rule 2).
inline bool accepted(Status s) {
  return s == Status::kOk || s == Status::kPartial || s == Status::kCapacityExceeded;
}

inline constexpr std::uint32_t kHashSeed = 2166136261u;  // FNV-1a offset basis

/// FNV-1a over the words of every estimate in tracker.outputs(): track ids,
/// confirmed flags and the bits of states and existences. Equal hashes on
/// two targets mean the same outputs bit for bit (with overwhelming odds).
template <class Tracker>
std::uint32_t hash_outputs(const Tracker& tracker, std::uint32_t h) {
  auto mix = [&h](std::uint32_t w) {
    for (int b = 0; b < 4; ++b) {
      h ^= (w >> (8 * b)) & 0xffu;
      h *= 16777619u;
    }
  };
  auto mix_f = [&mix](float f) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &f, sizeof bits);
    mix(bits);
  };
  for (const auto& est : tracker.outputs()) {
    mix(static_cast<std::uint32_t>(est.tracks.size()));
    for (const auto& t : est.tracks) {
      mix(static_cast<std::uint32_t>(t.id));
      mix(t.confirmed ? 1u : 0u);
      for (int a = 0; a < 4; ++a) mix_f(t.state(a));
      mix_f(t.existence);
    }
  }
  return h;
}

}  // namespace mptrack::test::othr_file
