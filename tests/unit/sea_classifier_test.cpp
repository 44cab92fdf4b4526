// Patch classifier inference (core/include/mptrack/classify/sea_classifier.h)
// against the float64 numpy reference of tests/tools/classify_reference.py
// (test weights, three patches, committed in classify_reference_data.h).
//
// Tolerance: features and target probabilities agree with float64 within
// kTol = 2e-6 absolute (sigmoid outputs in (0, 1); float32 sums of up to
// 1 680 products, the measured worst difference is about 3e-7).
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "alloc_guard.h"
#include "classify_reference_data.h"
#include "mptrack/classify/sea_classifier.h"
#include "mptrack/classify/trained_weights.h"

namespace {

namespace cl = mptrack::classify;
namespace ref = mptrack::test::classify_ref;
using mptrack::Status;

constexpr double kTol = 2e-6;

std::array<float, cl::kPatchSize> patch_of(std::size_t p) {
  std::array<float, cl::kPatchSize> x{};
  for (std::size_t i = 0; i < cl::kPatchSize; ++i) x[i] = static_cast<float>(ref::kPatches[p][i]);
  return x;
}

cl::SeaClassifier& classifier() {
  static cl::SeaClassifier c;
  static const Status s = c.init(ref::weights());
  REQUIRE(s == Status::kOk);
  return c;
}

}  // namespace

TEST_CASE("SeaClassifier: features match the float64 numpy reference within 2e-6") {
  cl::SeaClassifier& c = classifier();
  double worst = 0.0;
  for (std::size_t p = 0; p < ref::kNumPatches; ++p) {
    const auto x = patch_of(p);
    cl::Features f{};
    REQUIRE(c.features(x.data(), f) == Status::kOk);
    for (std::size_t k = 0; k < cl::kNumFeatures; ++k) {
      const double d = std::fabs(static_cast<double>(f[k]) - ref::kFeatures[p * cl::kNumFeatures + k]);
      worst = d > worst ? d : worst;
      CHECK(d <= kTol);
    }
  }
  MESSAGE("worst feature difference " << worst);
}

TEST_CASE("SeaClassifier: target probabilities match the numpy reference within 2e-6") {
  cl::SeaClassifier& c = classifier();
  double worst = 0.0;
  for (std::size_t p = 0; p < ref::kNumPatches; ++p) {
    const auto x = patch_of(p);
    cl::Features f{};
    REQUIRE(c.features(x.data(), f) == Status::kOk);
    for (std::size_t b = 0; b < ref::kNumBeliefs; ++b) {
      const float w = c.target_probability(f, static_cast<float>(ref::kBeliefs[b]));
      const double d = std::fabs(static_cast<double>(w) - ref::kProbabilities[p * ref::kNumBeliefs + b]);
      worst = d > worst ? d : worst;
      CHECK(d <= kTol);
    }
  }
  MESSAGE("worst probability difference " << worst);
}

TEST_CASE("SeaClassifier: the belief input changes the target probability") {
  // The reference varies with the belief (not a constant head); the C++ must too.
  cl::SeaClassifier& c = classifier();
  const auto x = patch_of(1);
  cl::Features f{};
  REQUIRE(c.features(x.data(), f) == Status::kOk);
  CHECK(c.target_probability(f, 0.0f) != c.target_probability(f, 1.0f));
}

TEST_CASE("SeaClassifier: features() and target_probability() allocate nothing") {
  cl::SeaClassifier& c = classifier();
  const auto x = patch_of(2);
  cl::Features f{};
  float w = 0.0f;
  {
    mptrack::test::NoAllocScope guard;
    REQUIRE(c.features(x.data(), f) == Status::kOk);
    w = c.target_probability(f, 0.5f);
    CHECK(guard.allocations() == 0);
  }
  CHECK(w > 0.0f);
}

TEST_CASE("SeaClassifier: init rejects incomplete weights and bad normalisation") {
  cl::SeaClassifier c;
  cl::SeaClassifierWeights w = ref::weights();
  w.fc2_bias = nullptr;
  CHECK(c.init(w) == Status::kInvalidArgument);
  w = ref::weights();
  w.input_scale = 0.0f;
  CHECK(c.init(w) == Status::kInvalidArgument);
  w = ref::weights();
  w.input_offset = std::numeric_limits<float>::quiet_NaN();
  CHECK(c.init(w) == Status::kInvalidArgument);
  w = ref::weights();
  w.train_target_fraction = 1.0f;
  CHECK(c.init(w) == Status::kInvalidArgument);
  CHECK_FALSE(c.ready());
  CHECK(c.init(ref::weights()) == Status::kOk);
  CHECK(c.ready());
}

TEST_CASE("SeaClassifier: features() before init and on a non-finite patch") {
  cl::SeaClassifier c;
  auto x = patch_of(0);
  cl::Features f{};
  f.fill(-1.0f);
  CHECK(c.features(x.data(), f) == Status::kNotInitialized);
  REQUIRE(c.init(ref::weights()) == Status::kOk);
  x[777] = std::numeric_limits<float>::infinity();
  CHECK(c.features(x.data(), f) == Status::kInvalidInput);
  CHECK(f[0] == -1.0f);
}

TEST_CASE("SeaClassifier: MAC counts and scratch size") {
  // By hand: conv1 8 x (5*3 - 2 padded rows) x (512*7 - 2*(3+2+1) padded cols)
  // = 8 * 13 * 3572; conv2 16*8 * 13 * (128*5 - 2*(2+1)); conv3 16*16 * 13 *
  // (32*3 - 2); fc 128*32 + 32*16 + 16*8; MLP 9*16 + 16*8 + 8.
  CHECK(cl::SeaClassifier::kFeatureMacs == 8u * 13u * 3572u + 128u * 13u * 634u + 256u * 13u * 94u + 4736u);
  CHECK(cl::SeaClassifier::kMlpMacs == 280u);
  CHECK(cl::SeaClassifier::kScratchBytes == (2560u + 5120u) * 4u);
  CHECK(cl::kNumParameters == 168u + 8u + 1920u + 16u + 2304u + 16u + 4096u + 32u + 512u + 16u + 128u + 8u +
                                  144u + 16u + 128u + 8u + 8u + 1u);
}

TEST_CASE("SeaClassifier: trained_weights() binds a complete set exactly when the header exists") {
  CHECK(cl::trained_weights().complete() == cl::kHaveTrainedWeights);
}
