// The seed002-othr detections the Cortex-M7 scan-cost report runs on
// (tests/support/othr_scan_file.h for the layout): run 0 (seed 1) of the four
// Table IV cells, generated here exactly as `mptrack-sim --scenario
// seed002-othr --pd P --clutter-scale S` generates them, with the multipath
// tracker's Params as its harness adapter sets them (trackers/othr_setup.h,
// lag 3, the cross-range bearing PSD). The committed file must equal the generator's output byte for byte.
// Regenerate (after an intended generator change):
//   MPTRACK_GOLDEN_REGENERATE=1 ./seed002_scans_golden_test
#include <doctest/doctest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>

#include "mptrack/caps.h"
#include "mptrack/multipath/multipath_tracker.h"
#include "mptrack/scenario/builtin.h"
#include "mptrack/scenario/generator.h"
#include "othr_scan_file.h"
#include "trackers/othr_setup.h"

namespace {

namespace sc = mptrack::scenario;
using BigScan = mptrack::Scan<float, mptrack::LargeCaps::kMaxMeasurements>;

const std::string kPath = std::string(MPTRACK_GOLDEN_DIR) + "/seed002_othr_run0.scans";

struct CellSpec {
  double pd;
  double clutter_scale;
};
constexpr CellSpec kCells[] = {{0.75, 1.0}, {0.75, 3.2}, {0.4, 1.0}, {0.4, 3.2}};

void put_u32(std::string& out, std::uint32_t v) {
  for (int b = 0; b < 4; ++b) out.push_back(static_cast<char>((v >> (8 * b)) & 0xffu));
}
void put_f32(std::string& out, float f) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &f, sizeof bits);
  put_u32(out, bits);
}
std::uint32_t milli(double v) { return static_cast<std::uint32_t>(v * 1000.0 + 0.5); }

/// The tracker's Params as the mfbp-multipath adapter sets them.
mptrack::MultipathParams<float> harness_params(const sc::ScenarioSpec& spec, double clutter_scale) {
  mptrack::sim::TrackerSetup setup;
  setup.spec = spec;
  setup.clutter_scale = clutter_scale;
  mptrack::MultipathParams<float> p;
  mptrack::sim::configure_othr(setup, p);
  for (std::size_t i = 0; i < spec.othr.paths.size() && i < p.pd.size(); ++i) {
    const double pd = spec.othr.paths[i].pd;
    p.pd[i] = static_cast<float>(pd < 0.999 ? pd : 0.999);
  }
  p.smoothing_lag_scans = 3;
  p.bearing_psd_rad2ps3 = mptrack::sim::othr_cross_range_bearing_psd(p.range_psd_m2ps3, p.region);
  return p;
}

void put_cell(std::string& out, const CellSpec& cell) {
  sc::ScenarioSpec spec;
  REQUIRE(sc::builtin_scenario("seed002-othr", spec));
  for (auto& path : spec.othr.paths) path.pd = cell.pd;  // what --pd does
  const mptrack::MultipathParams<float> p = harness_params(spec, cell.clutter_scale);
  put_u32(out, milli(cell.pd));
  put_u32(out, milli(cell.clutter_scale));
  put_u32(out, spec.num_scans);
  put_u32(out, p.num_paths);
  for (std::uint32_t i = 0; i < p.num_paths; ++i) {
    put_f32(out, p.paths[i].tx_height_km);
    put_f32(out, p.paths[i].rx_height_km);
    put_f32(out, p.pd[i]);
  }
  for (float v : {p.baseline_km, p.region.range_min_m, p.region.range_max_m, p.region.azimuth_min_rad,
                  p.region.azimuth_max_rad, p.range_rate_span_mps, p.noise.range_std_m, p.noise.azimuth_std_rad,
                  p.noise.doppler_std_mps, p.clutter_mean_count, p.max_gap_s, p.bearing_psd_rad2ps3}) {
    put_f32(out, v);
  }
  put_u32(out, p.smoothing_lag_scans);
  sc::Generator gen;
  sc::GeneratorOptions options;
  options.clutter_scale = cell.clutter_scale;
  REQUIRE(gen.init(spec, 1, 0, options) == mptrack::Status::kOk);
  static BigScan scan;
  sc::SimScan sim;
  for (std::uint32_t k = 1; k <= spec.num_scans; ++k) {
    REQUIRE(gen.generate(k, sim) == mptrack::Status::kOk);
    REQUIRE(sc::to_scan(sim, scan) == mptrack::Status::kOk);
    put_u32(out, static_cast<std::uint32_t>(scan.time_us & 0xffffffffu));
    put_u32(out, static_cast<std::uint32_t>(scan.time_us >> 32));
    put_u32(out, static_cast<std::uint32_t>(scan.measurements.size()));
    for (const auto& m : scan.measurements) {
      put_f32(out, m.range_m);
      put_f32(out, m.azimuth_rad);
      put_f32(out, m.doppler_mps);
    }
  }
}

