// Golden record of the SBL detector: the case is tests/golden/cases/sbl.cpp
// (shared with the bare-metal runners).
// Regenerate (after an intended change): MPTRACK_GOLDEN_REGENERATE=1 ./sbl_golden_test
#include <doctest/doctest.h>

#include "cases/golden_cases.h"
#include "golden.h"

TEST_CASE("SBL golden: two frames of seed 004 echoes in noise, float, bit-exact") {
  mptrack::test::GoldenFile g("sbl_detector");
  mptrack::test::golden_case_sbl_detector(g);
  CHECK(g.failures() == 0u);
  CHECK(g.matches());
}
