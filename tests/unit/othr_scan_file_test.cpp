// The seed002-othr detections file reader (tests/support/othr_scan_file.h)
// on the committed file: runs on every Linux target, the big-endian ppc one
// included, so it checks that the reader assembles the little-endian words
// the same way everywhere. Expected values from the scenario (seed 002 Sec.
// IV: E 100 km, F 260 km, d 100 km, region 1500-2000 km x 0.428-0.608 rad)
// and from seed002_scans_golden_test's message (31 689 detections).
#include <doctest/doctest.h>

#include <cstdint>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>

#include "othr_scan_file.h"

namespace of = mptrack::test::othr_file;

namespace {

std::string committed_file() {
  std::ifstream in(std::string(MPTRACK_GOLDEN_DIR) + "/seed002_othr_run0.scans", std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

TEST_CASE("othr scan file: the first cell's header reads as pd 0.75, Nc 125, 30 scans, the EE/EF/FE/FF paths") {
  const std::string bytes = committed_file();
  REQUIRE(bytes.size() > 64u);
  const auto* begin = reinterpret_cast<const unsigned char*>(bytes.data());
  of::Reader r(begin, begin + bytes.size());
  CHECK(r.u32() == of::kMagic);
  CHECK(r.u32() == 4u);
  of::Cell cell;
  REQUIRE(of::read_cell(r, cell));
  CHECK(cell.pd_milli == 750u);
  CHECK(cell.clutter_scale_milli == 1000u);
  CHECK(cell.num_scans == 30u);
  REQUIRE(cell.params.num_paths == 4u);
  const float tx[4] = {100.0f, 100.0f, 260.0f, 260.0f};
  const float rx[4] = {100.0f, 260.0f, 100.0f, 260.0f};
  for (int i = 0; i < 4; ++i) {
    CHECK(cell.params.paths[static_cast<std::size_t>(i)].tx_height_km == tx[i]);
    CHECK(cell.params.paths[static_cast<std::size_t>(i)].rx_height_km == rx[i]);
    CHECK(cell.params.pd[static_cast<std::size_t>(i)] == 0.75f);
  }
  CHECK(cell.params.baseline_km == 100.0f);
  CHECK(cell.params.region.range_min_m == 1.5e6f);
  CHECK(cell.params.region.range_max_m == 2.0e6f);
  CHECK(cell.params.smoothing_lag_scans == 3u);
}

TEST_CASE("othr scan file: every detection of the four cells lies in the region and the file ends there") {
  const std::string bytes = committed_file();
  const auto* begin = reinterpret_cast<const unsigned char*>(bytes.data());
  of::Reader r(begin, begin + bytes.size());
  REQUIRE(r.u32() == of::kMagic);
  REQUIRE(r.u32() == 4u);
  auto scan = std::make_unique<mptrack::Scan<float, 512>>();
  std::size_t detections = 0;
  std::size_t outside = 0;
  for (int c = 0; c < 4; ++c) {
    of::Cell cell;
    REQUIRE(of::read_cell(r, cell));
    for (std::uint32_t k = 0; k < cell.num_scans; ++k) {
      REQUIRE(of::read_scan(r, *scan));
      for (const auto& m : scan->measurements) {
        ++detections;
        if (m.range_m < cell.params.region.range_min_m || m.range_m > cell.params.region.range_max_m ||
            m.azimuth_rad < cell.params.region.azimuth_min_rad || m.azimuth_rad > cell.params.region.azimuth_max_rad) {
          ++outside;
        }
      }
    }
  }
  CHECK(detections == 31689u);
  CHECK(outside == 0u);
  CHECK(r.ok());
  static_cast<void>(r.u32());
  CHECK_FALSE(r.ok());  // nothing after the last cell
}
