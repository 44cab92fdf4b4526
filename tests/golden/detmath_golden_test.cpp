// Cross-target bit-exactness of the deterministic elementary functions: the
// case is tests/golden/cases/detmath.cpp (shared with the bare-metal
// runner); the result bits are compared with tests/golden/data/detmath.golden.
// The same file must match on x86-64 and, under qemu, on aarch64, armhf and
// ppc: that is the proof that no libm, contraction or excess precision leaks in.
//
// Regenerate (only after an intended change of results, and review the diff):
//   MPTRACK_GOLDEN_REGENERATE=1 ctest -R detmath_golden_test
#include <doctest/doctest.h>

#include "cases/golden_cases.h"
#include "golden.h"

TEST_CASE("detmath results match the golden bits on every target") {
  mptrack::test::GoldenFile g("detmath");
  mptrack::test::golden_case_detmath(g);
  CHECK(g.size() > 5000u);
  CHECK(g.matches());
}
