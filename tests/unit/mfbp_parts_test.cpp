// The MF-BP parts on their own: slot shifts and births (track_slot.h,
// clutter_slot.h), the window store's history rule (window_store.h), the
// caps accessors and the params check against them (mfbp_caps.h).
#include <doctest/doctest.h>

#include <cstddef>
#include <cstdint>
#include <memory>

#include "mptrack/mfbp/clutter_slot.h"
#include "mptrack/mfbp/mfbp_caps.h"
#include "mptrack/mfbp/mfbp_tracker.h"
#include "mptrack/mfbp/track_slot.h"
#include "mptrack/mfbp/window_store.h"

using namespace mptrack;

namespace {

struct Caps5 {  // no MF-BP members: the accessors must fall back to the defaults
  static constexpr std::size_t kMaxTargets = 4;
  static constexpr std::size_t kMaxMeasurements = 8;
  static constexpr std::size_t kMaxClutterComponents = 2;
  static constexpr std::size_t kMaxWindow = 5;
};

struct Caps5Small : Caps5 {  // with them
  static constexpr std::size_t kMaxGatePairs = 3;
  static constexpr std::size_t kMaxClutterGridCells = 100;
  static constexpr std::size_t kMaxBirthCandidates = 4;
};

using Slot = mfbp::TrackSlot<double, Caps5>;

// Every per-scan field of scan k gets a value that names the field and k.
double tag(int field, std::size_t k) { return 100.0 * field + static_cast<double>(k); }

void fill_scan(Slot& t, std::size_t k) {
  t.xf[k] = Slot::Vec4::Constant(tag(1, k));
  t.xs[k] = Slot::Vec4::Constant(tag(2, k));
  t.Pf[k].set(Slot::Mat4::Constant(tag(3, k)));
  t.Ps[k].set(Slot::Mat4::Constant(tag(4, k)));
  t.igf[k].b = tag(5, k);
  t.igs[k].b = tag(6, k);
  t.amp[k].s = tag(7, k);
  t.xi1[k] = tag(8, k);
  t.xi0[k] = tag(9, k);
  t.visf[k] = tag(10, k);
  t.vis[k] = tag(11, k);
  t.extr[k] = tag(12, k);
  t.missed[k] = tag(13, k);
  t.n_edges[k] = static_cast<std::uint8_t>(14 + k);
  t.edge_begin[k] = static_cast<std::uint16_t>(15 + k);
  t.best[k] = static_cast<std::int32_t>(17 + k);
  t.biasf[k] = Slot::Vec2::Constant(tag(18, k));
  t.qk[k] = tag(19, k);
  t.mate[k] = static_cast<std::uint16_t>(20 + k);
}

// True if window scan d holds what scan k held before the shift (all 19 fields).
bool holds_scan(const Slot& t, std::size_t d, std::size_t k) {
  return t.xf[d](0) == tag(1, k) && t.xs[d](3) == tag(2, k) && t.Pf[d].get()(1, 2) == tag(3, k) &&
         t.Ps[d].get()(3, 3) == tag(4, k) && t.igf[d].b == tag(5, k) && t.igs[d].b == tag(6, k) &&
         t.amp[d].s == tag(7, k) && t.xi1[d] == tag(8, k) && t.xi0[d] == tag(9, k) &&
         t.visf[d] == tag(10, k) && t.vis[d] == tag(11, k) && t.extr[d] == tag(12, k) &&
         t.missed[d] == tag(13, k) && std::size_t{t.n_edges[d]} == 14 + k && std::size_t{t.edge_begin[d]} == 15 + k &&
         t.best[d] == static_cast<std::int32_t>(17 + k) &&
         t.biasf[d](1) == tag(18, k) && t.qk[d] == tag(19, k) && std::size_t{t.mate[d]} == 20 + k;
}

}  // namespace

