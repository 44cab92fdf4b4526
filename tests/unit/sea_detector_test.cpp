// Sea-clutter detection chain (core/include/mptrack/seaclutter/): map,
// CFAR threshold, grid DBSCAN, patch codes, plots. Expected values are
// derived by hand in the comments (docs/algorithms/sea_clutter.md).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "alloc_guard.h"
#include "mptrack/seaclutter/sea_detector.h"

namespace sc = mptrack::seaclutter;
using mptrack::Status;
using Caps = sc::SeaClutterCaps;

namespace {

constexpr std::size_t kR = Caps::kRangeBins;
constexpr std::size_t kD = Caps::kDopplerBins;
constexpr double kPi = 3.14159265358979323846;

/// Unit tone exp(j 2 pi k p / D) in range bin m of an otherwise zero CPI.
void add_tone(std::vector<float>& re, std::vector<float>& im, std::size_t m, double k, double amp) {
  for (std::size_t p = 0; p < kD; ++p) {
    const double ph = 2.0 * kPi * k * static_cast<double>(p) / static_cast<double>(kD);
    re[m * kD + p] += static_cast<float>(amp * std::cos(ph));
    im[m * kD + p] += static_cast<float>(amp * std::sin(ph));
  }
}

/// Unit-power complex noise from a fixed LCG (platform-independent test input).
void add_noise(std::vector<float>& re, std::vector<float>& im, std::uint32_t seed) {
  std::uint32_t s = seed;
  auto uni = [&s]() {
    s = s * 1664525u + 1013904223u;
    return (static_cast<double>(s >> 8) + 0.5) / 16777216.0;
  };
  for (std::size_t i = 0; i < re.size(); ++i) {
    const double r = std::sqrt(-std::log(uni()));  // Rayleigh with E r^2 = 1
    const double ph = 2.0 * kPi * uni();
    re[i] += static_cast<float>(r * std::cos(ph));
    im[i] += static_cast<float>(r * std::sin(ph));
  }
}

/// A map accessor for PatchExtractor tests: constant power with exceptions.
struct FlatMap {
  float level = 1.0f;
  std::size_t peak_m = 0, peak_d = 0;
  float peak = 1.0f;
  float power(std::size_t m, std::size_t d) const { return (m == peak_m && d == peak_d) ? peak : level; }
};

}  // namespace

TEST_CASE("range-Doppler map: a tone at FFT bin k lands at k + D/2 with power (D a)^2 (rectangular window)") {
  auto map = std::make_unique<sc::RangeDopplerMap<Caps>>();
  REQUIRE(map->init(mptrack::frontend::WindowType::kRectangular) == Status::kOk);
  std::vector<float> re(kR * kD, 0.0f), im(kR * kD, 0.0f);
  add_tone(re, im, 7, 10.0, 0.5);   // +10 bins -> shifted bin 266
  add_tone(re, im, 8, 0.0, 1.0);    // zero Doppler -> bin 256
  REQUIRE(map->compute(re.data(), im.data()) == Status::kOk);
  CHECK(map->power(7, 266) == doctest::Approx(256.0 * 256.0).epsilon(1e-4));  // (512 * 0.5)^2
  CHECK(map->power(7, 10) < 1e-3f);
  CHECK(map->power(8, 256) == doctest::Approx(512.0 * 512.0).epsilon(1e-4));
  CHECK(map->power(9, 256) == 0.0f);
}

TEST_CASE("range-Doppler map: a non-finite sample is refused") {
  auto map = std::make_unique<sc::RangeDopplerMap<Caps>>();
  REQUIRE(map->init(mptrack::frontend::WindowType::kHann) == Status::kOk);
  std::vector<float> re(kR * kD, 0.0f), im(kR * kD, 0.0f);
  im[5] = std::nanf("");
  CHECK(map->compute(re.data(), im.data()) == Status::kInvalidInput);
}

TEST_CASE("detector: CA-CFAR threshold solves (1 + alpha / 2T)^-2T = 0.28 for T = 8") {
  auto det = std::make_unique<sc::SeaDetector<Caps>>();
  REQUIRE(det->init(sc::SeaDetectorParams{}) == Status::kOk);
  const double expected = 16.0 * (std::pow(0.28, -1.0 / 16.0) - 1.0);  // 1.3244...
  CHECK(det->cfar_alpha() == doctest::Approx(expected).epsilon(1e-9));
}

TEST_CASE("grid DBSCAN: a 3x3 block is one cluster; an isolated detection is noise") {
  auto db = std::make_unique<sc::GridDbscan<Caps>>();
  db->configure(1, 1, 5);
  db->clear();
  for (std::size_t m = 10; m <= 12; ++m) {
    for (std::size_t d = 100; d <= 102; ++d) db->mark_detection(m, d);
  }
  db->mark_detection(50, 300);
  db->find_core_cells();
  std::size_t cursor = 0;
  sc::ClusterSums s;
  auto unit = [](std::size_t, std::size_t) { return 4.0f; };  // amplitude 2 everywhere
  REQUIRE(db->next_cluster(&cursor, unit, s));
  CHECK(s.cells == 9u);
  CHECK(s.range_sum / s.weight == doctest::Approx(11.0));
  CHECK(s.doppler_sum / s.weight == doctest::Approx(101.0));
  CHECK_FALSE(db->next_cluster(&cursor, unit, s));  // the single cell has 1 < 5 neighbours
}

