// The C API (core/include/mptrack/c/mptrack_c.h): the scene of
// c_api_scene.c (C99) run through the C API must give the C++ trackers'
// tracks bit for bit; memory, parameter and scan refusals are statuses.
#include <doctest/doctest.h>

#include <cstddef>
#include <cstdint>
#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "c_api_scene.h"
#include "mptrack/c/mptrack_c.h"
#include "mptrack/caps.h"
#include "mptrack/cbmember/cbmember_filter.h"
#include "mptrack/phd/phd_filter.h"
#include "mptrack/gnn/gnn_tracker.h"
#include "mptrack/mfbp/mfbp_tracker.h"

namespace {

template <class X>
using ScanOf = typename X::ScanType;

/// A C++ track report as the C API's track, written out here independently
/// of c_api_slot.h into t, zeroed first so that padding bytes compare equal
/// (in place: a copy need not keep padding).
void write_c_track(const mptrack::TrackReport<float>& r, mptrack_track& t) {
  std::memset(&t, 0, sizeof t);
  t.id = r.id;
  for (int a = 0; a < 4; ++a) {
    t.state[a] = r.state(a);
    for (int b = 0; b < 4; ++b) t.covariance[4 * a + b] = r.covariance(a, b);
  }
  t.existence = r.existence;
  t.snr = r.snr;
  t.confirmed = r.confirmed ? 1 : 0;
  t.measurement_index = r.measurement_index;
}

/// The C++ tracker on the scene's detections: every track of every
/// finalised scan, in output order, as the C records are.
template <class X>
std::vector<c_api_record> run_cpp(X& tracker) {
  std::vector<c_api_record> out;
  ScanOf<X> scan;
  auto collect = [&] {
    for (std::size_t o = 0; o < tracker.outputs().size(); ++o) {
      const auto& e = tracker.outputs()[o];
      for (std::size_t i = 0; i < e.tracks.size(); ++i) {
        c_api_record rec{};
        rec.scan_index = e.scan_index;
        rec.time_us = e.time_us;
        write_c_track(e.tracks[i], rec.track);
        out.push_back(rec);
      }
    }
  };
  for (std::uint32_t k = 0; k < kCApiSceneScans; ++k) {
    mptrack_detection d[kCApiSceneMaxDetections];
    const std::size_t n = c_api_scene_scan(k, d);
    scan.time_us = c_api_scene_time_us(k);
    scan.measurements.clear();
    for (std::size_t j = 0; j < n; ++j) {
      mptrack::Measurement<float> m;
      m.range_m = d[j].range_m;
      m.azimuth_rad = d[j].azimuth_rad;
      m.amplitude = d[j].amplitude;
      REQUIRE(scan.measurements.push_back(m) == mptrack::Status::kOk);
    }
    const mptrack::Status s = tracker.step(scan);
    REQUIRE((s == mptrack::Status::kOk || s == mptrack::Status::kPartial));
    collect();
  }
  REQUIRE(tracker.flush() == mptrack::Status::kOk);
  collect();
  return out;
}

/// Byte-wise equality of two record lists (bit patterns of every float).
void require_bit_identical(const std::vector<c_api_record>& c, const std::vector<c_api_record>& cpp) {
  REQUIRE(c.size() == cpp.size());
  for (std::size_t i = 0; i < c.size(); ++i) {
    INFO("record " << i << " scan " << c[i].scan_index << " track " << c[i].track.id);
    CHECK(c[i].scan_index == cpp[i].scan_index);
    CHECK(c[i].time_us == cpp[i].time_us);
    CHECK(std::memcmp(&c[i].track, &cpp[i].track, sizeof(mptrack_track)) == 0);
  }
}

std::vector<c_api_record> run_c(c_api_tracker which, mptrack_counters& counters) {
  static c_api_record records[kCApiSceneMaxRecords];
  std::memset(records, 0, sizeof records);  // padding bytes compare equal
  std::size_t n = 0;
  REQUIRE(c_api_scene_run(which, records, kCApiSceneMaxRecords, &n, &counters) == MPTRACK_OK);
  return std::vector<c_api_record>(records, records + n);
}

std::size_t confirmed_ids(const std::vector<c_api_record>& r) {
  std::vector<std::uint32_t> ids;
  for (const auto& x : r) {
    if (x.track.confirmed != 0 && std::find(ids.begin(), ids.end(), x.track.id) == ids.end()) {
      ids.push_back(x.track.id);
    }
  }
  return ids.size();
}

mptrack_mfbp_storage g_mem;

mptrack_detection g_many[300];

}  // namespace

