// MF-BP birth inside weaker clutter (issue 18 point 1; docs/algorithms/mfbp.md
// §Birth, "Young tracks inside weaker clutter"): which clutter component
// counts as weaker (weaker_clutter.h), the predictive spatial evidence of a
// young track there (evidence.h, target_evidence) and its confirmation
// threshold (track_management.h). Values derived by hand.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "mptrack/mfbp/evidence.h"
#include "mptrack/mfbp/mfbp_tracker.h"
#include "mptrack/mfbp/track_management.h"
#include "mptrack/mfbp/weaker_clutter.h"

using namespace mptrack;

namespace {

struct WcCaps {
  static constexpr std::size_t kMaxTargets = 4;
  static constexpr std::size_t kMaxMeasurements = 8;
  static constexpr std::size_t kMaxClutterComponents = 2;
  static constexpr std::size_t kMaxWindow = 4;
};

constexpr double kAz0 = 0.6108652381980153;   // 35 deg [rad]
constexpr double kSigAz = 0.08726646259971647;  // 5 deg [rad]

/// The clutter-birth scene's component as a known map: 30 per scan at
/// 30 km, 35 deg, spread 2.5 km x 5 deg, CNR 4 (total power 5).
MfbpParams<double> known_map_params() {
  MfbpParams<double> p = seed000_default_params<double>();
  p.clutter_mode = ClutterMode::kKnownMap;
  p.known_clutter.num_components = 1;
  auto& c = p.known_clutter.components[0];
  c.rate_per_scan = 30.0;
  c.mean << 30000.0, kAz0;
  c.covariance << 2500.0 * 2500.0, 0.0, 0.0, kSigAz * kSigAz;
  c.cnr = 4.0;
  return p;
}

}  // namespace

TEST_CASE("mfbp weaker clutter: a component of lower power than the target holds its gate") {
  const MfbpParams<double> p = known_map_params();
  const mfbp::ClutterTable<double, WcCaps> cl{};
  // Centre, target total power 11 (SNR 10) > 5: weaker.
  CHECK(mfbp::inside_weaker_component(30000.0, kAz0, 11.0, 0, 0u, cl, p));
  // Equal or lower target power: not weaker (the amplitude does not favour the target).
  CHECK_FALSE(mfbp::inside_weaker_component(30000.0, kAz0, 5.0, 0, 0u, cl, p));
  CHECK_FALSE(mfbp::inside_weaker_component(30000.0, kAz0, 4.0, 0, 0u, cl, p));
  // 5 sigma in range: d^2 = 25 <= clutter_gate_chi2 30, inside; 5.6 sigma: d^2 = 31.36, outside.
  CHECK(mfbp::inside_weaker_component(30000.0 + 5.0 * 2500.0, kAz0, 11.0, 0, 0u, cl, p));
  CHECK_FALSE(mfbp::inside_weaker_component(30000.0 + 5.6 * 2500.0, kAz0, 11.0, 0, 0u, cl, p));
  // 3 sigma in both: d^2 = 18, inside.
  CHECK(mfbp::inside_weaker_component(30000.0 + 3.0 * 2500.0, kAz0 - 3.0 * kSigAz, 11.0, 0, 0u, cl, p));
}

TEST_CASE("mfbp weaker clutter: never without amplitude or Gaussian components") {
  MfbpParams<double> p = known_map_params();
  const mfbp::ClutterTable<double, WcCaps> cl{};
  p.amplitude.use_amplitude = false;  // KI ablation
  CHECK_FALSE(mfbp::inside_weaker_component(30000.0, kAz0, 11.0, 0, 0u, cl, p));
  p = known_map_params();
  p.clutter_mode = ClutterMode::kKnownRateUniform;  // NCE ablation: uniform clutter only
  CHECK_FALSE(mfbp::inside_weaker_component(30000.0, kAz0, 11.0, 0, 0u, cl, p));
  p = known_map_params();
  p.known_clutter.components[0].rate_per_scan = 0.0;  // a component that produces nothing
  CHECK_FALSE(mfbp::inside_weaker_component(30000.0, kAz0, 11.0, 0, 0u, cl, p));
  p = known_map_params();
  p.clutter_mode = ClutterMode::kEstimatedMap;  // no component alive yet
  CHECK_FALSE(mfbp::inside_weaker_component(30000.0, kAz0, 11.0, 0, 0u, cl, p));
}

