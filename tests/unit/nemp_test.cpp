// NEMP in MF-BP's association (core/include/mptrack/mfbp/nemp.h and the hook
// in mfbp/association.h): neutrality (bit-identical MF-BP with no evidence or
// w = 0.5 everywhere), the extrinsic belief and the fused message by hand,
// parameter validation, no allocation.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

#include "alloc_guard.h"
#include "classify_reference_data.h"
#include "mfbp_scenario.h"
#include "mptrack/mfbp/mfbp_tracker.h"

using namespace mptrack;
using mfbp_test::TestCaps;

namespace {

using Tracker = MfbpTracker<float, TestCaps>;
using Nemp = mfbp::NempState<float, TestCaps>;
using Evidence = mfbp::ScanEvidence<TestCaps::kMaxMeasurements>;
using TestScan = Scan<float, TestCaps::kMaxMeasurements>;

constexpr float kZeros[8] = {0, 0, 0, 0, 0, 0, 0, 0};

/// The reference weights with a constant classifier head: w = sigmoid(bias)
/// whatever the features and belief (sigmoid(0) = 1 / (1 + dexp(-0)) = 0.5
/// exactly).
struct ConstantHead {
  float bias[1];
  classify::SeaClassifier classifier;
  explicit ConstantHead(float b) : bias{b} {
    classify::SeaClassifierWeights w = test::classify_ref::weights();
    w.mlp3_weight = kZeros;
    w.mlp3_bias = bias;
    REQUIRE(classifier.init(w) == Status::kOk);
  }
};

void put_bits(std::vector<std::uint32_t>& out, float v) {
  std::uint32_t u = 0;
  std::memcpy(&u, &v, sizeof u);
  out.push_back(u);
}

void record(const Tracker& trk, std::vector<std::uint32_t>& out) {
  for (const auto& est : trk.outputs()) {
    out.push_back(static_cast<std::uint32_t>(est.scan_index));
    out.push_back(static_cast<std::uint32_t>(est.tracks.size()));
    for (const auto& t : est.tracks) {
      out.push_back(t.id);
      for (int i = 0; i < 4; ++i) put_bits(out, t.state(i));
      for (int i = 0; i < 4; ++i) put_bits(out, t.covariance(i, i));
      put_bits(out, t.existence);
      put_bits(out, t.snr);
      out.push_back(static_cast<std::uint32_t>(t.measurement_index));
    }
    for (const auto& c : est.clutter) {
      put_bits(out, c.expected_count);
      put_bits(out, c.cnr);
    }
  }
}

struct RunResult {
  std::vector<std::uint32_t> bits;
  std::uint64_t bp_runs = 0;
  std::vector<std::size_t> reported;  ///< tracks per output estimate, in order
};

/// Window of run_scene(): 7 / 3 fills the store (kMaxWindow 7, no history
/// scans); 4 / 1 keeps three history scans behind the window.
struct WindowShape {
  std::size_t length = 7;
  std::size_t slide = 3;
};

/// 30 scans of the seed 000 two-target scene (tests/unit/mfbp_scenario.h);
/// nemp == nullptr: plain MF-BP; with_patches: every detection carries
/// (zero) features, except on scans k with k % patchless_every == 0 (if
/// patchless_every > 0) and on scans k < patchless_before.
RunResult run_scene(Nemp* nemp, bool with_patches, std::uint64_t* born = nullptr,
                    WindowShape w = WindowShape{}, int patchless_every = 0, int patchless_before = 0) {
  auto trk = std::make_unique<Tracker>();
  MfbpParams<float> p = seed000_default_params<float>();
  p.window_length = w.length;
  p.slide = w.slide;
  p.uniform_rate_per_scan = 10.0f;
  REQUIRE(trk->init(p) == Status::kOk);
  if (nemp != nullptr) REQUIRE(trk->attach_nemp(nemp) == Status::kOk);
  auto ev = std::make_unique<Evidence>();
  mfbp_test::Lcg rng;
  auto scan = std::make_unique<TestScan>();
  RunResult r;
  for (int k = 0; k < 30; ++k) {
    mfbp_test::make_scan(rng, k, 10, *scan);
    ev->has_patch.fill(with_patches && !(patchless_every > 0 && k % patchless_every == 0) &&
                       k >= patchless_before);
    const Status s = nemp != nullptr ? trk->step(*scan, *ev) : trk->step(*scan);
    REQUIRE(s == Status::kOk);
    record(*trk, r.bits);
    for (const auto& est : trk->outputs()) r.reported.push_back(est.tracks.size());
  }
  REQUIRE(trk->flush() == Status::kOk);
  record(*trk, r.bits);
  for (const auto& est : trk->outputs()) r.reported.push_back(est.tracks.size());
  r.bp_runs = trk->bp_runs();
  if (born != nullptr) *born = trk->counters().tracks_born;
  return r;
}

/// A BP stand-in: one clutter source whose posterior is given.
struct FakeBp {
  float pc[4] = {0.5f, 0.5f, 0.5f, 0.5f};
  float added[4] = {0, 0, 0, 0};
  std::size_t num_sources() const { return 1; }
  float clutter_belief(std::size_t, std::size_t j) const { return pc[j]; }
  void add_clutter_log(std::size_t j, float d) { added[j] += d; }
};

/// A window store slot with count detections, stored in input order.
struct FakeSlot {
  std::size_t count = 1;
  std::array<std::uint16_t, TestCaps::kMaxMeasurements> orig_index{};
  std::array<bool, TestCaps::kMaxMeasurements> vetoed{};
  std::array<bool, TestCaps::kMaxMeasurements> tentative_vetoed{};
  void set_birth_vetoed(std::size_t c, bool on) { vetoed[c] = on; }
  void set_tentative_vetoed(std::size_t c, bool on) { tentative_vetoed[c] = on; }
};

}  // namespace

