// Bit-exact golden vectors of the MF-BP tracker (float): 30 scans of the
// small two-target scenario (tests/unit/mfbp_scenario.h), online filter and
// window-7 smoother. Every finalised confirmed track's id, state,
// existence and SNR are recorded as raw bits, plus the counters; the same
// file must match on x86-64, aarch64 and armhf (qemu).
#include <doctest/doctest.h>

#include <memory>
#include <string>

#include "golden.h"
#include "../unit/mfbp_scenario.h"
#include "mptrack/mfbp/mfbp_tracker.h"

using namespace mptrack;

using mfbp_test::TestCaps;

namespace {

using Tracker = MfbpTracker<float, TestCaps>;

void record(const Tracker& trk, test::GoldenFile& g, const std::string& tag) {
  for (const auto& est : trk.outputs()) {
    const std::string k = tag + ".k" + std::to_string(est.scan_index);
    g.add(k + ".n", static_cast<int>(est.tracks.size()));
    for (const auto& t : est.tracks) {
      const std::string p = k + ".id" + std::to_string(t.id);
      for (int i = 0; i < 4; ++i) g.add(p + ".x" + std::to_string(i), t.state(i));
      g.add(p + ".Pxx", t.covariance(0, 0));
      g.add(p + ".Pyy", t.covariance(2, 2));
      g.add(p + ".e", t.existence);
      g.add(p + ".snr", t.snr);
      g.add(p + ".j", static_cast<int>(t.measurement_index));
    }
    for (const auto& c : est.clutter) {
      const std::string p = k + ".c" + std::to_string(c.id);
      g.add(p + ".n", c.expected_count);
      g.add(p + ".cnr", c.cnr);
    }
  }
}

void run_case(std::size_t window, std::size_t slide, const std::string& tag, test::GoldenFile& g) {
  auto trk = std::make_unique<Tracker>();
  MfbpParams<float> p = seed000_default_params<float>();
  p.window_length = window;
  p.slide = slide;
  p.uniform_rate_per_scan = 10.0f;
  REQUIRE(trk->init(p) == Status::kOk);
  mfbp_test::Lcg rng;
  auto scan = std::make_unique<Scan<float, TestCaps::kMaxMeasurements>>();
  for (int k = 0; k < 30; ++k) {
    mfbp_test::make_scan(rng, k, 10, *scan);
    CHECK(trk->step(*scan) == Status::kOk);
    record(*trk, g, tag);
  }
  CHECK(trk->flush() == Status::kOk);
  record(*trk, g, tag);
  const auto& c = trk->counters();
  g.add(tag + ".born", c.tracks_born);
  g.add(tag + ".confirmed", c.tracks_confirmed);
  g.add(tag + ".deleted", c.tracks_deleted);
  g.add(tag + ".repairs", c.numerical_repairs);
  g.add(tag + ".bp_not_converged", c.bp_not_converged);
}

}  // namespace

TEST_CASE("mfbp golden: online filter and smoother, 30 scans, float bits") {
  test::GoldenFile g("mfbp_tracker");
  run_case(1, 1, "filter", g);
  run_case(7, 3, "smoother", g);
  CHECK(g.size() > 200u);
  CHECK(g.matches());
}
