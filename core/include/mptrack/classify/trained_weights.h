// The trained classifier weights, when the training export has written
// generated/sea_classifier_weights.h (`./run train-classifier`,
// docs/algorithms/nemp.md §Network). Without it, kHaveTrainedWeights is
// false and trained_weights() returns an incomplete set, which
// SeaClassifier::init() rejects.
#pragma once

#include "mptrack/classify/sea_classifier_weights.h"

#if __has_include("mptrack/classify/generated/sea_classifier_weights.h")
#include "mptrack/classify/generated/sea_classifier_weights.h"
#define MPTRACK_HAVE_TRAINED_CLASSIFIER 1
#else
#define MPTRACK_HAVE_TRAINED_CLASSIFIER 0
#endif

namespace mptrack::classify {

inline constexpr bool kHaveTrainedWeights = MPTRACK_HAVE_TRAINED_CLASSIFIER != 0;

inline SeaClassifierWeights trained_weights() {
  SeaClassifierWeights w;
#if MPTRACK_HAVE_TRAINED_CLASSIFIER
  namespace g = generated;
  w.conv1_weight = g::kConv1Weight;
  w.conv1_bias = g::kConv1Bias;
  w.conv2_weight = g::kConv2Weight;
  w.conv2_bias = g::kConv2Bias;
  w.conv3_weight = g::kConv3Weight;
  w.conv3_bias = g::kConv3Bias;
  w.fc1_weight = g::kFc1Weight;
  w.fc1_bias = g::kFc1Bias;
  w.fc2_weight = g::kFc2Weight;
  w.fc2_bias = g::kFc2Bias;
  w.fc3_weight = g::kFc3Weight;
  w.fc3_bias = g::kFc3Bias;
  w.mlp1_weight = g::kMlp1Weight;
  w.mlp1_bias = g::kMlp1Bias;
  w.mlp2_weight = g::kMlp2Weight;
  w.mlp2_bias = g::kMlp2Bias;
  w.mlp3_weight = g::kMlp3Weight;
  w.mlp3_bias = g::kMlp3Bias;
  w.input_scale = g::kInputScale;
  w.input_offset = g::kInputOffset;
  w.train_target_fraction = g::kTrainTargetFraction;
#endif
  return w;
}

}  // namespace mptrack::classify