TEST_CASE("MF-BP through the C API reports the C++ tracker's tracks bit for bit") {
  mptrack_counters c{};
  const std::vector<c_api_record> from_c = run_c(kCApiMfbp, c);
  static mptrack::MfbpTracker<float, mptrack::DefaultCaps> tracker;
  REQUIRE(tracker.init(mptrack::MfbpParams<float>{}) == mptrack::Status::kOk);
  const std::vector<c_api_record> from_cpp = run_cpp(tracker);
  CHECK(confirmed_ids(from_c) == 2);  // the scene's two targets
  require_bit_identical(from_c, from_cpp);
  CHECK(c.scans == tracker.counters().scans);
  CHECK(c.measurements_invalid == tracker.counters().measurements_invalid);
  CHECK(c.tracks_born == tracker.counters().tracks_born);
}

TEST_CASE("MF-BP with mptrack_mfbp_every_scan_params reports every_scan_smoother_params' tracks bit for bit") {
  mptrack_mfbp_params d, e;
  mptrack_mfbp_default_params(&d);
  mptrack_mfbp_every_scan_params(&e);
  CHECK(d.slide == 3u);
  CHECK(d.confirm_lookahead_in_clutter == 0u);
  CHECK(e.slide == 1u);
  CHECK(e.confirm_lookahead_in_clutter == 2u);
  CHECK(d.birth_in_clutter_max_cnr == 0.0f);
  CHECK(e.birth_in_clutter_max_cnr == 6.0f);
  mptrack_counters c{};
  const std::vector<c_api_record> from_c = run_c(kCApiMfbpEveryScan, c);
  static mptrack::MfbpTracker<float, mptrack::DefaultCaps> tracker;
  REQUIRE(tracker.init(mptrack::every_scan_smoother_params<float>()) == mptrack::Status::kOk);
  const std::vector<c_api_record> from_cpp = run_cpp(tracker);
  CHECK(confirmed_ids(from_c) == 2);
  require_bit_identical(from_c, from_cpp);
  CHECK(c.tracks_born == tracker.counters().tracks_born);
}

TEST_CASE("GNN through the C API reports the C++ tracker's tracks bit for bit") {
  mptrack_counters c{};
  const std::vector<c_api_record> from_c = run_c(kCApiGnn, c);
  // The scene's GNN parameters, written out independently of c_api_scene.c.
  mptrack::GnnParams<float> p;
  p.region = {10000.0f, 50000.0f, 0.17453292f, 1.0471976f};
  p.noise.range_std_m = 20.0f;
  p.noise.azimuth_std_rad = 0.0104719755f;
  p.init_velocity_std_mps = 50.0f;
  static mptrack::GnnTracker<float, mptrack::DefaultCaps> tracker;
  REQUIRE(tracker.init(p) == mptrack::Status::kOk);
  const std::vector<c_api_record> from_cpp = run_cpp(tracker);
  CHECK(confirmed_ids(from_c) >= 2);
  require_bit_identical(from_c, from_cpp);
  CHECK(c.scans == kCApiSceneScans);
  CHECK(c.tracks_confirmed == tracker.counters().tracks_confirmed);
}

