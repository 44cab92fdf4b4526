// int8 inference of the patch classifier's CNN feature extractor g_M
// (docs/algorithms/nemp.md §int8 inference): the network of sea_classifier.h
// with int8 weights and uint8 activations, from the patch codes straight to
// the 8 sigmoid features. The MLP g_c (target_probability, 0.3 k MACs, once
// per NEMP round) stays in SeaClassifier's float: this class replaces only
// SeaClassifier::features(), 99.9 % of the MACs and 97 % of the weights.
//
// Integers up to the last layer, whose accumulator becomes a float logit by
// one multiplication before the deterministic sigmoid: the features have the
// same bits on every target. Allocation-free; scratch 12 800 B in the object
// (int16 centred input 5 120, conv1 map 5 120, conv2 map 2 560; 30 KiB for
// the float network).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "mptrack/classify/layers.h"
#include "mptrack/classify/layers_q8.h"
#include "mptrack/classify/sea_classifier_weights.h"
#include "mptrack/status.h"

namespace mptrack::classify {

/// The quantised g_M (generated/sea_features_q8_weights.h, written by
/// host-sim/train/quantise_classifier.py).
struct SeaFeaturesQ8Weights {
  QuantLayer conv1, conv2, conv3, fc1, fc2;
  const std::int8_t* fc3_weight = nullptr;   ///< [8][16]
  const std::int32_t* fc3_bias = nullptr;    ///< [8]
  const float* fc3_out_scale = nullptr;      ///< [8]: logit = acc * scale
  std::int32_t input_zero_point = 0;         ///< round(input_offset) of the float set

  bool complete() const {
    return conv1.complete() && conv2.complete() && conv3.complete() && fc1.complete() && fc2.complete() &&
           fc3_weight != nullptr && fc3_bias != nullptr && fc3_out_scale != nullptr;
  }
};

class SeaFeaturesQ8 {
 public:
  static constexpr std::size_t kW1 = kPatchDoppler / 4, kW2 = kW1 / 4, kW3 = kW2 / 4;
  static constexpr std::size_t kMap1 = kConv1Out * kPatchRange * kW1;  ///< 8x5x128
  static constexpr std::size_t kMap2 = kConv2Out * kPatchRange * kW2;  ///< 16x5x32
  /// Scratch: the centred input codes (int16), then conv1's and conv2's
  /// maps; conv3's, fc1's and fc2's outputs reuse the conv1 buffer.
  static constexpr std::size_t kScratchBytes = kPatchSize * sizeof(std::int16_t) + kMap1 + kMap2;
  /// Flash of the int8 weights, int32 biases, multipliers, shifts and fc3 scales.
  static constexpr std::size_t kWeightBytes =
      (kConv1Out * kConv1Kh * kConv1Kw + kConv2Out * kConv1Out * kConv2Kh * kConv2Kw +
       kConv3Out * kConv2Out * kConv3Kh * kConv3Kw + kFc1Out * kFlat + kFc2Out * kFc1Out + kFc3Out * kFc2Out) +
      (kConv1Out + kConv2Out + kConv3Out + kFc1Out + kFc2Out) * (2 * sizeof(std::int32_t) + 1) +
      kFc3Out * (sizeof(std::int32_t) + sizeof(float));
  static_assert(kFlat == kConv3Out * kW3, "flatten size");
  static_assert(kFlat + kFc1Out + kFc2Out <= kMap1, "dense outputs fit the conv1 buffer");

  /// Binds a weight set (kept by pointer). kInvalidArgument for a missing
  /// array, a shift outside [1, 62] or a zero point outside 0..255.
  [[nodiscard]] Status init(const SeaFeaturesQ8Weights& w) {
    ready_ = false;
    if (!w.complete() || w.input_zero_point < 0 || w.input_zero_point > 255) return Status::kInvalidArgument;
    if (!shifts_valid(w.conv1, kConv1Out) || !shifts_valid(w.conv2, kConv2Out) ||
        !shifts_valid(w.conv3, kConv3Out) || !shifts_valid(w.fc1, kFc1Out) || !shifts_valid(w.fc2, kFc2Out)) {
      return Status::kInvalidArgument;
    }
    w_ = w;
    ready_ = true;
    return Status::kOk;
  }

  bool ready() const { return ready_; }

  /// g_M of a patch of codes ([range][Doppler] row-major, kPatchSize values
  /// 0..255, as the detector writes them). kNotInitialized before init().
  [[nodiscard]] Status features(const std::uint8_t* codes, Features& out) {
    std::array<std::int32_t, kFc3Out> acc{};
    const Status s = logits(codes, acc);
    if (s != Status::kOk) return s;
    for (std::size_t o = 0; o < kFc3Out; ++o) out[o] = sigmoid(static_cast<float>(acc[o]) * w_.fc3_out_scale[o]);
    return Status::kOk;
  }

  /// The integer fc3 accumulators of a patch (features() before the float
  /// scale and sigmoid); for tests against the integer emulation.
  /// kNotInitialized before init().
  [[nodiscard]] Status logits(const std::uint8_t* codes, std::array<std::int32_t, kFc3Out>& acc) {
    if (!ready_) return Status::kNotInitialized;
    for (std::size_t i = 0; i < kPatchSize; ++i) {
      input_[i] = static_cast<std::int16_t>(static_cast<std::int32_t>(codes[i]) - w_.input_zero_point);
    }
    conv_relu_pool_q8<1, kPatchRange, kPatchDoppler, kConv1Out, kConv1Kh, kConv1Kw, 1, 4>(input_.data(), w_.conv1,
                                                                                          map1_.data());
    conv_relu_pool_q8<kConv1Out, kPatchRange, kW1, kConv2Out, kConv2Kh, kConv2Kw, 1, 4>(map1_.data(), w_.conv2,
                                                                                        map2_.data());
    std::uint8_t* flat = map1_.data();  // conv1's map is no longer needed
    conv_relu_pool_q8<kConv2Out, kPatchRange, kW2, kConv3Out, kConv3Kh, kConv3Kw, kPatchRange, 4>(
        map2_.data(), w_.conv3, flat);
    std::uint8_t* fc1 = flat + kFlat;
    std::uint8_t* fc2 = fc1 + kFc1Out;
    dense_relu_q8<kFlat, kFc1Out>(flat, w_.fc1, fc1);
    dense_relu_q8<kFc1Out, kFc2Out>(fc1, w_.fc2, fc2);
    dense_acc_q8<kFc2Out, kFc3Out>(fc2, w_.fc3_weight, w_.fc3_bias, acc.data());
    return Status::kOk;
  }

 private:
  static bool shifts_valid(const QuantLayer& l, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) {
      if (l.shift[i] < 1 || l.shift[i] > 62 || l.mult[i] < 0) return false;
    }
    return true;
  }

  SeaFeaturesQ8Weights w_{};
  bool ready_ = false;
  std::array<std::int16_t, kPatchSize> input_{};
  std::array<std::uint8_t, kMap1> map1_{};
  std::array<std::uint8_t, kMap2> map2_{};
};

}  // namespace mptrack::classify