TEST_CASE("NEMP off, no patches, or w = 0.5 everywhere: MF-BP output bit-identical") {
  const RunResult plain = run_scene(nullptr, false);
  REQUIRE(plain.bits.size() > 100u);  // tracks were reported
  auto neutral = std::make_unique<ConstantHead>(0.0f);
  CHECK(neutral->classifier.target_probability(classify::Features{}, 0.3f) == 0.5f);
  auto nemp = std::make_unique<Nemp>();
  REQUIRE(nemp->init(&neutral->classifier, mfbp::NempParams<float>{}) == Status::kOk);
  const RunResult no_patch = run_scene(nemp.get(), false);
  const RunResult half = run_scene(nemp.get(), true);
  CHECK(no_patch.bits == plain.bits);
  CHECK(half.bits == plain.bits);
  // and no extra BP runs: a round that changes no factor stops the loop
  CHECK(no_patch.bp_runs == plain.bp_runs);
  CHECK(half.bp_runs == plain.bp_runs);
}

/// Settings of the sea kind (docs/algorithms/nemp.md §Sea settings): log-odds
/// gain 2, birth veto at 0.5 over the tentative life too, the target side
/// bounded at 0.5 (as the adapter ships them); neutrality must hold for any
/// such values.
mfbp::NempParams<float> sea_like_params() {
  mfbp::NempParams<float> p;
  p.nn_log_odds_gain = 2.0f;
  p.nn_max_target_prob = 0.5f;
  p.birth_min_target_prob = 0.5f;
  p.tentative_min_target_prob = 0.5f;
  return p;
}

TEST_CASE("NEMP with the sea settings and w = 0.5 everywhere: MF-BP output bit-identical") {
  const RunResult plain = run_scene(nullptr, false);
  auto neutral = std::make_unique<ConstantHead>(0.0f);
  auto nemp = std::make_unique<Nemp>();
  REQUIRE(nemp->init(&neutral->classifier, sea_like_params()) == Status::kOk);
  const RunResult half = run_scene(nemp.get(), true);
  CHECK(half.bits == plain.bits);
  CHECK(half.bp_runs == plain.bp_runs);
}

