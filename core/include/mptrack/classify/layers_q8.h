// int8 layers of the patch classifier's CNN g_M (docs/algorithms/nemp.md
// §int8 inference): the same "same"-padded convolution + ReLU + max-pool and
// dense layers as layers.h, in integers. Weights int8 (per output channel
// scale), activations uint8 (zero point 0, after ReLU), accumulators int32
// with the bias in accumulator units. Integer sums are exact in any order,
// so the bits are the same on every target without the float rules.
#pragma once

#include <cstddef>
#include <cstdint>

#include "mptrack/classify/layers.h"

namespace mptrack::classify {

/// One quantised layer: weights [out][in...] as the float layout, biases
/// and the fixed-point requantisation m / 2^s = s_x s_w / s_y per output.
struct QuantLayer {
  const std::int8_t* weight = nullptr;
  const std::int32_t* bias = nullptr;
  const std::int32_t* mult = nullptr;  ///< m in [2^30, 2^31)
  const std::uint8_t* shift = nullptr;  ///< s in [1, 62]

  bool complete() const { return weight != nullptr && bias != nullptr && mult != nullptr && shift != nullptr; }
};

/// uint8 activation of a non-negative accumulator: min(255, round(acc m / 2^s)),
/// halves rounded up. |acc| < 2^31 and m < 2^31, so the product fits int64.
inline std::uint8_t requantise(std::int32_t acc, std::int32_t mult, std::uint8_t shift) {
  const std::int64_t half = std::int64_t{1} << (shift - 1);
  const std::int64_t y = (static_cast<std::int64_t>(acc) * mult + half) >> shift;
  return static_cast<std::uint8_t>(y > 255 ? 255 : y);
}

/// The int8 layer of conv_pool_loops (layers.h): the sum starts at the
/// bias, ReLU and max-pool act on the accumulator, and only the pooled value
/// is requantised (all three are monotone, so they commute).
struct QuantConvLayer {
  using Acc = std::int32_t;
  const QuantLayer& l;
  template <class In>
  static std::int32_t mul(std::int8_t w, In x) {
    return static_cast<std::int32_t>(w) * static_cast<std::int32_t>(x);
  }
  std::int32_t start(std::size_t oc) const { return l.bias[oc]; }
  static std::int32_t finish(std::int32_t acc, std::size_t /*oc*/) { return acc; }
  std::uint8_t store(std::int32_t best, std::size_t oc) const { return requantise(best, l.mult[oc], l.shift[oc]); }
};

/// out[oc][ho][wo] = requantise(max(0, max over the Ph x Pw pool window of
/// b[oc] + sum w[oc][ic][kh][kw] x[ic][h+kh-Kh/2][w+kw-Kw/2])), x zero outside
/// the map. In: int16_t (the centred input codes) or uint8_t (activations).
template <std::size_t Cin, std::size_t H, std::size_t W, std::size_t Cout, std::size_t Kh, std::size_t Kw,
          std::size_t Ph, std::size_t Pw, class In>
void conv_relu_pool_q8(const In* in, const QuantLayer& l, std::uint8_t* out) {
  conv_pool_loops<Cin, H, W, Cout, Kh, Kw, Ph, Pw>(in, l.weight, QuantConvLayer{l}, out);
}

/// acc[o] = b[o] + sum_i w[o][i] x[i], w: [Out][In] (the last layer, whose
/// accumulator becomes a float logit).
template <std::size_t In, std::size_t Out>
void dense_acc_q8(const std::uint8_t* in, const std::int8_t* wgt, const std::int32_t* bias, std::int32_t* acc) {
  for (std::size_t o = 0; o < Out; ++o) {
    const std::int8_t* w_o = wgt + o * In;
    std::int32_t a = bias[o];
    for (std::size_t i = 0; i < In; ++i) a += QuantConvLayer::mul(w_o[i], in[i]);
    acc[o] = a;
  }
}

/// out[o] = requantise(max(0, acc[o])): a hidden dense layer with ReLU.
template <std::size_t In, std::size_t Out>
void dense_relu_q8(const std::uint8_t* in, const QuantLayer& l, std::uint8_t* out) {
  for (std::size_t o = 0; o < Out; ++o) {
    std::int32_t a = 0;
    dense_acc_q8<In, 1>(in, l.weight + o * In, l.bias + o, &a);
    out[o] = requantise(a > 0 ? a : 0, l.mult[o], l.shift[o]);
  }
}

}  // namespace mptrack::classify