TEST_CASE("mfbp track slot shift: last finalised filtered beliefs become the prior, later scans move up") {
  auto t = std::make_unique<Slot>();
  t->start(7, 0, 0.6);
  for (std::size_t k = 0; k < 5; ++k) fill_scan(*t, k);
  t->shift(2, 5, 123456u);  // scans 0, 1 finalised; 2, 3, 4 stay
  CHECK(t->x0(2) == tag(1, 1));
  CHECK(t->P0(0, 3) == tag(3, 1));
  CHECK(t->ig0.b == tag(5, 1));
  CHECK(t->vis0 == tag(10, 1));
  CHECK(t->bias0(0) == tag(18, 1));
  CHECK(t->t0_us == 123456u);
  CHECK(t->first == 0);
  CHECK_FALSE(t->from_birth);
  for (std::size_t d = 0; d < 3; ++d) CHECK(holds_scan(*t, d, d + 2));
}

TEST_CASE("mfbp track slot shift: a track born after the finalised scans keeps its prior") {
  auto t = std::make_unique<Slot>();
  t->start(7, 3, 0.6);
  t->x0 = Slot::Vec4(1.0, 2.0, 3.0, 4.0);
  t->t0_us = 99u;
  for (std::size_t k = 0; k < 5; ++k) fill_scan(*t, k);
  t->shift(2, 5, 123456u);
  CHECK(t->first == 1);
  CHECK(t->from_birth);
  CHECK(t->x0(3) == 4.0);
  CHECK(t->t0_us == 99u);
  CHECK(holds_scan(*t, 2, 4));
}

TEST_CASE("mfbp track slot start: a used slot comes back as a fresh birth") {
  auto t = std::make_unique<Slot>();
  t->confirmed = true;
  t->low_run = 5;
  t->age = 9;
  t->vis_emitted = 0.1;
  t->P0 = Slot::Mat4::Constant(3.0);
  for (std::size_t k = 0; k < 5; ++k) fill_scan(*t, k);
  t->start(42, 2, 0.6);
  CHECK(t->alive);
  CHECK(t->from_birth);
  CHECK_FALSE(t->confirmed);
  CHECK(t->id == 42);
  CHECK(t->first == 2);
  CHECK(t->low_run == 0);
  CHECK(t->age == 0);
  CHECK(t->vis_emitted == 1.0);
  CHECK(t->vis0 == 0.6);
  CHECK(t->P0 == Slot::Mat4::Identity());
  for (std::size_t k = 0; k < 5; ++k) {
    CHECK(t->missed[k] == 1.0);
    CHECK(t->best[k] == -1);
    CHECK(t->xi1[k] == 1.0);
    CHECK(t->xi0[k] == 1.0);
    CHECK(t->extr[k] == 0.6);
    CHECK(t->n_edges[k] == 0);
    CHECK(t->amp[k].w == 0.0);
    CHECK(t->mate[k] == 0);
  }
}

TEST_CASE("mfbp track slot participates: not on its birth scan, not before it") {
  Slot t;
  t.start(1, 2, 0.6);
  CHECK_FALSE(t.participates(1));
  CHECK_FALSE(t.participates(2));
  CHECK(t.participates(3));
  t.from_birth = false;
  CHECK(t.participates(2));
}

TEST_CASE("mfbp clutter table shift: priors from the last finalised scan, Dirichlet floored at 1e-3") {
  auto cl = std::make_unique<mfbp::ClutterTable<double, Caps5>>();
  cl->comps[0].alive = true;
  cl->comps[1].alive = true;
  for (std::size_t k = 0; k < 4; ++k) {
    cl->m[k] = 10.0 + static_cast<double>(k);
    cl->alpha_f[k] = {20.0 + static_cast<double>(k), 1e-5, 3.0};
    cl->alpha_s[k] = {30.0 + static_cast<double>(k), 1.0, 1.0};
    cl->uniform.igf[k].b = 40.0 + static_cast<double>(k);
    cl->comps[1].nwf[k].c = 50.0 + static_cast<double>(k);
    cl->comps[1].igs[k].a = 60.0 + static_cast<double>(k);
  }
  cl->shift(3, 4);
  CHECK(cl->m_prev == 12.0);
  CHECK(cl->uniform.alpha0 == 22.0);
  CHECK(cl->uniform.ig0.b == 42.0);
  CHECK(cl->comps[0].alpha0 == 1e-3);  // 1e-5 floored
  CHECK(cl->comps[1].alpha0 == 3.0);
  CHECK(cl->comps[1].nw0.c == 52.0);
  CHECK(cl->m[0] == 13.0);
  CHECK(cl->alpha_s[0][0] == 33.0);
  CHECK(cl->uniform.igf[0].b == 43.0);
  CHECK(cl->comps[1].nwf[0].c == 53.0);
  CHECK(cl->comps[1].igs[0].a == 63.0);
}