/// A NEMP state on the given head with the birth veto at 0.5 (and the
/// tentative veto at tentative_min).
std::unique_ptr<Nemp> vetoing_nemp(const ConstantHead& head, float tentative_min = 0.0f) {
  auto nemp = std::make_unique<Nemp>();
  mfbp::NempParams<float> p;
  p.birth_min_target_prob = 0.5f;
  p.tentative_min_target_prob = tentative_min;
  REQUIRE(nemp->init(&head.classifier, p) == Status::kOk);
  return nemp;
}

TEST_CASE("NEMP birth veto: detections the classifier calls clutter start no track") {
  std::uint64_t born_plain = 0, born_vetoed = 0, born_off = 0;
  (void)run_scene(nullptr, false, &born_plain);
  REQUIRE(born_plain > 0u);
  auto clutterish = std::make_unique<ConstantHead>(-3.0f);  // w = 0.047 < 0.5 everywhere
  auto nemp = vetoing_nemp(*clutterish);
  (void)run_scene(nemp.get(), true, &born_vetoed);
  CHECK(born_vetoed == 0u);
  // veto off (default 0): the same classifier lets births through
  auto nemp_off = std::make_unique<Nemp>();
  REQUIRE(nemp_off->init(&clutterish->classifier, mfbp::NempParams<float>{}) == Status::kOk);
  (void)run_scene(nemp_off.get(), true, &born_off);
  CHECK(born_off > 0u);
  // detections without a patch are never vetoed
  std::uint64_t born_no_patch = 0;
  (void)run_scene(nemp.get(), false, &born_no_patch);
  CHECK(born_no_patch == born_plain);
}

TEST_CASE("NEMP birth veto holds on history scans: a vetoed detection never becomes a first point") {
  // Window 4 of a 7-scan store, so births may pair a second point of the
  // oldest window scan with a first point on a history scan. Every 4th scan
  // has no patches (never vetoed), the others are all vetoed: with
  // birth_max_lag 3 no two unvetoed points can pair, so no track may start
  // unless a vetoed history point is taken as a first point.
  const WindowShape short_window{4, 1};
  constexpr int kUnvetoedEvery = 4;
  REQUIRE(seed000_default_params<float>().birth_max_lag < static_cast<std::size_t>(kUnvetoedEvery));
  std::uint64_t born_plain = 0, born_vetoed = 0;
  (void)run_scene(nullptr, false, &born_plain, short_window);
  REQUIRE(born_plain > 0u);
  auto clutterish = std::make_unique<ConstantHead>(-3.0f);  // w = 0.047 < 0.5 everywhere
  auto nemp = vetoing_nemp(*clutterish);
  (void)run_scene(nemp.get(), true, &born_vetoed, short_window, kUnvetoedEvery);
  CHECK(born_vetoed == 0u);
}

TEST_CASE("NEMP tentative veto: set on the detections below its own threshold, never without a patch") {
  // w = 0.3 at belief 0.5 (sigmoid of the constant head); birth veto at 0.5
  auto head = std::make_unique<ConstantHead>(std::log(0.3f / 0.7f));
  FakeSlot slot;
  slot.count = 2;
  slot.orig_index[1] = 1;
  auto ev = std::make_unique<Evidence>();
  ev->has_patch[0] = true;  // input 1 has no patch: never vetoed
  struct Case {
    float threshold;
    bool vetoed;
  };
  for (const Case c : {Case{0.0f, false}, Case{0.25f, false}, Case{0.5f, true}}) {
    CAPTURE(c.threshold);
    auto nemp = vetoing_nemp(*head, c.threshold);
    nemp->store_scan(0, slot, ev.get());
    CHECK(slot.vetoed[0]);  // the birth veto does not depend on it
    CHECK_FALSE(slot.vetoed[1]);
    CHECK(slot.tentative_vetoed[0] == c.vetoed);
    CHECK_FALSE(slot.tentative_vetoed[1]);
  }
}

/// Total tracks reported over all outputs of a run.
std::size_t reported_total(const RunResult& r) {
  std::size_t n = 0;
  for (const std::size_t c : r.reported) n += c;
  return n;
}