TEST_CASE("mfbp young track in weaker clutter: predictive evidence N(y; z, Sz + R), not E[ln N]") {
  MfbpParams<double> p = seed000_default_params<double>();
  p.amplitude.use_amplitude = false;  // spatial term alone
  mfbp::ModelConstants<double> mc;
  mc.set(p);
  const double var_r = 20.0 * 20.0;
  const double var_a = p.noise.azimuth_std_rad * p.noise.azimuth_std_rad;
  // A track one scan after a two-point birth: Sz = 5 R (docs/algorithms/mfbp.md §Birth).
  mfbp::TrackMoments<double> mo;
  mo.z << 30000.0, kAz0;
  mo.z_shared = mo.z;
  mo.Sz << 5.0 * var_r, 0.0, 0.0, 5.0 * var_a;
  mo.ok = true;
  const model::Mahalanobis2<double> gate(mo.Sz + mc.R);
  REQUIRE(gate.valid());
  mfbp::ScanSlot<double, WcCaps> s{};
  s.count = 1;
  s.r[0] = 30000.0 + 2.0 * 20.0;  // 2 sigma_r off, e^T R^-1 e = 4
  s.az[0] = kAz0;
  mfbp::TrackSlot<double, WcCaps> t{};
  mfbp::GateList<double, 64> mf_list, pred_list;
  (void)mfbp::target_evidence(t, mo, gate, s, 0, p, mc, mf_list);
  mo.predictive = true;
  (void)mfbp::target_evidence(t, mo, gate, s, 0, p, mc, pred_list);
  REQUIRE(mf_list.size == 1);
  REQUIRE(pred_list.size == 1);
  const double ln_norm_R = -std::log(2.0 * M_PI) - 0.5 * std::log(var_r * var_a);
  // MF (seed 000 eq. (79)): ln N(y; z, R) - tr(R^-1 Sz) / 2 = ln_norm_R - (4 + 10) / 2.
  CHECK(mf_list.v[0] == doctest::Approx(ln_norm_R - 7.0).epsilon(1e-12));
  // Predictive: S = 6 R, so ln_norm_R - ln 6 - (4 / 6) / 2.
  CHECK(pred_list.v[0] == doctest::Approx(ln_norm_R - std::log(6.0) - 1.0 / 3.0).epsilon(1e-12));
  // The gap that kept a young track below a dense component: 7 - 1.79 - 0.33 = 4.87 nats.
  CHECK(pred_list.v[0] - mf_list.v[0] == doctest::Approx(7.0 - std::log(6.0) - 1.0 / 3.0).epsilon(1e-12));
}

namespace {

/// Tentative tracks ids 1 and 2 from scan 0; the second is held to
/// confirm_threshold_in_clutter (it scored with the predictive density).
void start_plain_and_held(mfbp::TrackTable<double, WcCaps>& tracks) {
  tracks[0].start(1, 0, 0.5);
  tracks[1].start(2, 0, 0.5);
  tracks[1].predictive_evidence = true;
}

}  // namespace

TEST_CASE("mfbp young track in weaker clutter: confirmed at confirm_threshold_in_clutter") {
  MfbpParams<double> p = seed000_default_params<double>();
  mfbp::TrackTable<double, WcCaps> tracks{};
  TrackerCounters counters{};
  start_plain_and_held(tracks);
  for (auto* t : {&tracks[0], &tracks[1]}) t->vis[0] = 0.98;  // above 0.75, below 0.99
  mfbp::confirm_tracks(tracks, 1, 0, p, counters);
  CHECK(tracks[0].confirmed);
  CHECK_FALSE(tracks[1].confirmed);
  tracks[1].vis[0] = 0.99;
  mfbp::confirm_tracks(tracks, 1, 0, p, counters);
  CHECK(tracks[1].confirmed);
  CHECK(counters.tracks_confirmed == 2u);
  // Off: the usual threshold for every track.
  p.tentative_predictive_in_clutter = false;
  tracks[2].start(3, 0, 0.5);
  tracks[2].predictive_evidence = true;
  tracks[2].vis[0] = 0.8;
  CHECK(mfbp::confirmation_threshold(tracks[2], p) == 0.75);
}

