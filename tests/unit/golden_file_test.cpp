#include <doctest/doctest.h>

#include "golden.h"

using mptrack::test::hex_bits;

TEST_CASE("hex_bits prints IEEE-754 bit patterns") {
  CHECK(hex_bits(1.0f) == "3f800000");
  CHECK(hex_bits(-2.0f) == "c0000000");
  CHECK(hex_bits(1.0) == "3ff0000000000000");
  CHECK(hex_bits(-0.0) == "8000000000000000");
}

TEST_CASE("golden comparison detects a single flipped bit") {
  // golden_file_selftest.golden is committed with exactly these values.
  mptrack::test::GoldenFile same("golden_file_selftest");
  same.add("one", 1.0f);
  same.add("third", 1.0 / 3.0);
  same.add("count", 42);
  CHECK(same.matches());

  mptrack::test::GoldenFile flipped("golden_file_selftest");
  flipped.add("one", 1.0f);
  flipped.add("third", 0.33333333333333337);  // 1/3 plus one ulp
  flipped.add("count", 42);
  if (std::getenv("MPTRACK_GOLDEN_REGENERATE") == nullptr) CHECK_FALSE(flipped.matches());
}

TEST_CASE("a missing golden file is a failure, not a pass") {
  mptrack::test::GoldenFile g("does_not_exist_anywhere");
  g.add("x", 1.0);
  if (std::getenv("MPTRACK_GOLDEN_REGENERATE") == nullptr) CHECK_FALSE(g.matches());
}