/// The scene's RFS parameters, written out independently of c_api_scene.c.
mptrack::RfsFilterParams<float> scene_rfs_params() {
  mptrack::RfsFilterParams<float> p;
  p.space = mptrack::MeasurementSpace::kPolar;
  p.region = {10000.0f, 50000.0f, 0.17453292f, 1.0471976f};
  p.noise.range_std_m = 20.0f;
  p.noise.azimuth_std_rad = 0.0104719755f;
  p.hotspot_half_width0 = 500.0f;
  p.hotspot_half_width1 = 0.034906585f;
  return p;
}

template <class X>
void check_rfs_filter(c_api_tracker which) {
  mptrack_counters c{};
  const std::vector<c_api_record> from_c = run_c(which, c);
  static X tracker;
  REQUIRE(tracker.init(scene_rfs_params()) == mptrack::Status::kOk);
  const std::vector<c_api_record> from_cpp = run_cpp(tracker);
  CHECK(!from_c.empty());
  require_bit_identical(from_c, from_cpp);
  CHECK(c.measurements_invalid == tracker.counters().measurements_invalid);
}

TEST_CASE("GM-PHD, GM-CPHD and CBMeMBer through the C API report the C++ filters' tracks bit for bit") {
  SUBCASE("GM-PHD") { check_rfs_filter<mptrack::GmPhdFilter<float, mptrack::DefaultCaps>>(kCApiGmPhd); }
  SUBCASE("GM-CPHD") { check_rfs_filter<mptrack::GmCphdFilter<float, mptrack::DefaultCaps>>(kCApiGmCphd); }
  SUBCASE("CBMeMBer") { check_rfs_filter<mptrack::CbMemberFilter<float, mptrack::DefaultCaps>>(kCApiCbMember); }
}

TEST_CASE("mptrack_status_string names every status and no other value") {
  CHECK(std::string(mptrack_status_string(MPTRACK_OK)) == "ok");
  CHECK(std::string(mptrack_status_string(MPTRACK_INVALID_ARGUMENT)) == "invalid_argument");
  CHECK(std::string(mptrack_status_string(MPTRACK_OUT_OF_ORDER)) == "out_of_order");
  CHECK(std::string(mptrack_status_string(MPTRACK_PARTIAL)) == "partial");
  CHECK(std::string(mptrack_status_string(static_cast<mptrack_status>(10))) == "unknown");
  CHECK(std::string(mptrack_status_string(static_cast<mptrack_status>(15))) == "unknown");
}

TEST_CASE("init refuses memory that is too small, misaligned or missing") {
  CHECK(mptrack_mfbp_size() <= sizeof(mptrack_mfbp_storage));
  CHECK(mptrack_gnn_size() <= sizeof(mptrack_gnn_storage));
  CHECK(mptrack_gmphd_size() <= sizeof(mptrack_gmphd_storage));
  CHECK(mptrack_gmcphd_size() <= sizeof(mptrack_gmphd_storage));
  CHECK(mptrack_cbmember_size() <= sizeof(mptrack_cbmember_storage));
  CHECK(mptrack_mfbp_alignment() <= alignof(mptrack_mfbp_storage));
  mptrack_mfbp_params p;
  mptrack_mfbp_default_params(&p);
  mptrack_tracker* t = reinterpret_cast<mptrack_tracker*>(&g_mem);  // must be reset to NULL
  CHECK(mptrack_mfbp_init(&g_mem, mptrack_mfbp_size() - 1, &p, &t, nullptr) == MPTRACK_INVALID_ARGUMENT);
  CHECK(t == nullptr);
  CHECK(mptrack_mfbp_init(g_mem.bytes + 1, sizeof g_mem - 1, &p, &t, nullptr) == MPTRACK_INVALID_ARGUMENT);
  CHECK(mptrack_mfbp_init(nullptr, sizeof g_mem, &p, &t, nullptr) == MPTRACK_INVALID_ARGUMENT);
  CHECK(mptrack_mfbp_init(&g_mem, sizeof g_mem, nullptr, &t, nullptr) == MPTRACK_INVALID_ARGUMENT);
  CHECK(t == nullptr);
}

