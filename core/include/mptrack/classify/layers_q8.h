// int8 layers of the patch classifier's CNN g_M (docs/algorithms/nemp.md
// §int8 inference): the same "same"-padded convolution + ReLU + max-pool and
// dense layers as layers.h, in integers. Weights int8 (per output channel
// scale), activations uint8 (zero point 0, after ReLU), accumulators int32
// with the bias in accumulator units. Integer sums are exact in any order,
// so the bits are the same on every target without the float rules.
#pragma once

#include <cstddef>
#include <cstdint>

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

/// out[oc][ho][wo] = requantise(max(0, max over the Ph x Pw pool window of
/// b[oc] + sum w[oc][ic][kh][kw] x[ic][h+kh-Kh/2][w+kw-Kw/2])), x zero outside
/// the map (padding taps skipped). ReLU, pool and requantisation commute
/// (all monotone), so only the pooled accumulator is requantised.
/// In: int16_t (the centred input codes) or uint8_t (activations).
template <std::size_t Cin, std::size_t H, std::size_t W, std::size_t Cout, std::size_t Kh, std::size_t Kw,
          std::size_t Ph, std::size_t Pw, class In>
void conv_relu_pool_q8(const In* in, const QuantLayer& l, std::uint8_t* out) {
  static_assert(Kh % 2 == 1 && Kw % 2 == 1, "odd kernels for symmetric same padding");
  static_assert(H % Ph == 0 && W % Pw == 0, "pool windows tile the map");
  constexpr std::size_t kPadH = Kh / 2, kPadW = Kw / 2;
  constexpr std::size_t kHo = H / Ph, kWo = W / Pw;
  for (std::size_t oc = 0; oc < Cout; ++oc) {
    const std::int8_t* w_oc = l.weight + oc * Cin * Kh * Kw;
    for (std::size_t ho = 0; ho < kHo; ++ho) {
      for (std::size_t wo = 0; wo < kWo; ++wo) {
        std::int32_t best = 0;  // ReLU: the pooled value is at least 0
        for (std::size_t ph = 0; ph < Ph; ++ph) {
          const std::size_t h = ho * Ph + ph;
          const std::size_t kh0 = h < kPadH ? kPadH - h : 0;
          const std::size_t kh1 = h + Kh - kPadH > H ? H + kPadH - h : Kh;
          for (std::size_t pw = 0; pw < Pw; ++pw) {
            const std::size_t w = wo * Pw + pw;
            const std::size_t kw0 = w < kPadW ? kPadW - w : 0;
            const std::size_t kw1 = w + Kw - kPadW > W ? W + kPadW - w : Kw;
            std::int32_t acc = l.bias[oc];
            for (std::size_t ic = 0; ic < Cin; ++ic) {
              for (std::size_t kh = kh0; kh < kh1; ++kh) {
                const In* x_row = in + (ic * H + h + kh - kPadH) * W;
                const std::int8_t* w_row = w_oc + (ic * Kh + kh) * Kw;
                for (std::size_t kw = kw0; kw < kw1; ++kw) {
                  acc += static_cast<std::int32_t>(w_row[kw]) * static_cast<std::int32_t>(x_row[w + kw - kPadW]);
                }
              }
            }
            best = acc > best ? acc : best;
          }
        }
        out[(oc * kHo + ho) * kWo + wo] = requantise(best, l.mult[oc], l.shift[oc]);
      }
    }
  }
}

/// acc[o] = b[o] + sum_i w[o][i] x[i], w: [Out][In] (the last layer, whose
/// accumulator becomes a float logit).
template <std::size_t In, std::size_t Out>
void dense_acc_q8(const std::uint8_t* in, const std::int8_t* wgt, const std::int32_t* bias, std::int32_t* acc) {
  for (std::size_t o = 0; o < Out; ++o) {
    const std::int8_t* w_o = wgt + o * In;
    std::int32_t a = bias[o];
    for (std::size_t i = 0; i < In; ++i) a += static_cast<std::int32_t>(w_o[i]) * static_cast<std::int32_t>(in[i]);
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