namespace {

/// One online-filter scan of a young track inside weaker clutter: the
/// association left visibility evidence xi(1)/xi(0) = ratio, b_s 0.9 (below
/// 0.99, so only the score can confirm).
void filter_scan(mfbp::TrackSlot<double, WcCaps>& t, double ratio) {
  t.from_birth = false;  // a scan after the birth scan: the track takes part in its association
  t.xi1[0] = ratio / (1.0 + ratio);
  t.xi0[0] = 1.0 / (1.0 + ratio);
  t.vis[0] = 0.9;
}

}  // namespace

TEST_CASE("mfbp online filter in weaker clutter: confirmed when the summed ln(xi1/xi0) reaches 9.21") {
  MfbpParams<double> p = seed000_default_params<double>();
  p.window_length = 1;
  REQUIRE(p.filter_confirm_score_in_clutter == 9.21);
  mfbp::TrackTable<double, WcCaps> tracks{};
  TrackerCounters counters{};
  tracks[0].start(1, 0, 0.5);
  tracks[0].predictive_evidence = true;
  // Evidence 20:1 per scan: ln 20 = 2.996, so 8.99 after three scans (not yet)
  // and 11.98 after four.
  for (int scan = 1; scan <= 3; ++scan) {
    filter_scan(tracks[0], 20.0);
    mfbp::confirm_tracks(tracks, 1, 0, p, counters);
    CHECK_FALSE(tracks[0].confirmed);
  }
  CHECK(tracks[0].score == doctest::Approx(3.0 * std::log(20.0)).epsilon(1e-9));
  filter_scan(tracks[0], 20.0);
  mfbp::confirm_tracks(tracks, 1, 0, p, counters);
  CHECK(tracks[0].confirmed);
  CHECK(counters.tracks_confirmed == 1u);
}

TEST_CASE("mfbp online filter in weaker clutter: a scan against the track lowers its score") {
  MfbpParams<double> p = seed000_default_params<double>();
  p.window_length = 1;
  mfbp::TrackTable<double, WcCaps> tracks{};
  TrackerCounters counters{};
  tracks[0].start(1, 0, 0.5);
  tracks[0].predictive_evidence = true;
  const double ratios[] = {20.0, 0.25, 20.0, 20.0};  // ln: 3.00 - 1.39 + 3.00 + 3.00 = 7.60
  for (double r : ratios) {
    filter_scan(tracks[0], r);
    mfbp::confirm_tracks(tracks, 1, 0, p, counters);
  }
  CHECK(tracks[0].score == doctest::Approx(3.0 * std::log(20.0) + std::log(0.25)).epsilon(1e-9));
  CHECK_FALSE(tracks[0].confirmed);
}

TEST_CASE("mfbp score confirmation: not in the smoother, not for plain tracks, not when off") {
  MfbpParams<double> p = seed000_default_params<double>();
  mfbp::TrackTable<double, WcCaps> tracks{};
  TrackerCounters counters{};
  tracks[0].start(1, 0, 0.5);  // smoother (window 7), young track in clutter
  tracks[0].predictive_evidence = true;
  MfbpParams<double> filter = p;
  filter.window_length = 1;
  tracks[1].start(2, 0, 0.5);  // filter, plain track: confirm_threshold 0.75 decides
  MfbpParams<double> off = filter;
  off.filter_confirm_score_in_clutter = 0.0;
  tracks[2].start(3, 0, 0.5);  // filter, in clutter, rule off
  tracks[2].predictive_evidence = true;
  for (int scan = 0; scan < 10; ++scan) {
    for (auto& t : tracks) {
      filter_scan(t, 20.0);
      t.vis[0] = 0.7;  // below 0.75: b_s confirms none of them
    }
    mfbp::confirm_tracks(tracks, 1, 0, p, counters);
    CHECK(mfbp::filter_score_confirms(tracks[1], 1, filter) == false);
    CHECK(mfbp::filter_score_confirms(tracks[2], 1, off) == false);
  }
  CHECK_FALSE(tracks[0].confirmed);
  CHECK(tracks[0].score == 0.0);
  CHECK(tracks[1].score == 0.0);
  CHECK(tracks[2].score == 0.0);
}

