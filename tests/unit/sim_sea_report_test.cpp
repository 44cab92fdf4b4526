// The seed 003 comparison report (host-sim/src/sea_report.cpp): NEMP against
// MP-NN paired over runs, per SCR, in compare.json and under the markdown
// table.
#include <doctest/doctest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "sea_runner.h"

using namespace mptrack::sim;

namespace {

SeaSummary summary(const char* tracker, std::vector<double> amota, std::vector<double> mospa) {
  SeaSummary s;
  s.base.tracker = tracker;
  s.base.track_scores.amota_per_run = std::move(amota);
  s.base.ospa_mahalanobis_per_run = std::move(mospa);
  return s;
}

SeaCompareConfig config() {
  SeaCompareConfig cfg;
  cfg.scenario.name = "seed003-sea-a";
  cfg.runs = 2;
  return cfg;
}

}  // namespace

TEST_CASE("sea report: NEMP - MP-NN paired per run, mean and standard error of the differences") {
  // AMOTA differences 0.1 and 0.3: mean 0.2, sample sd 0.1 sqrt(2), SE 0.1.
  // MOSPA differences -1 and -2: mean -1.5, sd sqrt(0.5), SE 0.5; NEMP lower in both runs.
  const std::vector<std::vector<SeaSummary>> r = {
      {summary("mfbp-nn", {0.4, 0.4}, {6.0, 7.0}), summary("nemp", {0.5, 0.7}, {5.0, 5.0})}};
  const auto j = sea_compare_to_json(config(), r);
  const auto& p = j["levels"][0]["nemp_minus_mfbp_nn"];
  CHECK(p["amota"]["mean"].get<double>() == doctest::Approx(0.2));
  CHECK(p["amota"]["standard_error"].get<double>() == doctest::Approx(0.1));
  CHECK(p["amota"]["runs"].get<int>() == 2);
  CHECK(p["mospa_mahalanobis"]["mean"].get<double>() == doctest::Approx(-1.5));
  CHECK(p["mospa_mahalanobis"]["standard_error"].get<double>() == doctest::Approx(0.5));
  CHECK(p["mospa_mahalanobis"]["nemp_lower"].get<int>() == 2);
  const std::string md = sea_compare_to_markdown(config(), r);
  CHECK(md.find("| AMOTA | +0.200 +- 0.100 |") != std::string::npos);
  CHECK(md.find("| MOSPA | -1.500 +- 0.500 |") != std::string::npos);
}

TEST_CASE("sea report: no paired rows without both MP-NN and NEMP") {
  const std::vector<std::vector<SeaSummary>> r = {
      {summary("mfbp", {0.1, 0.2}, {9.0, 9.0}), summary("nemp", {0.5, 0.7}, {5.0, 5.0})}};
  CHECK_FALSE(sea_compare_to_json(config(), r)["levels"][0].contains("nemp_minus_mfbp_nn"));
  CHECK(sea_compare_to_markdown(config(), r).find("NEMP - MP-NN") == std::string::npos);
}

namespace {

SeaSummary scored(const char* tracker, std::vector<double> amota, double mospa) {
  SeaSummary s = summary(tracker, std::move(amota), {mospa, mospa});
  s.base.track_scores.runs = static_cast<std::uint32_t>(s.base.track_scores.amota_per_run.size());
  s.base.mean_ospa_mahalanobis = mospa;
  return s;
}

}  // namespace

TEST_CASE("sea report: NEMP - MP-NN over all SCRs averages each run over the SCRs, then pairs the runs") {
  // Two SCRs, two runs. Per-run differences NEMP - MP-NN: SCR 1 (0.1, 0.3),
  // SCR 2 (0.3, 0.1). Averaged over the SCRs per run: (0.2, 0.2), so the
  // mean is 0.2 with standard error 0 (the columns' own SEs are 0.1 each).
  std::vector<std::vector<SeaSummary>> r = {
      {summary("mfbp-nn", {0.4, 0.4}, {6.0, 6.0}), summary("nemp", {0.5, 0.7}, {5.0, 6.0})},
      {summary("mfbp-nn", {0.4, 0.4}, {6.0, 6.0}), summary("nemp", {0.7, 0.5}, {7.0, 6.0})}};
  r[0][0].scr_db = 0.0;
  r[1][0].scr_db = 4.0;
  const auto j = sea_compare_to_json(config(), r);
  const auto& all = j["nemp_minus_mfbp_nn_over_scr"];
  CHECK(all["amota"]["mean"].get<double>() == doctest::Approx(0.2));
  CHECK(all["amota"]["standard_error"].get<double>() == doctest::Approx(0.0));
  CHECK(all["amota"]["runs"].get<int>() == 2);
  // MOSPA differences: SCR 1 (-1, 0), SCR 2 (+1, 0): per run (0, 0).
  CHECK(all["mospa_mahalanobis"]["mean"].get<double>() == doctest::Approx(0.0));
  const std::string md = sea_compare_to_markdown(config(), r);
  CHECK(md.find("| metric | 0 dB | 4 dB | mean over SCRs |\n|---|---:|---:|---:|\n") != std::string::npos);
  CHECK(md.find("| AMOTA | +0.200 +- 0.100 | +0.200 +- 0.100 | +0.200 +- 0.000 |") != std::string::npos);
}

TEST_CASE("sea report: the best rows name every tracker within 0.005 of the best AMOTA and MOSPA") {
  // AMOTA (MP / MP-NN / NEMP) 0.400 / 0.500 / 0.504: MP-NN is 0.004 behind,
  // so level. MOSPA 9.00 / 5.01 / 5.00: MP-NN is 0.01 behind, so NEMP alone.
  const std::vector<std::vector<SeaSummary>> r = {
      {scored("mfbp", {0.4, 0.4}, 9.0), scored("mfbp-nn", {0.5, 0.5}, 5.01), scored("nemp", {0.504, 0.504}, 5.0)}};
  const std::string md = sea_compare_to_markdown(config(), r);
  CHECK(md.find("| best AMOTA (within 0.005) | | MP-NN/NEMP |") != std::string::npos);
  CHECK(md.find("| best MOSPA (within 0.005) | | NEMP |") != std::string::npos);
}