TEST_CASE("NEMP tentative veto: a track born before the veto cannot confirm on vetoed detections") {
  // Scans 0-2 carry no patch, so the two targets' two-point births happen
  // (on scans 1-2); from scan 3 on every detection is vetoed. The soft fusion alone (gain 1, no
  // bound) lets the young tracks take their targets' detections and
  // confirm; with the veto over the tentative life they see only misses.
  // w = 0.3: vetoed (< 0.5), clutter evidence x 7/3 in the soft fusion.
  auto clutterish = std::make_unique<ConstantHead>(std::log(0.3f / 0.7f));
  std::uint64_t born_soft = 0, born_hard = 0;
  auto soft = vetoing_nemp(*clutterish, 0.0f);
  const RunResult with_soft = run_scene(soft.get(), true, &born_soft, WindowShape{}, 0, 3);
  auto hard = vetoing_nemp(*clutterish, 0.5f);
  const RunResult with_hard = run_scene(hard.get(), true, &born_hard, WindowShape{}, 0, 3);
  REQUIRE(born_soft > 0u);
  CHECK(born_hard == born_soft);  // the births themselves are the same
  CHECK(reported_total(with_soft) > 0u);
  CHECK(reported_total(with_hard) == 0u);
}

TEST_CASE("NEMP tentative veto: confirmed tracks keep taking vetoed detections") {
  // Scans 0-14 carry no patch (the two targets are confirmed there), then
  // every detection is vetoed: the confirmed tracks must carry on to the
  // end as they do without the tentative veto.
  auto clutterish = std::make_unique<ConstantHead>(-3.0f);
  auto soft = vetoing_nemp(*clutterish, 0.0f);
  const RunResult with_soft = run_scene(soft.get(), true, nullptr, WindowShape{}, 0, 15);
  auto hard = vetoing_nemp(*clutterish, 0.5f);
  const RunResult with_hard = run_scene(hard.get(), true, nullptr, WindowShape{}, 0, 15);
  REQUIRE(with_soft.reported.size() == with_hard.reported.size());
  REQUIRE_FALSE(with_hard.reported.empty());
  CHECK(with_hard.reported.back() == 2u);
  CHECK(with_hard.reported.back() == with_soft.reported.back());
}

TEST_CASE("NEMP clutter side and gain: w above the bound is no evidence, the gain squares the odds") {
  FakeSlot slot;
  auto ev = std::make_unique<Evidence>();
  ev->has_patch[0] = true;
  FakeBp bp;  // p_FG = 0.5
  // w = 0.9 with nn_max_target_prob 0.5: capped to 0.5, no factor
  auto targetish = std::make_unique<ConstantHead>(std::log(9.0f));
  auto nemp = std::make_unique<Nemp>();
  mfbp::NempParams<float> p;
  p.nn_max_target_prob = 0.5f;
  REQUIRE(nemp->init(&targetish->classifier, p) == Status::kOk);
  nemp->store_scan(0, slot, ev.get());
  CHECK_FALSE(nemp->update(0, 1, bp));
  CHECK(nemp->log_factor(0, 0) == 0.0f);
  // w = 0.25 (odds 1/3) with gain 2: odds 1/9, BetP = 0.1 at p_FG = 0.5,
  // L = ln odds(0.5) - ln odds(0.1) = ln 9
  auto clutterish = std::make_unique<ConstantHead>(-std::log(3.0f));
  p.nn_log_odds_gain = 2.0f;
  REQUIRE(nemp->init(&clutterish->classifier, p) == Status::kOk);
  nemp->store_scan(0, slot, ev.get());
  CHECK(nemp->update(0, 1, bp));
  CHECK(nemp->log_factor(0, 0) == doctest::Approx(std::log(9.0)).epsilon(1e-4));
}

TEST_CASE("NEMP with a non-neutral classifier changes the association") {
  const RunResult plain = run_scene(nullptr, false);
  auto clutterish = std::make_unique<ConstantHead>(-3.0f);  // w = 0.047 for every detection
  auto nemp = std::make_unique<Nemp>();
  REQUIRE(nemp->init(&clutterish->classifier, mfbp::NempParams<float>{}) == Status::kOk);
  const RunResult fused = run_scene(nemp.get(), true);
  CHECK(fused.bits != plain.bits);
  CHECK(fused.bp_runs > plain.bp_runs);
}

