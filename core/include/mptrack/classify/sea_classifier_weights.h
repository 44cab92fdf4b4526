// Weights of the range-Doppler patch classifier (docs/algorithms/nemp.md
// §Network): the CNN feature extractor g_M and the classifier MLP g_c of
// seed 003 Figs. 2-3, in the embedded size of the same section.
//
// The network reads its weights through this struct of pointers, so the
// trained set (generated/sea_classifier_weights.h, written by the training
// export) and the test sets of tests/unit share one inference code path.
// Layouts are PyTorch's: conv [out][in][kh][kw], linear [out][in]; BatchNorm
// is folded into the conv weights and biases at export.
#pragma once

#include <array>
#include <cstddef>

namespace mptrack::classify {

/// Patch: kPatchRange range bins x kPatchDoppler Doppler bins, values 0..255.
inline constexpr std::size_t kPatchRange = 5;
inline constexpr std::size_t kPatchDoppler = 512;
inline constexpr std::size_t kPatchSize = kPatchRange * kPatchDoppler;
/// Features of g_M (sigmoid outputs) and inputs of g_c (features + belief).
inline constexpr std::size_t kNumFeatures = 8;
inline constexpr std::size_t kMlpInputs = kNumFeatures + 1;
/// The output of g_M: the features h_j of a detection.
using Features = std::array<float, kNumFeatures>;

/// Layer shapes (output channels, kernel height, kernel width).
inline constexpr std::size_t kConv1Out = 8, kConv1Kh = 3, kConv1Kw = 7;
inline constexpr std::size_t kConv2Out = 16, kConv2Kh = 3, kConv2Kw = 5;
inline constexpr std::size_t kConv3Out = 16, kConv3Kh = 3, kConv3Kw = 3;
inline constexpr std::size_t kFlat = kConv3Out * 1 * 8;  ///< 16 x 1 x 8 after conv3's 5x4 pool
inline constexpr std::size_t kFc1Out = 32, kFc2Out = 16, kFc3Out = kNumFeatures;
inline constexpr std::size_t kMlp1Out = 16, kMlp2Out = 8, kMlp3Out = 1;

/// Number of float parameters of the whole network (flash of the weights:
/// 4 bytes each).
inline constexpr std::size_t kNumParameters =
    kConv1Out * 1 * kConv1Kh * kConv1Kw + kConv1Out + kConv2Out * kConv1Out * kConv2Kh * kConv2Kw + kConv2Out +
    kConv3Out * kConv2Out * kConv3Kh * kConv3Kw + kConv3Out + kFc1Out * kFlat + kFc1Out + kFc2Out * kFc1Out +
    kFc2Out + kFc3Out * kFc2Out + kFc3Out + kMlp1Out * kMlpInputs + kMlp1Out + kMlp2Out * kMlp1Out + kMlp2Out +
    kMlp3Out * kMlp2Out + kMlp3Out;

/// Pointers to the weight arrays (sizes in the comments) and the input
/// normalisation x_n = (x - input_offset) * input_scale.
struct SeaClassifierWeights {
  const float* conv1_weight = nullptr;  ///< [8][1][3][7]
  const float* conv1_bias = nullptr;    ///< [8]
  const float* conv2_weight = nullptr;  ///< [16][8][3][5]
  const float* conv2_bias = nullptr;    ///< [16]
  const float* conv3_weight = nullptr;  ///< [16][16][3][3]
  const float* conv3_bias = nullptr;    ///< [16]
  const float* fc1_weight = nullptr;    ///< [32][128]
  const float* fc1_bias = nullptr;      ///< [32]
  const float* fc2_weight = nullptr;    ///< [16][32]
  const float* fc2_bias = nullptr;      ///< [16]
  const float* fc3_weight = nullptr;    ///< [8][16]
  const float* fc3_bias = nullptr;      ///< [8]
  const float* mlp1_weight = nullptr;   ///< [16][9]
  const float* mlp1_bias = nullptr;     ///< [16]
  const float* mlp2_weight = nullptr;   ///< [8][16]
  const float* mlp2_bias = nullptr;     ///< [8]
  const float* mlp3_weight = nullptr;   ///< [1][8]
  const float* mlp3_bias = nullptr;     ///< [1]
  float input_scale = 1.0f;
  float input_offset = 0.0f;
  /// Fraction of target patches in the training set (the prior the network's
  /// output carries; docs/algorithms/nemp.md §Fusion).
  float train_target_fraction = 0.5f;

  bool complete() const {
    const float* const p[] = {conv1_weight, conv1_bias, conv2_weight, conv2_bias, conv3_weight, conv3_bias,
                              fc1_weight,   fc1_bias,   fc2_weight,   fc2_bias,   fc3_weight,   fc3_bias,
                              mlp1_weight,  mlp1_bias,  mlp2_weight,  mlp2_bias,  mlp3_weight,  mlp3_bias};
    for (const float* q : p) {
      if (q == nullptr) return false;
    }
    return true;
  }
};

}  // namespace mptrack::classify