TEST_CASE("init names the refused parameter and leaves no tracker") {
  mptrack_mfbp_params p;
  mptrack_mfbp_default_params(&p);
  p.gate_chi2 = -1.0f;
  mptrack_tracker* t = nullptr;
  mptrack_param_error err{nullptr, nullptr};
  CHECK(mptrack_mfbp_init(&g_mem, sizeof g_mem, &p, &t, &err) == MPTRACK_INVALID_ARGUMENT);
  CHECK(t == nullptr);
  REQUIRE(err.field != nullptr);
  CHECK(std::string(err.field) == "gate_chi2");
  mptrack_mfbp_default_params(&p);
  p.window_length = 8;  // DefaultCaps::kMaxWindow is 7
  CHECK(mptrack_mfbp_init(&g_mem, sizeof g_mem, &p, &t, &err) == MPTRACK_INVALID_ARGUMENT);
  CHECK(std::string(err.field) == "window_length");
  mptrack_gnn_params g;
  mptrack_gnn_default_params(&g);
  g.confirm_window = 33;
  static mptrack_gnn_storage gmem;
  CHECK(mptrack_gnn_init(&gmem, sizeof gmem, &g, &t, &err) == MPTRACK_INVALID_ARGUMENT);
  CHECK(std::string(err.field) == "confirm_window");  // <= 32 (GnnParams::kMaxConfirmWindow)
}

TEST_CASE("a scan over the detection cap is refused whole and counted") {
  static mptrack_gnn_storage mem;
  mptrack_gnn_params p;
  c_api_scene_gnn_params(&p);
  mptrack_tracker* t = nullptr;
  REQUIRE(mptrack_gnn_init(&mem, sizeof mem, &p, &t, nullptr) == MPTRACK_OK);
  REQUIRE(mptrack_max_detections(t) == mptrack::DefaultCaps::kMaxMeasurements);
  mptrack_detection d[kCApiSceneMaxDetections];
  mptrack_scan scan{c_api_scene_time_us(0), 0, c_api_scene_scan(0, d), d};
  REQUIRE(mptrack_step(t, &scan) == MPTRACK_OK);
  REQUIRE(mptrack_num_outputs(t) == 1);
  const mptrack_scan big{c_api_scene_time_us(1), 0, mptrack::DefaultCaps::kMaxMeasurements + 1, g_many};
  CHECK(mptrack_step(t, &big) == MPTRACK_CAPACITY_EXCEEDED);
  CHECK(mptrack_num_outputs(t) == 0);  // a refused scan finalises nothing
  mptrack_counters c{};
  REQUIRE(mptrack_get_counters(t, &c) == MPTRACK_OK);
  CHECK(c.scans_over_detection_cap == 1);
  CHECK(c.scans == 1);
  scan.time_us = c_api_scene_time_us(1);  // the same time is still free
  CHECK(mptrack_step(t, &scan) == MPTRACK_OK);
  CHECK(mptrack_num_outputs(t) == 1);
  mptrack_deinit(t);
}

TEST_CASE("an out-of-order scan is refused and a deinit tracker refuses every call") {
  static mptrack_gnn_storage mem;
  mptrack_gnn_params p;
  c_api_scene_gnn_params(&p);
  mptrack_tracker* t = nullptr;
  REQUIRE(mptrack_gnn_init(&mem, sizeof mem, &p, &t, nullptr) == MPTRACK_OK);
  mptrack_detection d[kCApiSceneMaxDetections];
  mptrack_scan scan{c_api_scene_time_us(3), 0, c_api_scene_scan(3, d), d};
  REQUIRE(mptrack_step(t, &scan) == MPTRACK_OK);
  scan.time_us = c_api_scene_time_us(2);
  CHECK(mptrack_step(t, &scan) == MPTRACK_OUT_OF_ORDER);
  mptrack_counters c{};
  REQUIRE(mptrack_get_counters(t, &c) == MPTRACK_OK);
  CHECK(c.scans_rejected == 1);
  mptrack_deinit(t);
  scan.time_us = c_api_scene_time_us(4);
  CHECK(mptrack_step(t, &scan) == MPTRACK_NOT_INITIALIZED);
  CHECK(mptrack_num_outputs(t) == 0);
  CHECK(mptrack_get_counters(t, &c) == MPTRACK_NOT_INITIALIZED);
  CHECK(mptrack_step(nullptr, &scan) == MPTRACK_NOT_INITIALIZED);
}

