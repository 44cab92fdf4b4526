// `--rfs-param` and `--mfbp-param` (host-sim/src/trackers/*_param_override.h
// on param_override.h): one behaviour per case.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "trackers/mfbp_param_override.h"
#include "trackers/rfs_param_override.h"

using namespace mptrack;
using namespace mptrack::sim;

TEST_CASE("rfs-param: a real and a flag are set by name, in order") {
  RfsFilterParams<double> p;
  REQUIRE(apply_rfs_params(p, {"extract_threshold=0.9", "amplitude.use_amplitude=0", "extract_threshold=0.8"}).empty());
  CHECK(p.extract_threshold == 0.8);
  CHECK_FALSE(p.amplitude.use_amplitude);
}

TEST_CASE("rfs-param: an unknown name is refused with the option and the name") {
  RfsFilterParams<double> p;
  const std::string e = apply_rfs_params(p, {"extract=0.9"});
  CHECK(e.find("--rfs-param") != std::string::npos);
  CHECK(e.find("'extract'") != std::string::npos);
}

TEST_CASE("rfs-param: a value that is not a number leaves the field unchanged") {
  RfsFilterParams<double> p;
  const double before = p.extract_threshold;
  CHECK_FALSE(apply_rfs_params(p, {"extract_threshold=high"}).empty());
  CHECK(p.extract_threshold == before);
}

TEST_CASE("rfs-param: a flag given without its block is refused with the full name") {
  RfsFilterParams<double> p;
  CHECK(apply_rfs_params(p, {"use_amplitude=0"}).find("'amplitude.use_amplitude'") != std::string::npos);
}

TEST_CASE("rfs-param: a flag other than 0 or 1 is refused") {
  RfsFilterParams<double> p;
  CHECK_FALSE(apply_rfs_params(p, {"amplitude.use_amplitude=2"}).empty());
  CHECK(p.amplitude.use_amplitude);
}

TEST_CASE("mfbp-param: a count must be an integer") {
  MfbpParams<double> p;
  CHECK(apply_mfbp_params(p, {"window_length=2.5"}).find("integer") != std::string::npos);
  REQUIRE(apply_mfbp_params(p, {"window_length=5"}).empty());
  CHECK(p.window_length == 5u);
}

TEST_CASE("mfbp-param: NEMP's fields are passed by, RFS names are not MF-BP's") {
  MfbpParams<double> p;
  CHECK(apply_mfbp_params(p, {"nemp.rounds=3"}).empty());
  CHECK(apply_mfbp_params(p, {"extract_threshold=0.9"}).find("--mfbp-param") != std::string::npos);
}