TEST_CASE("NEMP: extrinsic belief divides the detection's own factor out") {
  // posterior clutter 0.2 with factor e^L, L = ln 3 applied: extrinsic
  // clutter odds 0.25 / 3 -> p_FG = 1 / (1 + 1/12) = 12/13.
  FakeBp bp;
  bp.pc[0] = 0.2f;
  const float p = Nemp::extrinsic_target_belief(bp, 0, std::log(3.0f));
  CHECK(p == doctest::Approx(12.0 / 13.0).epsilon(1e-6));
}

TEST_CASE("NEMP: one round by hand, and no double counting at the fixed point") {
  // w = sigmoid(ln 9) = 0.9, p_FG = 0.5 (posterior 0.5, no factor yet):
  // BetP = 0.45 / (0.45 + 0.05) = 0.9, L = ln odds(0.5) - ln odds(0.9) = -ln 9.
  auto head = std::make_unique<ConstantHead>(std::log(9.0f));
  auto nemp = std::make_unique<Nemp>();
  REQUIRE(nemp->init(&head->classifier, mfbp::NempParams<float>{}) == Status::kOk);
  auto ev = std::make_unique<Evidence>();
  ev->has_patch[0] = true;
  FakeSlot slot;
  nemp->store_scan(0, slot, ev.get());
  FakeBp bp;
  CHECK(nemp->update(0, 1, bp));
  CHECK(nemp->log_factor(0, 0) == doctest::Approx(-std::log(9.0)).epsilon(1e-5));
  // The next BP sees the factor: its posterior is BetP = 0.9. The extrinsic
  // belief is 0.5 again, so the factor stays -ln 9 (a full-belief loop would
  // fuse 0.9 with 0.9 and go to -2 ln 9).
  bp.pc[0] = 0.1f;
  nemp->update(0, 1, bp);
  CHECK(nemp->log_factor(0, 0) == doctest::Approx(-std::log(9.0)).epsilon(1e-4));
  // apply() adds it to the clutter evidence
  FakeBp target;
  nemp->apply(0, 1, target);
  CHECK(target.added[0] == nemp->log_factor(0, 0));
}

TEST_CASE("NEMP: a detection without a patch keeps a zero factor and is never applied") {
  auto head = std::make_unique<ConstantHead>(2.0f);
  auto nemp = std::make_unique<Nemp>();
  REQUIRE(nemp->init(&head->classifier, mfbp::NempParams<float>{}) == Status::kOk);
  FakeSlot slot;
  slot.count = 2;
  slot.orig_index[0] = 1;  // stored 0 is input 1 (no patch), stored 1 is input 0
  slot.orig_index[1] = 0;
  auto ev = std::make_unique<Evidence>();
  ev->has_patch[0] = true;
  nemp->store_scan(0, slot, ev.get());
  FakeBp bp;
  CHECK(nemp->update(0, 2, bp));
  CHECK(nemp->log_factor(0, 0) == 0.0f);
  CHECK(nemp->log_factor(0, 1) < 0.0f);
  FakeBp target;
  target.added[0] = 7.0f;
  nemp->apply(0, 2, target);
  CHECK(target.added[0] == 7.0f);
}

