// Per-stage profile (core/include/mptrack/profile.h): exclusive stage
// accounting and step statistics with a scripted clock, and the hooks of
// MfbpTracker::step and VmpTracker::step compiled in (this TU defines MPTRACK_PROFILE=1 before
// any include; nothing else in this executable includes core).
#define MPTRACK_PROFILE 1

#include <doctest/doctest.h>

#include <cstdint>
#include <memory>

#include "mfbp_scenario.h"
#include "mptrack/mfbp/mfbp_tracker.h"
#include "mptrack/profile.h"
#include "mptrack/vmp/vmp_tracker.h"
#include "vmp_test_frames.h"

using mptrack::profile::MfbpStage;
using mptrack::profile::ScopedStage;
using mptrack::profile::ScopedStep;
using mptrack::profile::StageProfile;

namespace {

// Scripted clock: each read returns the next value of a fixed sequence.
std::uint32_t g_script[16];
std::size_t g_pos = 0;
std::uint32_t scripted() { return g_script[g_pos++]; }

// Counting clock: 1 tick per read.
std::uint32_t g_ticks = 0;
std::uint32_t counting() { return ++g_ticks; }

}  // namespace

TEST_CASE("profile: a nested stage pauses the outer one (exclusive time)") {
  StageProfile<3> p;
  p.set_clock(&scripted);
  // reads: outer start 100, inner start 130 (outer +30), inner end 170
  // (inner +40, outer resumes), outer end 200 (outer +30).
  const std::uint32_t seq[] = {100u, 130u, 170u, 200u};
  for (std::size_t i = 0; i < 4; ++i) g_script[i] = seq[i];
  g_pos = 0;
  {
    ScopedStep<3> step(p);
    ScopedStage<3> outer(p, 0);
    {
      ScopedStage<3> inner(p, 2);
    }
  }
  CHECK(g_pos == 4u);
  CHECK(p.steps() == 1u);
  CHECK(p.last()[0] == 60u);
  CHECK(p.last()[1] == 0u);
  CHECK(p.last()[2] == 40u);
}

TEST_CASE("profile: deltas are taken modulo 2^32 across a counter wrap") {
  StageProfile<1> p;
  p.set_clock(&scripted);
  g_script[0] = 0xFFFFFFF0u;
  g_script[1] = 0x00000010u;
  g_pos = 0;
  {
    ScopedStep<1> step(p);
    ScopedStage<1> s(p, 0);
  }
  CHECK(p.last()[0] == 0x20u);
}

TEST_CASE("profile: min, max and total over steps; repeated stages in a step add up") {
  StageProfile<2> p;
  p.set_clock(&scripted);
  // step 1: stage 0 twice (5 + 7), step 2: stage 0 once (3), stage 1 (9).
  const std::uint32_t seq[] = {0u, 5u, 10u, 17u, 20u, 23u, 30u, 39u};
  for (std::size_t i = 0; i < 8; ++i) g_script[i] = seq[i];
  g_pos = 0;
  {
    ScopedStep<2> step(p);
    { ScopedStage<2> a(p, 0); }
    { ScopedStage<2> b(p, 0); }
  }
  CHECK(p.last()[0] == 12u);
  {
    ScopedStep<2> step(p);
    { ScopedStage<2> a(p, 0); }
    { ScopedStage<2> b(p, 1); }
  }
  CHECK(p.steps() == 2u);
  CHECK(p.last()[0] == 3u);
  CHECK(p.last()[1] == 9u);
  CHECK(p.min()[0] == 3u);
  CHECK(p.max()[0] == 12u);
  CHECK(p.total()[0] == 15u);
  CHECK(p.min()[1] == 0u);
  CHECK(p.max()[1] == 9u);
}

TEST_CASE("profile: a nested step scope (flush inside a step) closes only once") {
  StageProfile<1> p;
  p.set_clock(&counting);
  {
    ScopedStep<1> outer(p);
    ScopedStep<1> inner(p);
  }
  CHECK(p.steps() == 1u);
}

TEST_CASE("profile: MfbpTracker::step reports one step and its stages into g_mfbp") {
  auto& prof = mptrack::profile::g_mfbp;
  prof.reset();
  prof.set_clock(&counting);
  auto trk = std::make_unique<mptrack::MfbpTracker<float, mptrack::SmallBoardCaps>>();
  mptrack::MfbpParams<float> params = mptrack::seed000_default_params<float>();
  params.window_length = 1;
  params.slide = 1;
  params.uniform_rate_per_scan = 10.0f;
  REQUIRE(trk->init(params) == mptrack::Status::kOk);
  mfbp_test::Lcg rng;
  auto scan = std::make_unique<mptrack::Scan<float, mptrack::SmallBoardCaps::kMaxMeasurements>>();
  for (int k = 0; k < 12; ++k) {
    mfbp_test::make_scan(rng, k, 10, *scan);
    (void)trk->step(*scan);
  }
  CHECK(prof.steps() == 12u);
  // The online filter processes a window every scan: every stage ran.
  for (std::size_t s = 0; s < static_cast<std::size_t>(MfbpStage::kCount); ++s) {
    CAPTURE(mptrack::profile::stage_name(static_cast<MfbpStage>(s)));
    CHECK(prof.total()[s] > 0u);
  }
  // Out-of-order scans return before the step scope: no step recorded.
  (void)trk->step(*scan);
  CHECK(prof.steps() == 12u);
  prof.set_clock(nullptr);
}

TEST_CASE("profile: VmpTracker::step reports one step and its stages into g_vmp") {
  auto& prof = mptrack::profile::g_vmp;
  prof.reset();
  prof.set_clock(&counting);
  auto trk = std::make_unique<mptrack::VmpTracker<float, mptrack::VmpSmallCaps>>();
  const mptrack::VmpParams params;
  REQUIRE(trk->init(params) == mptrack::Status::kOk);
  auto cube = std::make_unique<vmp_test::Cube>();
  vmp_test::Lcg rng{11u};
  for (std::uint64_t k = 0; k < 4; ++k) {
    vmp_test::clear(*cube, 100000u * k);
    vmp_test::add_echo(params, 10.0 + 0.4 * static_cast<double>(k), 20.0, 1.0, 0.0, *cube);
    vmp_test::add_noise(params, rng, *cube);
    (void)trk->step(*cube);
  }
  CHECK(prof.steps() == 4u);
  // A track lives from the first frame on: every stage ran.
  for (std::size_t s = 0; s < static_cast<std::size_t>(mptrack::profile::VmpStage::kCount); ++s) {
    CAPTURE(mptrack::profile::stage_name(static_cast<mptrack::profile::VmpStage>(s)));
    CHECK(prof.total()[s] > 0u);
  }
  (void)trk->step(*cube);  // out of order: refused before the step scope
  CHECK(prof.steps() == 4u);
  prof.set_clock(nullptr);
}
