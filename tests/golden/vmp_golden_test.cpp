// Golden record of the VMP tracker on raw frames: the case is
// tests/golden/cases/vmp.cpp (shared with the bare-metal runners).
// Regenerate (after an intended change): MPTRACK_GOLDEN_REGENERATE=1 ./vmp_golden_test
#include <doctest/doctest.h>

#include "cases/golden_cases.h"
#include "golden.h"

TEST_CASE("VMP golden: 16 raw frames of two converging drones, float, bit-exact") {
  mptrack::test::GoldenFile g("vmp_tracker");
  mptrack::test::golden_case_vmp_tracker(g);
  CHECK(g.failures() == 0u);  // includes: both drones born, nothing else
  CHECK(g.matches());
}
