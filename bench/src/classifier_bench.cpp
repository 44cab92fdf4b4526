// Host latency of the seed 003 patch classifier (docs/algorithms/nemp.md
// §Cost): features() per detection and target_probability() per NEMP round,
// with the reference test weights (the cost does not depend on the values),
// and the int8 g_M's features() (sea_features_q8.h, with the trained int8
// set: there is no int8 test set).
// Prints the median and the 99th percentile of `runs` timed calls; with
// --out DIR also writes DIR/classifier.json (`./run bench`: build/bench-results/).
//   mptrack-bench-classifier [runs] [--out DIR]
#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "classify_reference_data.h"
#include "mptrack/classify/sea_classifier.h"
#include "mptrack/classify/sea_features_q8.h"
#include "mptrack/classify/trained_weights.h"

namespace {

namespace cl = mptrack::classify;
using Clock = std::chrono::steady_clock;

struct Stats {
  double p50 = 0.0, p99 = 0.0;
};

Stats report(const char* what, std::vector<double>& us, std::size_t macs) {
  std::sort(us.begin(), us.end());
  const Stats s{us[us.size() / 2], us[(us.size() * 99) / 100]};
  std::printf("%-20s p50 %9.2f us  p99 %9.2f us  MACs %zu  (%.2f GMAC/s)\n", what, s.p50, s.p99, macs,
              static_cast<double>(macs) / (s.p50 * 1e3));
  return s;
}

/// DIR/classifier.json: latency per detection (features) and per NEMP round (MLP), MACs, sizes.
bool write_json(const std::string& dir, std::size_t runs, Stats feat, Stats mlp, Stats feat_q8) {
  const std::string path = dir + "/classifier.json";
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (f == nullptr) return false;
  std::fprintf(f,
               "{\n  \"runs\": %zu,\n"
               "  \"features_us\": {\"p50\": %.3f, \"p99\": %.3f, \"macs\": %zu},\n"
               "  \"target_probability_us\": {\"p50\": %.4f, \"p99\": %.4f, \"macs\": %zu},\n"
               "  \"parameters\": %zu,\n  \"parameter_bytes\": %zu,\n  \"scratch_bytes\": %zu,\n"
               "  \"object_bytes\": %zu,\n"
               "  \"features_int8_us\": {\"p50\": %.3f, \"p99\": %.3f},\n"
               "  \"int8_weight_bytes\": %zu,\n  \"int8_scratch_bytes\": %zu,\n  \"int8_object_bytes\": %zu\n}\n",
               runs, feat.p50, feat.p99, cl::SeaClassifier::kFeatureMacs, mlp.p50, mlp.p99,
               cl::SeaClassifier::kMlpMacs, cl::kNumParameters, cl::kNumParameters * sizeof(float),
               cl::SeaClassifier::kScratchBytes, sizeof(cl::SeaClassifier), feat_q8.p50, feat_q8.p99,
               cl::SeaFeaturesQ8::kWeightBytes, cl::SeaFeaturesQ8::kScratchBytes, sizeof(cl::SeaFeaturesQ8));
  return std::fclose(f) == 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t runs = 300;
  std::string out_dir;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--out") == 0 && i + 1 < argc) {
      out_dir = argv[++i];
    } else {
      runs = static_cast<std::size_t>(std::atol(argv[i]));
    }
  }
  if (runs == 0) return 2;
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
  const Stats feat = report("features()", t_feat, cl::SeaClassifier::kFeatureMacs);
  const Stats mlp = report("target_probability()", t_mlp, cl::SeaClassifier::kMlpMacs);
  std::printf("parameters %zu (%zu bytes float32), scratch %zu bytes, object %zu bytes\n", cl::kNumParameters,
              cl::kNumParameters * sizeof(float), cl::SeaClassifier::kScratchBytes, sizeof(cl::SeaClassifier));
  Stats feat_q8;
  if (cl::kHaveTrainedQ8Weights) {
    static cl::SeaFeaturesQ8 q;
    if (q.init(cl::trained_q8_weights()) != mptrack::Status::kOk) return 1;
    std::vector<double> t_q8(runs);
    for (std::size_t r = 0; r < runs; ++r) {
      const auto t0 = Clock::now();
      if (q.features(mptrack::test::classify_ref::kPatch2, f) != mptrack::Status::kOk) return 1;
      t_q8[r] = std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
      sink = sink + f[0];
    }
    feat_q8 = report("int8 features()", t_q8, cl::SeaClassifier::kFeatureMacs);
    std::printf("int8 g_M: weights %zu bytes, scratch %zu bytes, object %zu bytes\n", cl::SeaFeaturesQ8::kWeightBytes,
                cl::SeaFeaturesQ8::kScratchBytes, sizeof(cl::SeaFeaturesQ8));
  }
  if (!out_dir.empty() && !write_json(out_dir, runs, feat, mlp, feat_q8)) {
    std::fprintf(stderr, "%s/classifier.json: cannot write\n", out_dir.c_str());
    return 1;
  }
  return 0;
}