TEST_CASE("mfbp params: filter_confirm_score_in_clutter must lie in [0, 100] nats") {
  MfbpParams<double> p = seed000_default_params<double>();
  CHECK(p.validate() == mptrack::Status::kOk);
  p.filter_confirm_score_in_clutter = -1.0;
  CHECK(p.validate() != mptrack::Status::kOk);
  p.filter_confirm_score_in_clutter = 101.0;
  CHECK(p.validate() != mptrack::Status::kOk);
}

TEST_CASE("mfbp young track in weaker clutter: dropped after tentative_timeout_in_clutter_scans, not 6") {
  MfbpParams<double> p = seed000_default_params<double>();
  REQUIRE(p.tentative_timeout_scans == 6u);
  REQUIRE(p.tentative_timeout_in_clutter_scans == 10u);
  mfbp::TrackTable<double, WcCaps> tracks{};
  const mfbp::ClutterTable<double, WcCaps> cl{};
  TrackerCounters counters{};
  tracks[0].start(1, 0, 0.5);
  tracks[1].start(2, 0, 0.5);
  tracks[1].predictive_evidence = true;
  CHECK(mfbp::tentative_timeout(tracks[0], p) == 6u);
  CHECK(mfbp::tentative_timeout(tracks[1], p) == 10u);
  // Seven finalised scans at b_s = 0.7: no deletion run (above 0.5), both
  // unconfirmed; the plain track has outlived its 6 scans, the young track
  // in clutter has not outlived its 10.
  for (auto* t : {&tracks[0], &tracks[1]}) {
    for (std::size_t k = 0; k < 4; ++k) t->vis[k] = 0.7;
  }
  mfbp::manage_tracks(tracks, cl, 4, 4, 0u, p, counters);  // 4 scans finalised
  CHECK(tracks[0].alive);
  CHECK(tracks[1].alive);
  mfbp::manage_tracks(tracks, cl, 3, 3, 0u, p, counters);  // 7 in all
  CHECK_FALSE(tracks[0].alive);
  CHECK(tracks[1].alive);
  // With the rule off (or an in-clutter timeout not above 6): the plain 6.
  p.tentative_predictive_in_clutter = false;
  CHECK(mfbp::tentative_timeout(tracks[1], p) == 6u);
  p.tentative_predictive_in_clutter = true;
  p.tentative_timeout_in_clutter_scans = 5;
  CHECK(mfbp::tentative_timeout(tracks[1], p) == 6u);
}

TEST_CASE("mfbp known map: a component counts only on scans inside its active interval") {
  MfbpParams<double> p = known_map_params();
  const mfbp::ClutterTable<double, WcCaps> cl{};
  auto& c = p.known_clutter.components[0];
  c.active_from_us = 10'000'000;   // exists from the scan at 10 s ...
  c.active_until_us = 20'000'000;  // ... to the scan at 20 s, both inclusive
  CHECK_FALSE(mfbp::inside_weaker_component(30000.0, kAz0, 11.0, 0, 9'999'999u, cl, p));
  CHECK(mfbp::inside_weaker_component(30000.0, kAz0, 11.0, 0, 10'000'000u, cl, p));
  CHECK(mfbp::inside_weaker_component(30000.0, kAz0, 11.0, 0, 20'000'000u, cl, p));
  // A window scan after the component ended (the KCE ablation's older scans
  // are evaluated against the newest map): no longer clutter there.
  CHECK_FALSE(mfbp::inside_weaker_component(30000.0, kAz0, 11.0, 0, 20'000'001u, cl, p));
}

TEST_CASE("mfbp known map: an interval that ends before it starts is refused, naming the field") {
  MfbpParams<double> p = known_map_params();
  p.known_clutter.components[0].active_from_us = 5;
  p.known_clutter.components[0].active_until_us = 4;
  ParamError e;
  CHECK(p.validate(&e) == Status::kInvalidArgument);
  CHECK(std::string(e.field) == "known_clutter.components.active_until_us");
  p.known_clutter.components[0].active_until_us = 5;  // one scan: valid
  CHECK(p.validate(&e) == Status::kOk);
}

