// Host latency of the seed 003 patch classifier (docs/algorithms/nemp.md
// §Cost): features() per detection and target_probability() per NEMP round,
// with the reference test weights (the cost does not depend on the values).
// Prints the median and the 99th percentile of `runs` timed calls.
//   mptrack-bench-classifier [runs]
#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "classify_reference_data.h"
#include "mptrack/classify/sea_classifier.h"

namespace {

namespace cl = mptrack::classify;
using Clock = std::chrono::steady_clock;

void report(const char* what, std::vector<double>& us, std::size_t macs) {
  std::sort(us.begin(), us.end());
  const double p50 = us[us.size() / 2];
  const double p99 = us[(us.size() * 99) / 100];
  std::printf("%-20s p50 %9.2f us  p99 %9.2f us  MACs %zu  (%.2f GMAC/s)\n", what, p50, p99, macs,
              static_cast<double>(macs) / (p50 * 1e3));
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t runs = argc > 1 ? static_cast<std::size_t>(std::atol(argv[1])) : 300;
  static cl::SeaClassifier c;
  if (c.init(mptrack::test::classify_ref::weights()) != mptrack::Status::kOk) return 1;
  static std::array<float, cl::kPatchSize> patch{};
  for (std::size_t i = 0; i < cl::kPatchSize; ++i) patch[i] = mptrack::test::classify_ref::kPatch2[i];
  cl::Features f{};
  std::vector<double> t_feat(runs), t_mlp(runs);
  volatile float sink = 0.0f;
  for (std::size_t r = 0; r < runs; ++r) {
    const auto t0 = Clock::now();
    if (c.features(patch.data(), f) != mptrack::Status::kOk) return 1;
    const auto t1 = Clock::now();
    float w = 0.0f;
    for (int k = 0; k < 100; ++k) w += c.target_probability(f, 0.01f * static_cast<float>(k));
    const auto t2 = Clock::now();
    sink = sink + w;
    t_feat[r] = std::chrono::duration<double, std::micro>(t1 - t0).count();
    t_mlp[r] = std::chrono::duration<double, std::micro>(t2 - t1).count() / 100.0;
  }
  report("features()", t_feat, cl::SeaClassifier::kFeatureMacs);
  report("target_probability()", t_mlp, cl::SeaClassifier::kMlpMacs);
  std::printf("parameters %zu (%zu bytes float32), scratch %zu bytes, object %zu bytes\n", cl::kNumParameters,
              cl::kNumParameters * sizeof(float), cl::SeaClassifier::kScratchBytes, sizeof(cl::SeaClassifier));
  return 0;
}
