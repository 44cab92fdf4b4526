// mptrack-soak: long-run reliability check (docs/reliability.md, "Soak").
//
//   mptrack-soak --scans N [--seed S] [--trackers gnn,mfbp]
//
// Runs the GNN tracker and the MF-BP online filter (window 1) side by side
// on one cluttered scenario generated here (deterministic LCG): up to 6
// targets that appear, fly a constant-velocity leg and disappear (birth
// and death times random), Pd = 0.9, Poisson clutter (mean 8 per scan,
// uniform in the region) and 0.5 % deliberately bad measurements (NaN,
// Inf or outside the region). Every scan checks, per tracker:
//   - no NaN/Inf in any reported state or covariance;
//   - every reported covariance is SPD (Eigen LLT in the tracker's float);
//   - the live track count stays <= the caps;
//   - step() returns a success status (kOk / kPartial / kCapacityExceeded);
// and at the end: counters add up (measurements_in = measurements offered,
// measurements_invalid = bad ones injected, scans = N) and the step
// latency p50/p99 of the last 10 % of scans is compared with the first
// 10 % (drift). Exit status 0 only if every check held.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include <Eigen/Cholesky>

#include "mptrack/gnn/gnn_tracker.h"
#include "mptrack/mfbp/mfbp_tracker.h"

namespace {

using mptrack::Status;

// Region (MF-BP seed 000 defaults): range [10, 50] km, azimuth [10, 60] deg.
constexpr double kRMin = 10000.0;
constexpr double kRMax = 50000.0;
constexpr double kAzMin = 0.17453292519943295;
constexpr double kAzMax = 1.0471975511965976;
constexpr std::uint64_t kDtUs = 1250000;  // 1.25 s scans
constexpr double kDt = 1.25;
constexpr int kMaxTargets = 6;
constexpr double kClutterMean = 8.0;
constexpr double kPd = 0.9;
constexpr double kBadRate = 0.005;

struct Rng {  // 64-bit LCG (Knuth MMIX), good enough for a scenario
  std::uint64_t s;
  double uniform() {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(s >> 11) * (1.0 / 9007199254740992.0);
  }
  double gaussian() {  // Box-Muller
    const double u1 = uniform() + 1e-300;
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
  }
  int poisson(double mean) {
    const double l = std::exp(-mean);
    int k = 0;
    double p = uniform();
    while (p > l) {
      ++k;
      p *= uniform();
    }
    return k;
  }
};

struct Target {
  bool alive = false;
  std::uint64_t until = 0;  ///< scan index at which it disappears
  double x = 0, y = 0, vx = 0, vy = 0;
};

struct Checks {
  const char* name;
  std::uint64_t nan = 0;
  std::uint64_t not_spd = 0;
  std::uint64_t bad_status = 0;
  std::size_t max_tracks = 0;
  std::size_t cap = 0;
  std::vector<double> lat_first_us, lat_last_us;
  double total_s = 0;
};

template <class Estimate>
void check_estimate(const Estimate& e, Checks& c) {
  c.max_tracks = std::max(c.max_tracks, e.tracks.size());
  for (const auto& r : e.tracks) {
    bool finite = true;
    for (int i = 0; i < 4; ++i) {
      finite = finite && std::isfinite(r.state(i));
      for (int j = 0; j < 4; ++j) finite = finite && std::isfinite(r.covariance(i, j));
    }
    if (!finite) {
      ++c.nan;
      continue;
    }
    Eigen::LLT<Eigen::Matrix4f> llt(r.covariance);
    const float asym = (r.covariance - r.covariance.transpose()).cwiseAbs().maxCoeff();
    if (llt.info() != Eigen::Success || asym > 1e-3f * r.covariance.diagonal().cwiseAbs().maxCoeff()) {
      ++c.not_spd;
    }
  }
}

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t i = static_cast<std::size_t>(q * static_cast<double>(v.size() - 1) + 0.5);
  return v[i];
}

struct GnnSoakCaps {  // DefaultCaps, with the scan capacity MF-BP uses below
  static constexpr std::size_t kMaxTargets = 64;
  static constexpr std::size_t kMaxMeasurements = 64;
  static constexpr std::size_t kMaxClutterComponents = 8;
  static constexpr std::size_t kMaxWindow = 7;
};
using Gnn = mptrack::GnnTracker<float, GnnSoakCaps>;
struct MfbpSoakCaps {
  static constexpr std::size_t kMaxTargets = 16;
  static constexpr std::size_t kMaxMeasurements = 64;
  static constexpr std::size_t kMaxClutterComponents = 4;
  static constexpr std::size_t kMaxWindow = 7;  // the online filter keeps history scans here
};
using Mfbp = mptrack::MfbpTracker<float, MfbpSoakCaps>;

Gnn g_gnn;
Mfbp g_mfbp;
Gnn::ScanType g_scan;  // the same type as Mfbp::ScanType (64 measurements)
static_assert(std::is_same<Gnn::ScanType, Mfbp::ScanType>::value, "one scan feeds both trackers");

}  // namespace

