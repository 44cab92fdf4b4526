// Golden record of the multipath MF-BP tracker (float, SmallBoardCaps): the
// case is tests/golden/cases/multipath.cpp (12 OTHR scans of two targets on
// four paths, shared with the bare-metal runner); the same file must match
// on x86-64 and, under qemu, aarch64, armhf and ppc, and on the Cortex-M7.
// Regenerate (after an intended change): MPTRACK_GOLDEN_REGENERATE=1 ./multipath_golden_test
#include <doctest/doctest.h>

#include "cases/golden_cases.h"
#include "golden.h"

TEST_CASE("multipath golden: 12 OTHR scans of two targets on four paths, float, bit-exact") {
  mptrack::test::GoldenFile g("multipath_tracker");
  mptrack::test::golden_case_multipath_tracker(g);
  CHECK(g.failures() == 0u);
  CHECK(g.size() > 100u);
  CHECK(g.matches());
}
