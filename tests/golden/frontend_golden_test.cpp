// Bit-exact golden vectors for every front-end stage: the cases are
// tests/golden/cases/frontend.cpp (shared with the bare-metal runner).
// Passing on x86-64 and, under qemu, on aarch64, armhf and ppc proves the
// stages are bit-exact across targets.
// Regenerate: MPTRACK_GOLDEN_REGENERATE=1 ctest -R frontend_golden
#include <doctest/doctest.h>

#include "cases/golden_cases.h"
#include "golden.h"

using mptrack::test::GoldenFile;

TEST_CASE("frontend golden: FFT outputs (64 and 1024 points) and twiddles") {
  GoldenFile g("frontend_fft");
  mptrack::test::golden_case_frontend_fft(g);
  CHECK(g.failures() == 0u);
  CHECK(g.matches());
}

TEST_CASE("frontend golden: windows and range matched filter profiles") {
  GoldenFile g("frontend_range");
  mptrack::test::golden_case_frontend_range(g);
  CHECK(g.failures() == 0u);
  CHECK(g.matches());
}

TEST_CASE("frontend golden: Doppler snapshots and angle power map") {
  GoldenFile g("frontend_doppler_angle");
  mptrack::test::golden_case_frontend_doppler_angle(g);
  CHECK(g.failures() == 0u);
  CHECK(g.matches());
}

TEST_CASE("frontend golden: CFAR thresholds and noise estimates") {
  GoldenFile g("frontend_cfar");
  mptrack::test::golden_case_frontend_cfar(g);
  CHECK(g.failures() == 0u);
  CHECK(g.matches());
}

TEST_CASE("frontend golden: end-to-end measurements (seed 004 and Doppler configurations)") {
  GoldenFile g("frontend_pipeline");
  mptrack::test::golden_case_frontend_pipeline(g);
  CHECK(g.failures() == 0u);
  CHECK(g.matches());
}