int main(int argc, char** argv) {
  std::uint64_t scans = 100000;
  std::uint64_t seed = 20240611;
  bool run_gnn = true;
  bool run_mfbp = true;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--scans" && i + 1 < argc) {
      scans = std::strtoull(argv[++i], nullptr, 10);
    } else if (a == "--seed" && i + 1 < argc) {
      seed = std::strtoull(argv[++i], nullptr, 10);
    } else if (a == "--trackers" && i + 1 < argc) {
      const std::string t = argv[++i];
      run_gnn = t.find("gnn") != std::string::npos;
      run_mfbp = t.find("mfbp") != std::string::npos;
    } else {
      std::fprintf(stderr, "usage: mptrack-soak --scans N [--seed S] [--trackers gnn,mfbp]\n");
      return 2;
    }
  }
  if (scans < 10) scans = 10;

  Gnn::Params gp;
  gp.region.range_min_m = static_cast<float>(kRMin);
  gp.region.range_max_m = static_cast<float>(kRMax);
  gp.region.azimuth_min_rad = static_cast<float>(kAzMin);
  gp.region.azimuth_max_rad = static_cast<float>(kAzMax);
  gp.noise.range_std_m = 20.0f;
  gp.noise.azimuth_std_rad = 0.0104720f;
  gp.accel_var_m2ps4 = 1.0f;
  gp.init_velocity_std_mps = 100.0f;
  Mfbp::Params mp;
  mp.window_length = 1;
  mp.slide = 1;
  if (g_gnn.init(gp) != Status::kOk || g_mfbp.init(mp) != Status::kOk) {
    std::fprintf(stderr, "init failed\n");
    return 1;
  }

  Checks cg{"gnn", 0, 0, 0, 0, Gnn::kMaxTracks, {}, {}, 0};
  Checks cm{"mfbp", 0, 0, 0, 0, MfbpSoakCaps::kMaxTargets, {}, {}, 0};
  Rng rng{seed};
  Target targets[kMaxTargets];
  std::uint64_t offered = 0, bad = 0, over_cap = 0, target_scans = 0;
  std::uint64_t expected_invalid = 0;  // bad ones + noisy target points just outside the region
  const std::uint64_t tenth = scans / 10;
  const double sigma_r = 20.0, sigma_az = 0.0104720;

  for (std::uint64_t k = 0; k < scans; ++k) {
    // Births and deaths.
    for (Target& t : targets) {
      if (t.alive && k >= t.until) t.alive = false;
      if (!t.alive && rng.uniform() < 0.01) {
        const double r = 15000.0 + 30000.0 * rng.uniform();
        const double az = 0.3 + 0.6 * rng.uniform();
        t.x = r * std::cos(az);
        t.y = r * std::sin(az);
        const double speed = 30.0 + 120.0 * rng.uniform();
        const double head = 6.283185307179586 * rng.uniform();
        t.vx = speed * std::cos(head);
        t.vy = speed * std::sin(head);
        t.until = k + 50 + static_cast<std::uint64_t>(400.0 * rng.uniform());
        t.alive = true;
      }
    }
    g_scan.measurements.clear();
    g_scan.time_us = 1000000 + k * kDtUs;
    g_scan.has_doppler = false;
    auto push = [&](float r, float az, float amp) {
      mptrack::Measurement<float> m;
      m.range_m = r;
      m.azimuth_rad = az;
      m.amplitude = amp;
      if (g_scan.measurements.push_back(m) != Status::kOk) {
        ++over_cap;
        return;
      }
      ++offered;
      // The trackers' region test, in float, as both trackers do it.
      const bool inside = std::isfinite(r) && std::isfinite(az) && !(r < static_cast<float>(kRMin)) &&
                          !(r > static_cast<float>(kRMax)) && !(az < static_cast<float>(kAzMin)) &&
                          !(az > static_cast<float>(kAzMax));
      if (!inside) ++expected_invalid;
    };
    for (Target& t : targets) {
      if (!t.alive) continue;
      t.x += t.vx * kDt;
      t.y += t.vy * kDt;
      const double r = std::sqrt(t.x * t.x + t.y * t.y);
      const double az = std::atan2(t.y, t.x);
      if (r < kRMin || r > kRMax || az < kAzMin || az > kAzMax) {
        t.alive = false;  // left the region
        continue;
      }
      ++target_scans;
      if (rng.uniform() < kPd) {
        // Rayleigh amplitude of SNR ~ 13 dB, conditioned above the threshold
        const double amp = std::sqrt(-2.0 * 20.0 * std::log(rng.uniform() + 1e-12));
        push(static_cast<float>(r + sigma_r * rng.gaussian()),
             static_cast<float>(az + sigma_az * rng.gaussian()),
             static_cast<float>(std::max(amp, 0.8)));
      }
    }
    const int nc = rng.poisson(kClutterMean);
    for (int c = 0; c < nc; ++c) {
      const double amp = std::sqrt(-2.0 * std::log(rng.uniform() + 1e-12));
      push(static_cast<float>(kRMin + (kRMax - kRMin) * rng.uniform()),
           static_cast<float>(kAzMin + (kAzMax - kAzMin) * rng.uniform()),
           static_cast<float>(std::max(amp, 0.8)));
    }
    if (rng.uniform() < kBadRate * 10.0) {  // about 0.5 % of all measurements
      const double u = rng.uniform();
      const float nan = std::numeric_limits<float>::quiet_NaN();
      if (u < 0.4) push(nan, 0.5f, 3.0f);
      else if (u < 0.7) push(30000.0f, std::numeric_limits<float>::infinity(), 3.0f);
      else push(static_cast<float>(kRMax * 1.5), 0.5f, 3.0f);
      ++bad;
    }

    const bool first = k < tenth;
    const bool last = k >= scans - tenth;
    if (run_gnn) {
      const auto t0 = std::chrono::steady_clock::now();
      const Status s = g_gnn.step(g_scan);
      const double us =
          std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
      cg.total_s += us * 1e-6;
      if (first) cg.lat_first_us.push_back(us);
      if (last) cg.lat_last_us.push_back(us);
      if (!(s == Status::kOk || s == Status::kPartial || s == Status::kCapacityExceeded)) ++cg.bad_status;
      for (const auto& e : g_gnn.outputs()) check_estimate(e, cg);
      cg.max_tracks = std::max(cg.max_tracks, g_gnn.tracks().size());
    }
    if (run_mfbp) {
      const auto t0 = std::chrono::steady_clock::now();
      const Status s = g_mfbp.step(g_scan);
      const double us =
          std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
      cm.total_s += us * 1e-6;
      if (first) cm.lat_first_us.push_back(us);
      if (last) cm.lat_last_us.push_back(us);
      if (!(s == Status::kOk || s == Status::kPartial || s == Status::kCapacityExceeded)) ++cm.bad_status;
      for (const auto& e : g_mfbp.outputs()) check_estimate(e, cm);
      cm.max_tracks = std::max(cm.max_tracks, g_mfbp.live_tracks());
    }
    if (k > 0 && k % 100000 == 0) {
      std::fprintf(stderr, "  %llu scans\n", static_cast<unsigned long long>(k));
    }
  }

  bool ok = over_cap == 0;
  std::printf("mptrack-soak: %llu scans (%.0f s of radar time), %llu measurements offered "
              "(%llu deliberately bad, %llu outside the region in all), %llu target-scans, seed %llu\n",
              static_cast<unsigned long long>(scans), static_cast<double>(scans) * kDt,
              static_cast<unsigned long long>(offered), static_cast<unsigned long long>(bad),
              static_cast<unsigned long long>(expected_invalid),
              static_cast<unsigned long long>(target_scans), static_cast<unsigned long long>(seed));
  std::printf("%-5s %10s %8s %8s %10s %11s %11s %11s %11s %9s %8s\n", "", "max_tracks", "NaN",
              "not_SPD", "bad_status", "p50_start", "p99_start", "p50_end", "p99_end", "total_s",
              "counters");
  auto report = [&](Checks& c, const mptrack::TrackerCounters& tc) {
    const bool counters_ok = tc.measurements_in == offered && tc.measurements_invalid == expected_invalid &&
                             tc.scans == scans && tc.scans_rejected == 0;
    const double p50a = percentile(c.lat_first_us, 0.5), p99a = percentile(c.lat_first_us, 0.99);
    const double p50b = percentile(c.lat_last_us, 0.5), p99b = percentile(c.lat_last_us, 0.99);
    // Drift: the median of the last 10 % within 2x of the first 10 % (+5 us
    // of timer noise). p99 is printed but not judged: a shared machine's
    // scheduler noise dominates it.
    const bool drift_ok = p50b <= 2.0 * p50a + 5.0;
    const bool pass = c.nan == 0 && c.not_spd == 0 && c.bad_status == 0 && c.max_tracks <= c.cap &&
                      counters_ok && drift_ok;
    std::printf("%-5s %10zu %8llu %8llu %10llu %9.1fus %9.1fus %9.1fus %9.1fus %9.1f %8s  %s\n", c.name,
                c.max_tracks, static_cast<unsigned long long>(c.nan),
                static_cast<unsigned long long>(c.not_spd), static_cast<unsigned long long>(c.bad_status),
                p50a, p99a, p50b, p99b, c.total_s, counters_ok ? "ok" : "MISMATCH",
                pass ? "PASS" : "FAIL");
    std::printf("      counters: in %llu invalid %llu born %llu confirmed %llu deleted %llu "
                "cap_hits %llu repairs %llu\n",
                static_cast<unsigned long long>(tc.measurements_in),
                static_cast<unsigned long long>(tc.measurements_invalid),
                static_cast<unsigned long long>(tc.tracks_born),
                static_cast<unsigned long long>(tc.tracks_confirmed),
                static_cast<unsigned long long>(tc.tracks_deleted),
                static_cast<unsigned long long>(tc.track_cap_hits),
                static_cast<unsigned long long>(tc.numerical_repairs));
    return pass;
  };
  if (run_gnn) ok = report(cg, g_gnn.counters()) && ok;
  if (run_mfbp) ok = report(cm, g_mfbp.counters()) && ok;
  std::printf("soak: %s\n", ok ? "PASS" : "FAIL");
  return ok ? 0 : 1;
}