TEST_CASE("mfbp any component: its gate holds a point whatever the component's power") {
  const MfbpParams<double> p = known_map_params();
  const mfbp::ClutterTable<double, WcCaps> cl{};
  // The centre of the CNR 4 component: not weaker than an SNR 3 target, yet inside.
  CHECK_FALSE(mfbp::inside_weaker_component(30000.0, kAz0, 4.0, 0, 0u, cl, p));
  CHECK(mfbp::inside_any_component(30000.0, kAz0, 0, 0u, cl, p));
  // Same gate as the weaker test: d^2 = 25 inside, 31.36 outside (clutter_gate_chi2 30).
  CHECK(mfbp::inside_any_component(30000.0 + 5.0 * 2500.0, kAz0, 0, 0u, cl, p));
  CHECK_FALSE(mfbp::inside_any_component(30000.0 + 5.6 * 2500.0, kAz0, 0, 0u, cl, p));
}

TEST_CASE("mfbp any component: a gate test alone, so also without amplitude (KI)") {
  MfbpParams<double> p = known_map_params();
  p.amplitude.use_amplitude = false;
  const mfbp::ClutterTable<double, WcCaps> cl{};
  CHECK_FALSE(mfbp::inside_weaker_component(30000.0, kAz0, 11.0, 0, 0u, cl, p));
  CHECK(mfbp::inside_any_component(30000.0, kAz0, 0, 0u, cl, p));
  p.known_clutter.components[0].rate_per_scan = 0.0;  // a component that produces nothing
  CHECK_FALSE(mfbp::inside_any_component(30000.0, kAz0, 0, 0u, cl, p));
}

TEST_CASE("mfbp any component: a reused slot starts without the flag and with score 0") {
  mfbp::TrackSlot<double, WcCaps> t{};
  t.start(1, 0, 0.5);
  t.predicted_in_component = true;
  t.predictive_evidence = true;
  t.score = 7.5;
  t.start(2, 0, 0.5);  // the slot taken by a new track
  CHECK_FALSE(t.predicted_in_component);
  CHECK_FALSE(t.predictive_evidence);
  CHECK(t.score == 0.0);
}

TEST_CASE("mfbp any component: the rule holds tentative tracks of the online filter only") {
  MfbpParams<double> filter = seed000_default_params<double>();
  filter.window_length = 1;
  REQUIRE(filter.filter_score_in_any_component);
  mfbp::TrackSlot<double, WcCaps> t{};
  t.start(1, 0, 0.5);
  CHECK(mfbp::filter_holds_in_any_component(t, filter));
  MfbpParams<double> smoother = filter;
  smoother.window_length = 7;
  CHECK_FALSE(mfbp::filter_holds_in_any_component(t, smoother));
  MfbpParams<double> off = filter;
  off.filter_score_in_any_component = false;
  CHECK_FALSE(mfbp::filter_holds_in_any_component(t, off));
  MfbpParams<double> no_score = filter;
  no_score.filter_confirm_score_in_clutter = 0.0;  // without the score it would never confirm
  CHECK_FALSE(mfbp::filter_holds_in_any_component(t, no_score));
  t.confirmed = true;
  CHECK_FALSE(mfbp::filter_holds_in_any_component(t, filter));
}

TEST_CASE("mfbp any component: a filter track predicted in a component needs the score, not b_s 0.75") {
  MfbpParams<double> p = seed000_default_params<double>();
  p.window_length = 1;
  mfbp::TrackTable<double, WcCaps> tracks{};
  TrackerCounters counters{};
  tracks[0].start(1, 0, 0.5);  // plain
  tracks[1].start(2, 0, 0.5);  // predicted inside a component
  tracks[1].predicted_in_component = true;
  CHECK(mfbp::confirmation_threshold(tracks[1], p) == 0.99);
  // Two scans at 4:1 (b_s 0.9 each): the plain track is confirmed at once; the
  // other's score is 2 ln 4 = 2.77 < 9.21.
  for (int scan = 0; scan < 2; ++scan) {
    for (auto& t : tracks) filter_scan(t, 4.0);
    mfbp::confirm_tracks(tracks, 1, 0, p, counters);
  }
  CHECK(tracks[0].confirmed);
  CHECK_FALSE(tracks[1].confirmed);
  CHECK(tracks[1].score == doctest::Approx(2.0 * std::log(4.0)).epsilon(1e-9));
}

