// Golden record of the patch classifier and the DS fusion: the case is
// tests/golden/cases/classify.cpp (shared with the bare-metal runners).
// Regenerate (after an intended change): MPTRACK_GOLDEN_REGENERATE=1 ./sea_classifier_golden_test
#include <doctest/doctest.h>

#include "cases/golden_cases.h"
#include "golden.h"

TEST_CASE("Sea classifier golden: three reference patches, five beliefs, float, bit-exact") {
  mptrack::test::GoldenFile g("sea_classifier");
  mptrack::test::golden_case_sea_classifier(g);
  CHECK(g.failures() == 0u);
  CHECK(g.matches());
}