std::string generate_file() {
  std::string out;
  put_u32(out, mptrack::test::othr_file::kMagic);
  put_u32(out, static_cast<std::uint32_t>(std::size(kCells)));
  for (const CellSpec& c : kCells) put_cell(out, c);
  return out;
}

}  // namespace

TEST_CASE("seed002 scans golden: the committed file is run 0 of the four Table IV cells, byte for byte") {
  const std::string generated = generate_file();
  const char* regen = std::getenv("MPTRACK_GOLDEN_REGENERATE");
  if (regen != nullptr && std::strcmp(regen, "1") == 0) {
    std::ofstream(kPath, std::ios::binary) << generated;
  }
  std::ifstream in(kPath, std::ios::binary);
  const std::string committed((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(committed.size() == generated.size());
  CHECK(committed == generated);
}

TEST_CASE("seed002 scans golden: the reader gives back the harness Params and every detection") {
  const std::string bytes = generate_file();
  const auto* begin = reinterpret_cast<const unsigned char*>(bytes.data());
  mptrack::test::othr_file::Reader r(begin, begin + bytes.size());
  REQUIRE(r.u32() == mptrack::test::othr_file::kMagic);
  REQUIRE(r.u32() == 4u);
  static BigScan scan;
  std::size_t detections = 0;
  for (const CellSpec& c : kCells) {
    mptrack::test::othr_file::Cell cell;
    REQUIRE(mptrack::test::othr_file::read_cell(r, cell));
    CHECK(cell.pd_milli == milli(c.pd));
    CHECK(cell.params.pd[0] == static_cast<float>(c.pd));
    CHECK(cell.params.smoothing_lag_scans == 3u);
    CHECK(cell.params.clutter_mean_count == doctest::Approx(125.0 * c.clutter_scale));
    CHECK(cell.params.validate() == mptrack::Status::kOk);
    for (std::uint32_t k = 0; k < cell.num_scans; ++k) {
      REQUIRE(mptrack::test::othr_file::read_scan(r, scan));
      detections += scan.measurements.size();
    }
  }
  CHECK(r.ok());
  CHECK(r.u32() == 0u);  // nothing left
  CHECK_FALSE(r.ok());
  MESSAGE("detections in the file: " << detections);
}

namespace {

/// What the Cortex-M7 report prints for one cell (multipath_scan_cost.cpp).
template <class Tracker>
void run_like_the_m7(mptrack::test::othr_file::Reader& r, const mptrack::test::othr_file::Cell& cell) {
  auto trk = std::make_unique<Tracker>();
  auto scan = std::make_unique<typename Tracker::ScanType>();
  REQUIRE(trk->init(cell.params) == mptrack::Status::kOk);
  std::uint32_t hash = mptrack::test::othr_file::kHashSeed;
  for (std::uint32_t k = 0; k < cell.num_scans; ++k) {
    REQUIRE(mptrack::test::othr_file::read_scan(r, *scan));
    REQUIRE(mptrack::test::othr_file::accepted(trk->step(*scan)));
    hash = mptrack::test::othr_file::hash_outputs(*trk, hash);
  }
  CHECK(trk->counters().tracks_confirmed >= 2u);
  MESSAGE("pd " << cell.pd_milli << "/1000 clutter x" << cell.clutter_scale_milli << "/1000: confirmed "
                << trk->counters().tracks_confirmed << ", cap hits " << mptrack::total_cap_hits(trk->counters())
                << " (association " << trk->counters().association_cap_hits << "), output hash " << hash);
}

}  // namespace

TEST_CASE("seed002 scans golden: the host's output hashes for the M7 report to match") {
  const std::string bytes = generate_file();
  const auto* begin = reinterpret_cast<const unsigned char*>(bytes.data());
  mptrack::test::othr_file::Reader r(begin, begin + bytes.size());
  REQUIRE(r.u32() == mptrack::test::othr_file::kMagic);
  const std::uint32_t cells = r.u32();
  for (std::uint32_t c = 0; c < cells; ++c) {
    mptrack::test::othr_file::Cell cell;
    REQUIRE(mptrack::test::othr_file::read_cell(r, cell));
    if (cell.clutter_scale_milli <= 1000u) {
      run_like_the_m7<mptrack::MultipathMfbpTracker<float, mptrack::DefaultCaps>>(r, cell);
    } else {
      run_like_the_m7<mptrack::MultipathMfbpTracker<float, mptrack::test::othr_file::Nc400Caps>>(r, cell);
    }
  }
}

TEST_CASE("seed002 harness: the bearing PSD is 1e-8 km^2/s^3 over the squared mid-region range, 1750 km") {
  sc::ScenarioSpec spec;
  REQUIRE(sc::builtin_scenario("seed002-othr", spec));
  const mptrack::MultipathParams<float> p = harness_params(spec, 1.0);
  // By hand: range PSD 1e-2 m^2/s^3 = 1e-8 km^2/s^3; region 1500..2000 km.
  CHECK(p.bearing_psd_rad2ps3 == doctest::Approx(1e-8 / (1750.0 * 1750.0)).epsilon(1e-5));
}
