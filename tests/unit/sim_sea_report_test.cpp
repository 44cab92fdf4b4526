// The seed 003 comparison report (host-sim/src/sea_report.cpp): NEMP against
// MP-NN paired over runs, per SCR, in compare.json and under the markdown
// table.
#include <doctest/doctest.h>

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
