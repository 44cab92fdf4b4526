// Golden record of the GNN + CV-EKF baseline: the case is
// tests/golden/cases/gnn.cpp (shared with the bare-metal runner).
// Regenerate (after an intended change): MPTRACK_GOLDEN_REGENERATE=1 ./gnn_golden_test
#include <doctest/doctest.h>

#include "cases/golden_cases.h"
#include "golden.h"

TEST_CASE("GNN golden: 20 scans of two targets in light clutter, float, bit-exact") {
  mptrack::test::GoldenFile g("gnn_tracker");
  mptrack::test::golden_case_gnn_tracker(g);
  CHECK(g.failures() == 0u);  // includes: both targets confirmed, no clutter track
  CHECK(g.matches());
}