TEST_CASE("mfbp confirm_lookahead: capped at the window, 0 when the window finalises every scan") {
  MfbpParams<double> p = seed000_default_params<double>();
  p.confirm_lookahead_in_clutter = 2;
  CHECK(mfbp::confirm_lookahead(7, 1, p) == 2u);  // slide 1: the window's newest 2 scans excluded
  CHECK(mfbp::confirm_lookahead(2, 1, p) == 1u);  // at most n - 1: scan 0 stays testable
  CHECK(mfbp::confirm_lookahead(7, 7, p) == 0u);  // flush(): no later window sees these scans
  CHECK(mfbp::confirm_lookahead(1, 1, p) == 0u);  // online filter
  CHECK(mfbp::confirm_lookahead(0, 0, p) == 0u);
  p.confirm_lookahead_in_clutter = 9;
  CHECK(mfbp::confirm_lookahead(7, 3, p) == 6u);
}

TEST_CASE("mfbp young track in weaker clutter: confirms only on a scan with `lookahead` scans after it") {
  MfbpParams<double> p = seed000_default_params<double>();
  mfbp::TrackTable<double, WcCaps> tracks{};
  TrackerCounters counters{};
  // Window of 4 scans; both tracks exist from scan 0 and reach 0.99 only on
  // the newest scan (3). Track 1 is held to the in-clutter threshold.
  start_plain_and_held(tracks);
  for (auto* t : {&tracks[0], &tracks[1]}) {
    for (std::size_t k = 0; k < 3; ++k) t->vis[k] = 0.5;
    t->vis[3] = 0.995;
  }
  mfbp::confirm_tracks(tracks, 4, 2, p, counters);
  CHECK(tracks[0].confirmed);        // the plain threshold ignores the lookahead
  CHECK_FALSE(tracks[1].confirmed);  // scan 3 has no later window scan; 0..1 are below 0.99
  tracks[1].vis[1] = 0.995;          // scan 1 has 2 later window scans (2, 3)
  mfbp::confirm_tracks(tracks, 4, 2, p, counters);
  CHECK(tracks[1].confirmed);
  CHECK(counters.tracks_confirmed == 2u);
}

TEST_CASE("mfbp young track in weaker clutter: lookahead 0 tests every window scan") {
  MfbpParams<double> p = seed000_default_params<double>();
  mfbp::TrackTable<double, WcCaps> tracks{};
  TrackerCounters counters{};
  tracks[0].start(1, 0, 0.5);
  tracks[0].predictive_evidence = true;
  for (std::size_t k = 0; k < 3; ++k) tracks[0].vis[k] = 0.5;
  tracks[0].vis[3] = 0.995;
  mfbp::confirm_tracks(tracks, 4, 0, p, counters);
  CHECK(tracks[0].confirmed);
}

TEST_CASE("mfbp every_scan_smoother_params: the defaults with slide 1, lookahead 2 and CNR limit 6, valid") {
  const MfbpParams<double> d = seed000_default_params<double>();
  const MfbpParams<double> p = every_scan_smoother_params<double>();
  CHECK(d.slide == 3u);  // the paper's schedule stays the default
  CHECK(d.confirm_lookahead_in_clutter == 0u);
  CHECK(p.slide == 1u);
  CHECK(p.confirm_lookahead_in_clutter == 2u);
  CHECK(d.birth_in_clutter_max_cnr == 0.0);
  CHECK(p.birth_in_clutter_max_cnr == 6.0);
  CHECK(p.window_length == d.window_length);
  CHECK(p.confirm_threshold_in_clutter == d.confirm_threshold_in_clutter);
  CHECK(p.validate() == Status::kOk);
}
