// Inference of the range-Doppler patch classifier of seed 003 (section
// III-D, Figs. 2-3) in the embedded size of docs/algorithms/nemp.md
// §Network:
//   patch 1x5x512 -> conv1 8@3x7 + ReLU + pool 1x4 -> 8x5x128
//                 -> conv2 16@3x5 + ReLU + pool 1x4 -> 16x5x32
//                 -> conv3 16@3x3 + ReLU + pool 5x4 -> 16x1x8 = 128
//                 -> fc 32 ReLU -> 16 ReLU -> 8 sigmoid   (features h_j, g_M)
//   [h_j, p_FG] -> 16 ReLU -> 8 ReLU -> 1 sigmoid          (w_j, g_c)
// features() runs once per detection and scan; target_probability() once
// per detection and NEMP round (seed 003 Algorithm 1 lines 15-24).
//
// Float only, allocation-free, bit-identical on every target (layers.h).
// Scratch: two ping-pong buffers of kPingFloats + kPongFloats floats in the
// object (30 KiB), see the comments at the members.
#pragma once

#include <array>
#include <cstddef>

#include "mptrack/classify/layers.h"
#include "mptrack/classify/sea_classifier_weights.h"
#include "mptrack/status.h"

namespace mptrack::classify {

class SeaClassifier {
 public:
  // Map sizes after each block.
  static constexpr std::size_t kW1 = kPatchDoppler / 4, kW2 = kW1 / 4, kW3 = kW2 / 4;
  static constexpr std::size_t kMap1 = kConv1Out * kPatchRange * kW1;  ///< 8x5x128
  static constexpr std::size_t kMap2 = kConv2Out * kPatchRange * kW2;  ///< 16x5x32
  static constexpr std::size_t kMap3 = kConv3Out * 1 * kW3;            ///< 16x1x8
  static_assert(kMap3 == kFlat, "flatten size");
  /// Ping: normalised patch, then conv2's output, then fc2's; pong: conv1's
  /// output, then conv3's and fc1's, fc3's.
  static constexpr std::size_t kPingFloats = kPatchSize > kMap2 ? kPatchSize : kMap2;
  static constexpr std::size_t kPongFloats = kMap1;
  static constexpr std::size_t kScratchBytes = (kPingFloats + kPongFloats) * sizeof(float);

  /// Multiply-accumulates per detection of features() and of one
  /// target_probability().
  static constexpr std::size_t kFeatureMacs =
      conv_macs<1, kPatchRange, kPatchDoppler, kConv1Out, kConv1Kh, kConv1Kw>() +
      conv_macs<kConv1Out, kPatchRange, kW1, kConv2Out, kConv2Kh, kConv2Kw>() +
      conv_macs<kConv2Out, kPatchRange, kW2, kConv3Out, kConv3Kh, kConv3Kw>() + kFlat * kFc1Out +
      kFc1Out * kFc2Out + kFc2Out * kFc3Out;
  static constexpr std::size_t kMlpMacs = kMlpInputs * kMlp1Out + kMlp1Out * kMlp2Out + kMlp2Out * kMlp3Out;

  /// Binds a weight set (kept by pointer: the arrays must outlive the
  /// classifier). kInvalidArgument for a missing array, a non-finite or zero
  /// input scale or a training target fraction outside (0, 1).
  [[nodiscard]] Status init(const SeaClassifierWeights& w) {
    ready_ = false;
    if (!w.complete()) return Status::kInvalidArgument;
    if (!(w.input_scale != 0.0f) || !(w.input_scale - w.input_scale == 0.0f)) return Status::kInvalidArgument;
    if (!(w.input_offset - w.input_offset == 0.0f)) return Status::kInvalidArgument;
    if (!(w.train_target_fraction > 0.0f && w.train_target_fraction < 1.0f)) return Status::kInvalidArgument;
    w_ = w;
    ready_ = true;
    return Status::kOk;
  }

  bool ready() const { return ready_; }
  const SeaClassifierWeights& weights() const { return w_; }

  /// g_M: the 8 features of a patch ([range][Doppler] row-major, kPatchSize
  /// values in 0..255). kNotInitialized before init(), kInvalidInput for a
  /// non-finite value (out is then left unchanged).
  [[nodiscard]] Status features(const float* patch, Features& out) {
    if (!ready_) return Status::kNotInitialized;
    for (std::size_t i = 0; i < kPatchSize; ++i) {
      const float x = patch[i];
      if (!(x - x == 0.0f)) return Status::kInvalidInput;
      ping_[i] = (x - w_.input_offset) * w_.input_scale;
    }
    conv_relu_pool<1, kPatchRange, kPatchDoppler, kConv1Out, kConv1Kh, kConv1Kw, 1, 4>(
        ping_.data(), w_.conv1_weight, w_.conv1_bias, pong_.data());
    conv_relu_pool<kConv1Out, kPatchRange, kW1, kConv2Out, kConv2Kh, kConv2Kw, 1, 4>(
        pong_.data(), w_.conv2_weight, w_.conv2_bias, ping_.data());
    conv_relu_pool<kConv2Out, kPatchRange, kW2, kConv3Out, kConv3Kh, kConv3Kw, kPatchRange, 4>(
        ping_.data(), w_.conv3_weight, w_.conv3_bias, pong_.data());
    // Flatten [c][h][w] is the layout conv_relu_pool writes: pong_[0..128).
    float* fc1 = pong_.data() + kFlat;
    dense<kFlat, kFc1Out, Activation::kRelu>(pong_.data(), w_.fc1_weight, w_.fc1_bias, fc1);
    dense<kFc1Out, kFc2Out, Activation::kRelu>(fc1, w_.fc2_weight, w_.fc2_bias, ping_.data());
    dense<kFc2Out, kFc3Out, Activation::kSigmoid>(ping_.data(), w_.fc3_weight, w_.fc3_bias, out.data());
    return Status::kOk;
  }

  /// g_c: w_j = P(detection is target-originated | features, belief), belief
  /// = the tracker's P(target-originated) p_FG (seed 003 Fig. 3; the polarity
  /// of docs/algorithms/nemp.md §Fusion). Requires ready().
  float target_probability(const Features& f, float belief) const {
    std::array<float, kMlpInputs> x{};
    for (std::size_t i = 0; i < kNumFeatures; ++i) x[i] = f[i];
    x[kNumFeatures] = belief;
    std::array<float, kMlp1Out> h1{};
    std::array<float, kMlp2Out> h2{};
    float y = 0.0f;
    dense<kMlpInputs, kMlp1Out, Activation::kRelu>(x.data(), w_.mlp1_weight, w_.mlp1_bias, h1.data());
    dense<kMlp1Out, kMlp2Out, Activation::kRelu>(h1.data(), w_.mlp2_weight, w_.mlp2_bias, h2.data());
    dense<kMlp2Out, kMlp3Out, Activation::kSigmoid>(h2.data(), w_.mlp3_weight, w_.mlp3_bias, &y);
    return y;
  }

 private:
  SeaClassifierWeights w_{};
  bool ready_ = false;
  std::array<float, kPingFloats> ping_{};
  std::array<float, kPongFloats> pong_{};
};

}  // namespace mptrack::classify