TEST_CASE("mfbp clutter table component count: M_k times the expected weight") {
  mfbp::ClutterTable<double, Caps5> cl;
  cl.m[0] = 12.0;
  cl.alpha_s[0] = {2.0, 1.0, 3.0};  // E[pi] = 2/6, 1/6, 3/6
  CHECK(cl.component_count(0, 0) == doctest::Approx(4.0));
  CHECK(cl.component_count(0, 2) == doctest::Approx(6.0));
}

TEST_CASE("mfbp window store shift: finalised scans become history, the oldest fall off") {
  auto store = std::make_unique<mfbp::WindowStore<double, Caps5>>();
  MfbpParams<double> p = seed000_default_params<double>();
  TrackerCounters counters{};
  std::array<bool, 8> kept{};
  Scan<double, 8> scan;
  for (std::uint64_t i = 0; i < 3; ++i) {
    scan.time_us = 1000u * (i + 1);
    REQUIRE(store->store_scan(scan, p, counters, kept) == false);
    store->push_window();
  }
  store->shift(2, 2);  // window length 2: 3 history scans fit in 5
  CHECK(store->n_hist() == 2);
  CHECK(store->n_win() == 1);
  CHECK(store->win(0).time_us == 3000u);
  for (std::uint64_t i = 3; i < 5; ++i) {
    scan.time_us = 1000u * (i + 1);
    REQUIRE(store->store_scan(scan, p, counters, kept) == false);
    store->push_window();
  }
  store->shift(2, 2);  // 4 finalised scans, 3 kept: the first drops off
  CHECK(store->n_hist() == 3);
  CHECK(store->n_win() == 1);
  CHECK(store->at(0).time_us == 2000u);
  CHECK(store->win(0).time_us == 5000u);
}

TEST_CASE("mfbp caps accessors: members read when present, defaults otherwise") {
  CHECK(mfbp::kMaxGatePairs<Caps5> == 8);
  CHECK(mfbp::kMaxClutterGridCells<Caps5> == 512);
  CHECK(mfbp::kMaxBirthCandidates<Caps5> == 32);
  CHECK(mfbp::kMaxGatePairs<Caps5Small> == 3);
  CHECK(mfbp::kMaxClutterGridCells<Caps5Small> == 100);
  CHECK(mfbp::kMaxBirthCandidates<Caps5Small> == 4);
  CHECK(mfbp::kMaxBirthCandidates<DefaultCaps> == DefaultCaps::kMaxBirthCandidates);
  // Without kMaxGatePool every track's full list fits: 4 x 8 and 4 x 3.
  CHECK(mfbp::kMaxGatePool<Caps5> == 32);
  CHECK(mfbp::kMaxGatePool<Caps5Small> == 12);
}

// init() with the smallest window and n births per window.
template <class T, class Caps>
Status init_with_births(std::size_t n) {
  auto trk = std::make_unique<MfbpTracker<T, Caps>>();
  MfbpParams<T> p = seed000_default_params<T>();
  p.window_length = 1;
  p.slide = 1;
  p.birth_max_per_window = n;
  return trk->init(p);
}

TEST_CASE("mfbp init refuses birth_max_per_window above Caps::kMaxBirthCandidates") {
  CHECK(init_with_births<double, Caps5Small>(5) == Status::kInvalidArgument);
  CHECK(init_with_births<double, Caps5Small>(4) == Status::kOk);
}

TEST_CASE("mfbp init: the preset caps accept birth_max_per_window up to 32, not 33") {
  CHECK(init_with_births<float, SmallBoardCaps>(33) == Status::kInvalidArgument);
  CHECK(init_with_births<float, SmallBoardCaps>(32) == Status::kOk);
}
