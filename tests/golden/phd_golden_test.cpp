// Bit-exact golden record: the case is tests/golden/cases/phd.cpp (shared
// with the bare-metal runner). Same bits on x86-64, aarch64, armhf and ppc.
#include <doctest/doctest.h>

#include "cases/golden_cases.h"
#include "golden.h"

TEST_CASE("GM-PHD and GM-CPHD golden record") {
  mptrack::test::GoldenFile g("phd_filters");
  mptrack::test::golden_case_phd_filters(g);
  CHECK(g.failures() == 0u);
  CHECK(g.size() > 100u);
  CHECK(g.matches());
}