TEST_CASE("mptrack_provisional hands out the C++ tracker's provisional estimate bit for bit, and none for GNN") {
  mptrack_mfbp_params p;
  mptrack_mfbp_every_scan_params(&p);
  mptrack_tracker* t = nullptr;
  REQUIRE(mptrack_mfbp_init(&g_mem, sizeof g_mem, &p, &t, nullptr) == MPTRACK_OK);
  static mptrack::MfbpTracker<float, mptrack::DefaultCaps> tracker;
  REQUIRE(tracker.init(mptrack::every_scan_smoother_params<float>()) == mptrack::Status::kOk);
  ScanOf<mptrack::MfbpTracker<float, mptrack::DefaultCaps>> cpp_scan;
  std::size_t provisional_tracks = 0;
  for (std::uint32_t k = 0; k < kCApiSceneScans; ++k) {
    mptrack_detection d[kCApiSceneMaxDetections];
    const mptrack_scan scan{c_api_scene_time_us(k), 0, c_api_scene_scan(k, d), d};
    cpp_scan.time_us = scan.time_us;
    cpp_scan.measurements.clear();
    for (std::size_t j = 0; j < scan.num_detections; ++j) {
      mptrack::Measurement<float> m;
      m.range_m = d[j].range_m;
      m.azimuth_rad = d[j].azimuth_rad;
      m.amplitude = d[j].amplitude;
      REQUIRE(cpp_scan.measurements.push_back(m) == mptrack::Status::kOk);
    }
    REQUIRE(mptrack_step(t, &scan) == static_cast<mptrack_status>(tracker.step(cpp_scan)));
    mptrack_output_info info{};
    mptrack_track tracks[8];
    std::memset(tracks, 0, sizeof tracks);
    std::size_t n = 0;
    const mptrack_status st = mptrack_provisional(t, &info, tracks, 8, &n);
    INFO("scan " << k);
    REQUIRE((st == MPTRACK_OK) == tracker.has_provisional());
    if (st != MPTRACK_OK) continue;
    const auto& e = tracker.provisional();
    CHECK(info.scan_index == k);
    CHECK(info.scan_index == e.scan_index);
    CHECK(info.time_us == e.time_us);
    REQUIRE(n == e.tracks.size());
    for (std::size_t i = 0; i < n; ++i) {
      mptrack_track expected;
      write_c_track(e.tracks[i], expected);
      CHECK(std::memcmp(&tracks[i], &expected, sizeof(mptrack_track)) == 0);
    }
    provisional_tracks += n;
  }
  CHECK(provisional_tracks > 0u);
  REQUIRE(mptrack_flush(t) == MPTRACK_OK);
  mptrack_output_info info{};
  std::size_t n = 0;
  CHECK(mptrack_provisional(t, &info, nullptr, 0, &n) == MPTRACK_INVALID_ARGUMENT);  // flush() leaves none
  mptrack_deinit(t);

  static mptrack_gnn_storage gnn_mem;
  mptrack_gnn_params g;
  c_api_scene_gnn_params(&g);
  REQUIRE(mptrack_gnn_init(&gnn_mem, sizeof gnn_mem, &g, &t, nullptr) == MPTRACK_OK);
  mptrack_detection d[kCApiSceneMaxDetections];
  const mptrack_scan scan{c_api_scene_time_us(0), 0, c_api_scene_scan(0, d), d};
  REQUIRE(mptrack_step(t, &scan) == MPTRACK_OK);
  CHECK(mptrack_provisional(t, &info, nullptr, 0, &n) == MPTRACK_INVALID_ARGUMENT);  // GNN's outputs have no lag
  mptrack_deinit(t);
}