TEST_CASE("grid DBSCAN: a non-core cell next to a core cell joins its cluster as a border cell") {
  auto db = std::make_unique<sc::GridDbscan<Caps>>();
  db->configure(1, 1, 5);
  db->clear();
  // Plus shape around (20, 200): the centre sees 5 detections (core); each arm
  // sees 4 in its 3x3 window (itself, the centre, the two arms at a diagonal):
  // border cells, which join. (22, 202) sees only itself: noise, stays out.
  db->mark_detection(20, 200);
  db->mark_detection(19, 200);
  db->mark_detection(21, 200);
  db->mark_detection(20, 199);
  db->mark_detection(20, 201);
  db->mark_detection(22, 202);
  db->find_core_cells();
  std::size_t cursor = 0;
  sc::ClusterSums s;
  auto power = [](std::size_t, std::size_t d) { return d == 200 ? 9.0f : 1.0f; };
  REQUIRE(db->next_cluster(&cursor, power, s));
  CHECK(s.cells == 5u);
  CHECK(s.peak_power == 9.0f);
  CHECK_FALSE(db->next_cluster(&cursor, power, s));
}

TEST_CASE("patch codes: floor((dB over the median + 10) * 255 / 60), clipped") {
  auto px = std::make_unique<sc::PatchExtractor<Caps>>();
  REQUIRE(px->init(-10.0, 60.0) == Status::kOk);
  sc::PatchExtractor<Caps>::Patch patch{};
  FlatMap map;
  map.level = 3.0f;
  map.peak_m = 42;
  map.peak_d = 17;
  map.peak = 300.0f;  // +20 dB: floor(30 * 4.25) = floor(127.5) = 127
  px->extract(map, 40, patch);
  CHECK(patch[0] == 42);                 // 0 dB: floor(10 * 4.25) = 42
  CHECK(patch[2 * kD + 17] == 127);
  map.peak = 0.03f;                      // -20 dB: below the floor -> 0
  px->extract(map, 40, patch);
  CHECK(patch[2 * kD + 17] == 0);
  map.peak = 3.0e9f;                     // +90 dB: above the span -> 255
  px->extract(map, 40, patch);
  CHECK(patch[2 * kD + 17] == 255);
}

TEST_CASE("patch window: 5 rows centred on the plot, shifted inside the map at the edges") {
  using Px = sc::PatchExtractor<Caps>;
  CHECK(Px::start_row(50) == 48u);
  CHECK(Px::start_row(0) == 0u);
  CHECK(Px::start_row(1) == 0u);
  CHECK(Px::start_row(95) == 91u);
}

TEST_CASE("detector: a strong target in noise gives a plot at its range and Doppler, range rate -f lambda / 2") {
  auto det = std::make_unique<sc::SeaDetector<Caps>>();
  sc::SeaDetectorParams p;
  REQUIRE(det->init(p) == Status::kOk);
  std::vector<float> re(kR * kD, 0.0f), im(kR * kD, 0.0f);
  add_noise(re, im, 12345u);
  // Target over range bins 39..41 (like a 30 m boat), FFT bin +50: shifted bin
  // 306, f = 50 * 1000 / 512 = 97.656 Hz, rdot = -f c / (2 f_c) = -1.5574 m/s.
  for (std::size_t m = 39; m <= 41; ++m) add_tone(re, im, m, 50.0, 3.0);
  mptrack::test::NoAllocScope guard;
  const Status st = det->process(re.data(), im.data());
  CHECK(guard.allocations() == 0);
  CHECK((st == Status::kOk || st == Status::kPartial));
  REQUIRE(det->num_plots() > 0);
  std::size_t best = 0;
  for (std::size_t j = 1; j < det->num_plots(); ++j) {
    if (det->plot(j).peak_power > det->plot(best).peak_power) best = j;
  }
  const sc::SeaPlot& pl = det->plot(best);
  CHECK(pl.range_bin == doctest::Approx(40.0).epsilon(0.01));
  CHECK(pl.doppler_bin == doctest::Approx(306.0).epsilon(0.002));
  CHECK(pl.range_m == doctest::Approx(600.0).epsilon(0.01));
  CHECK(pl.range_rate_mps == doctest::Approx(-50.0 * 1000.0 / 512.0 * 299792458.0 / 9.4e9 / 2.0).epsilon(0.003));
  CHECK(pl.patch_index == best);
  CHECK(pl.patch_range_start == 38u);
  CHECK(det->patch(best)[2 * kD + 306] > det->patch(best)[2 * kD + 100]);
  mptrack::Scan<float, 64> scan;
  CHECK(det->to_scan(1000000u, scan) == Status::kOk);
  CHECK(scan.measurements.size() == det->num_plots());
  CHECK(scan.has_doppler);
  CHECK(scan.measurements[best].doppler_mps == pl.range_rate_mps);
}
