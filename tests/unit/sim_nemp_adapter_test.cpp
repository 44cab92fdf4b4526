// The mfbp-nn and nemp adapters (host-sim/src/trackers/nemp_adapter.cpp)
// exist in the registry and refuse with a message, rather than running a
// plain MF-BP, when what they need is missing.
#include <doctest/doctest.h>

#include <string>

#include "mptrack/classify/trained_weights.h"
#include "tracker_registry.h"

TEST_CASE("mfbp-nn and nemp are registered and refuse without trained weights") {
  for (const char* name : {"mfbp-nn", "nemp"}) {
    std::string error;
    auto t = mptrack::sim::make_tracker(name, error);
    REQUIRE(t != nullptr);
    CHECK(error.empty());
    if (mptrack::classify::kHaveTrainedWeights) continue;  // init then depends on the scenario
    mptrack::sim::TrackerSetup setup;
    const std::string init_error = t->init(setup);
    CHECK(init_error.find("train-classifier") != std::string::npos);
  }
}

TEST_CASE("mfbp-nn and nemp refuse a scenario without range-Doppler patches") {
  if (!mptrack::classify::kHaveTrainedWeights) return;
  for (const char* name : {"mfbp-nn", "nemp"}) {
    std::string error;
    auto t = mptrack::sim::make_tracker(name, error);
    REQUIRE(t != nullptr);
    mptrack::sim::TrackerSetup setup;  // no sea_scenario: a measurement-level scene
    const std::string init_error = t->init(setup);
    CHECK(init_error.find("seed003-sea") != std::string::npos);
  }
}
