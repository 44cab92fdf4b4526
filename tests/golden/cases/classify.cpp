// Golden case of the patch classifier (core/include/mptrack/classify/):
// the features of the three reference patches of tests/tools/classify_reference.py
// with its test weights, the target probability for five tracker beliefs,
// and the Dempster-Shafer fusion of each with that belief (plain and
// discounted) and its clutter log-factor. Pins the float inference bit for
// bit on every target (fixed loop order, no FMA, the deterministic exp).
// Then the int8 g_M (trained int8 weights, when generated): the fc3
// accumulators and features of the same patches.
#include <array>
#include <cstddef>
#include <cstdint>

#include "../../unit/classify_reference_data.h"
#include "golden_cases.h"
#include "mptrack/classify/ds_fusion.h"
#include "mptrack/classify/sea_classifier.h"
#include "mptrack/classify/sea_features_q8.h"
#include "mptrack/classify/trained_weights.h"

namespace mptrack::test {

namespace {

Slot<classify::SeaClassifier> g_classifier;
Slot<classify::SeaFeaturesQ8> g_features_q8;
float g_patch[classify::kPatchSize];

void add_q8_features(GoldenSink& g) {
  namespace cl = classify;
  if (!cl::kHaveTrainedQ8Weights) return;
  cl::SeaFeaturesQ8& q = g_features_q8.make();
  g.require(q.init(cl::trained_q8_weights()) == Status::kOk, "int8 features init");
  for (std::size_t p = 0; p < classify_ref::kNumPatches; ++p) {
    std::array<std::int32_t, cl::kNumFeatures> acc{};
    g.require(q.logits(classify_ref::kPatches[p], acc) == Status::kOk, "int8 logits");
    cl::Features f{};
    g.require(q.features(classify_ref::kPatches[p], f) == Status::kOk, "int8 features");
    const Label s = Label("q8.p") + p;
    for (std::size_t k = 0; k < cl::kNumFeatures; ++k) {
      g.add(s + ".acc" + k, acc[k]);
      g.add(s + ".h" + k, f[k]);
    }
  }
}

}  // namespace

void golden_case_sea_classifier(GoldenSink& g) {
  namespace cl = classify;
  cl::SeaClassifier& c = g_classifier.make();
  g.require(c.init(classify_ref::weights()) == Status::kOk, "classifier init");
  for (std::size_t p = 0; p < classify_ref::kNumPatches; ++p) {
    for (std::size_t i = 0; i < cl::kPatchSize; ++i) g_patch[i] = static_cast<float>(classify_ref::kPatches[p][i]);
    cl::Features f{};
    g.require(c.features(g_patch, f) == Status::kOk, "classifier features");
    const Label s = Label("p") + p;
    for (std::size_t k = 0; k < cl::kNumFeatures; ++k) g.add(s + ".h" + k, f[k]);
    for (std::size_t b = 0; b < classify_ref::kNumBeliefs; ++b) {
      const float belief = static_cast<float>(classify_ref::kBeliefs[b]);
      const float w = c.target_probability(f, belief);
      const float fused = cl::ds_normalized_product(belief, w);
      const Label q = s + ".b" + b;
      g.add(q + ".w", w);
      g.add(q + ".ds", fused);
      g.add(q + ".ds_a07", cl::ds_discounted_betp(belief, w, 0.7f));
      g.add(q + ".logc", cl::clutter_log_factor(belief, fused));
    }
  }
  add_q8_features(g);
}

}  // namespace mptrack::test