TEST_CASE("NEMP params are validated; the tracker refuses evidence without a state") {
  CHECK(mfbp::validate(mfbp::NempParams<float>{}) == Status::kOk);
  mfbp::NempParams<float> p;
  p.rounds = 0;
  CHECK(mfbp::validate(p) == Status::kInvalidArgument);
  p.rounds = mfbp::kMaxNempRounds + 1;
  CHECK(mfbp::validate(p) == Status::kInvalidArgument);
  p.rounds = 1;
  p.nn_reliability = 1.5f;
  CHECK(mfbp::validate(p) == Status::kInvalidArgument);
  p.nn_reliability = 1.0f;
  p.nn_log_odds_gain = 0.0f;
  CHECK(mfbp::validate(p) == Status::kInvalidArgument);
  p.nn_log_odds_gain = 17.0f;
  CHECK(mfbp::validate(p) == Status::kInvalidArgument);
  p.nn_log_odds_gain = 1.0f;
  p.nn_max_target_prob = 0.4f;
  CHECK(mfbp::validate(p) == Status::kInvalidArgument);
  p.nn_max_target_prob = 1.0f;
  p.birth_min_target_prob = -0.1f;
  CHECK(mfbp::validate(p) == Status::kInvalidArgument);
  p.birth_min_target_prob = 0.5f;
  CHECK(mfbp::validate(p) == Status::kOk);
  auto nemp = std::make_unique<Nemp>();
  classify::SeaClassifier unready;
  CHECK(nemp->init(&unready, mfbp::NempParams<float>{}) == Status::kNotInitialized);
  CHECK(nemp->init(nullptr, mfbp::NempParams<float>{}) == Status::kNotInitialized);
  auto trk = std::make_unique<Tracker>();
  REQUIRE(trk->init(seed000_default_params<float>()) == Status::kOk);
  CHECK(trk->attach_nemp(nemp.get()) == Status::kNotInitialized);
  auto scan = std::make_unique<TestScan>();
  auto ev = std::make_unique<Evidence>();
  mfbp_test::Lcg rng;
  mfbp_test::make_scan(rng, 0, 10, *scan);
  CHECK(trk->step(*scan, *ev) == Status::kNotInitialized);
}

TEST_CASE("NEMP: classifier features and NEMP association allocate nothing") {
  // The reference weights (w depends on the belief, so every round changes
  // the factors), the plain and the discounted DS rule, and the largest
  // round count: every branch of NempState::update() runs under the guard.
  auto classifier = std::make_unique<classify::SeaClassifier>();
  REQUIRE(classifier->init(test::classify_ref::weights()) == Status::kOk);
  mfbp::NempParams<float> plain;
  mfbp::NempParams<float> discounted;
  discounted.rounds = mfbp::kMaxNempRounds;
  discounted.nn_reliability = 0.7f;
  for (const mfbp::NempParams<float>& np : {plain, discounted}) {
    auto nemp = std::make_unique<Nemp>();
    REQUIRE(nemp->init(classifier.get(), np) == Status::kOk);
    auto trk = std::make_unique<Tracker>();
    MfbpParams<float> p = seed000_default_params<float>();
    p.uniform_rate_per_scan = 10.0f;
    REQUIRE(trk->init(p) == Status::kOk);
    REQUIRE(trk->attach_nemp(nemp.get()) == Status::kOk);
    auto ev = std::make_unique<Evidence>();
    auto scan = std::make_unique<TestScan>();
    auto patch = std::make_unique<std::array<float, classify::kPatchSize>>();
    for (std::size_t i = 0; i < classify::kPatchSize; ++i) (*patch)[i] = test::classify_ref::kPatch2[i];
    mfbp_test::Lcg rng;
    std::size_t allocs = 0;
    for (int k = 0; k < 12; ++k) {
      mfbp_test::make_scan(rng, k, 10, *scan);
      test::NoAllocScope guard;
      // Every detection has the same patch, so one inference per scan gives
      // every detection's features (ten identical CNN runs per scan made this
      // case take 70 s under qemu-ppc).
      classify::Features features{};
      const bool has_patch = classifier->features(patch->data(), features) == Status::kOk;
      for (std::size_t j = 0; j < scan->measurements.size(); ++j) {
        ev->has_patch[j] = has_patch;
        ev->features[j] = features;
      }
      const Status s = trk->step(*scan, *ev);
      allocs += guard.allocations();
      CHECK(s == Status::kOk);
    }
    CHECK(allocs == 0u);
    CHECK(trk->bp_runs() > 0u);
    bool moved = false;  // some round changed a clutter message, so the rounds ran
    for (std::size_t k = 0; k < TestCaps::kMaxWindow; ++k) {
      for (std::size_t c = 0; c < 10; ++c) moved = moved || nemp->log_factor(k, c) != 0.0f;
    }
    CHECK(moved);
  }
}
