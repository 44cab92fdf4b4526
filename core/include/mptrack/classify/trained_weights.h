// The trained classifier weights, when the training export has written
// generated/sea_classifier_weights.h (`./run train-classifier`,
// docs/algorithms/nemp.md §Network). Without it, kHaveTrainedWeights is
// false and trained_weights() returns an incomplete set, which
// SeaClassifier::init() rejects.
#pragma once

#include "mptrack/classify/sea_classifier_weights.h"
#include "mptrack/classify/sea_features_q8.h"

#if __has_include("mptrack/classify/generated/sea_classifier_weights.h")
#include "mptrack/classify/generated/sea_classifier_weights.h"
#define MPTRACK_HAVE_TRAINED_CLASSIFIER 1
#else
#define MPTRACK_HAVE_TRAINED_CLASSIFIER 0
#endif
#if __has_include("mptrack/classify/generated/sea_features_q8_weights.h")
#include "mptrack/classify/generated/sea_features_q8_weights.h"
#define MPTRACK_HAVE_TRAINED_CLASSIFIER_Q8 1
#else
#define MPTRACK_HAVE_TRAINED_CLASSIFIER_Q8 0
#endif

namespace mptrack::classify {

inline constexpr bool kHaveTrainedWeights = MPTRACK_HAVE_TRAINED_CLASSIFIER != 0;
/// The int8 g_M quantised from the trained set (`./run quantise-classifier`).
inline constexpr bool kHaveTrainedQ8Weights = MPTRACK_HAVE_TRAINED_CLASSIFIER_Q8 != 0;

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

/// The int8 g_M of the trained set; incomplete (SeaFeaturesQ8::init()
/// rejects it) without generated/sea_features_q8_weights.h.
inline SeaFeaturesQ8Weights trained_q8_weights() {
  SeaFeaturesQ8Weights w;
#if MPTRACK_HAVE_TRAINED_CLASSIFIER_Q8
  namespace g = generated;
  w.conv1 = {g::kQ8Conv1Weight, g::kQ8Conv1Bias, g::kQ8Conv1Mult, g::kQ8Conv1Shift};
  w.conv2 = {g::kQ8Conv2Weight, g::kQ8Conv2Bias, g::kQ8Conv2Mult, g::kQ8Conv2Shift};
  w.conv3 = {g::kQ8Conv3Weight, g::kQ8Conv3Bias, g::kQ8Conv3Mult, g::kQ8Conv3Shift};
  w.fc1 = {g::kQ8Fc1Weight, g::kQ8Fc1Bias, g::kQ8Fc1Mult, g::kQ8Fc1Shift};
  w.fc2 = {g::kQ8Fc2Weight, g::kQ8Fc2Bias, g::kQ8Fc2Mult, g::kQ8Fc2Shift};
  w.fc3_weight = g::kQ8Fc3Weight;
  w.fc3_bias = g::kQ8Fc3Bias;
  w.fc3_out_scale = g::kQ8Fc3OutScale;
  w.input_zero_point = g::kQ8InputZeroPoint;
#endif
  return w;
}

}  // namespace mptrack::classify
