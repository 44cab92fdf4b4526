// Bit-exact golden record: the case is tests/golden/cases/cbmember.cpp (shared
// with the bare-metal runner). Same bits on x86-64, aarch64, armhf and ppc.
#include <doctest/doctest.h>

#include "cases/golden_cases.h"
#include "golden.h"

TEST_CASE("CBMeMBer golden record") {
  mptrack::test::GoldenFile g("cbmember_filter");
  mptrack::test::golden_case_cbmember_filter(g);
  CHECK(g.failures() == 0u);
  CHECK(g.size() > 50u);
  CHECK(g.matches());
}
