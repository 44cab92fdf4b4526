// Bit-exact golden vectors of the MF-BP tracker (float): the case is
// tests/golden/cases/mfbp.cpp (shared with the bare-metal runner); the same
// file must match on x86-64 and, under qemu, aarch64, armhf and ppc.
#include <doctest/doctest.h>

#include "cases/golden_cases.h"
#include "golden.h"

TEST_CASE("mfbp golden: online filter and smoother, 30 scans, float bits") {
  mptrack::test::GoldenFile g("mfbp_tracker");
  mptrack::test::golden_case_mfbp_tracker(g);
  CHECK(g.failures() == 0u);
  CHECK(g.size() > 200u);
  CHECK(g.matches());
}
