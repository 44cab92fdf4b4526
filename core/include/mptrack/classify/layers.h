// The layers of the patch classifier (docs/algorithms/nemp.md §Network):
// a "same"-padded convolution fused with its bias, ReLU and max-pool, and a
// dense layer. Every sum runs in one fixed order (input channel, kernel row,
// kernel column; input index for dense), starting from +0 and adding the
// bias last, so with -ffp-contract=off the result has the same bits on
// every target. Zero-padding taps are skipped: adding w * 0 = +-0 to a sum
// that starts at +0 never changes it.
#pragma once

#include <cstddef>

#include "mptrack/math/detmath.h"

namespace mptrack::classify {

/// The loop nest shared by the float and the int8 convolution (layers_q8.h):
/// out[oc][ho][wo] = L::store(max(0, max over the Ph x Pw pool window of
/// L::finish(sum, oc))), the sum starting at L::start(oc) and adding
/// L::mul(w[oc][ic][kh][kw], x[ic][h+kh-Kh/2][w+kw-Kw/2]) in the order
/// (ic, kh, kw) over the taps inside the map ("same" padding: zero taps are
/// skipped). in: [Cin][H][W], out: [Cout][H/Ph][W/Pw]; the pre-pool map is
/// never stored.
template <std::size_t Cin, std::size_t H, std::size_t W, std::size_t Cout, std::size_t Kh, std::size_t Kw,
          std::size_t Ph, std::size_t Pw, class L, class In, class Wt, class Out>
void conv_pool_loops(const In* in, const Wt* wgt, const L& layer, Out* out) {
  static_assert(Kh % 2 == 1 && Kw % 2 == 1, "odd kernels for symmetric same padding");
  static_assert(H % Ph == 0 && W % Pw == 0, "pool windows tile the map");
  using Acc = typename L::Acc;
  constexpr std::size_t kPadH = Kh / 2, kPadW = Kw / 2;
  constexpr std::size_t kHo = H / Ph, kWo = W / Pw;
  for (std::size_t oc = 0; oc < Cout; ++oc) {
    const Wt* w_oc = wgt + oc * Cin * Kh * Kw;
    for (std::size_t ho = 0; ho < kHo; ++ho) {
      for (std::size_t wo = 0; wo < kWo; ++wo) {
        Acc best = Acc(0);  // ReLU outputs are >= +0, so max starts at +0
        for (std::size_t ph = 0; ph < Ph; ++ph) {
          const std::size_t h = ho * Ph + ph;
          const std::size_t kh0 = h < kPadH ? kPadH - h : 0;
          const std::size_t kh1 = h + Kh - kPadH > H ? H + kPadH - h : Kh;
          for (std::size_t pw = 0; pw < Pw; ++pw) {
            const std::size_t w = wo * Pw + pw;
            const std::size_t kw0 = w < kPadW ? kPadW - w : 0;
            const std::size_t kw1 = w + Kw - kPadW > W ? W + kPadW - w : Kw;
            Acc acc = layer.start(oc);
            for (std::size_t ic = 0; ic < Cin; ++ic) {
              const In* x_ic = in + ic * H * W;
              const Wt* w_ic = w_oc + ic * Kh * Kw;
              for (std::size_t kh = kh0; kh < kh1; ++kh) {
                // Indexed from the row start: w + kw - kPadW >= 0 for kw >= kw0. A
                // row pointer offset by (w - kPadW) would point before the array at
                // the left edge, which is undefined (clang's UBSan reports it).
                const In* x_row = x_ic + (h + kh - kPadH) * W;
                const Wt* w_row = w_ic + kh * Kw;
                for (std::size_t kw = kw0; kw < kw1; ++kw) acc += L::mul(w_row[kw], x_row[w + kw - kPadW]);
              }
            }
            const Acc v = layer.finish(acc, oc);
            best = v > best ? v : best;
          }
        }
        out[(oc * kHo + ho) * kWo + wo] = layer.store(best, oc);
      }
    }
  }
}

/// The float layer of conv_pool_loops: the sum starts at +0 and the bias is
/// added last, so with -ffp-contract=off the result has the same bits on
/// every target.
struct FloatConvLayer {
  using Acc = float;
  const float* bias;
  static float mul(float w, float x) { return w * x; }
  static float start(std::size_t /*oc*/) { return 0.0f; }
  float finish(float acc, std::size_t oc) const { return acc + bias[oc]; }
  static float store(float best, std::size_t /*oc*/) { return best; }
};

/// out[oc][ho][wo] = max over the Ph x Pw pool window of
/// ReLU(b[oc] + sum_{ic,kh,kw} w[oc][ic][kh][kw] x[ic][h+kh-Kh/2][w+kw-Kw/2]),
/// x zero outside [0,H) x [0,W). in: [Cin][H][W], out: [Cout][H/Ph][W/Pw].
template <std::size_t Cin, std::size_t H, std::size_t W, std::size_t Cout, std::size_t Kh, std::size_t Kw,
          std::size_t Ph, std::size_t Pw>
void conv_relu_pool(const float* in, const float* wgt, const float* bias, float* out) {
  conv_pool_loops<Cin, H, W, Cout, Kh, Kw, Ph, Pw>(in, wgt, FloatConvLayer{bias}, out);
}

enum class Activation { kRelu, kSigmoid };

/// Logistic function with the deterministic exp (mptrack/math/exp_log.h).
inline float sigmoid(float x) { return 1.0f / (1.0f + dmath::dexp(-x)); }

/// out[o] = act(b[o] + sum_i w[o][i] x[i]), w: [Out][In].
template <std::size_t In, std::size_t Out, Activation A>
void dense(const float* in, const float* wgt, const float* bias, float* out) {
  for (std::size_t o = 0; o < Out; ++o) {
    const float* w_o = wgt + o * In;
    float acc = 0.0f;
    for (std::size_t i = 0; i < In; ++i) acc += w_o[i] * in[i];
    const float v = acc + bias[o];
    if constexpr (A == Activation::kRelu) {
      out[o] = v > 0.0f ? v : 0.0f;
    } else {
      out[o] = sigmoid(v);
    }
  }
}

/// Multiply-accumulates of one conv_relu_pool / dense call (zero-padding
/// taps not counted).
template <std::size_t Cin, std::size_t H, std::size_t W, std::size_t Cout, std::size_t Kh, std::size_t Kw>
constexpr std::size_t conv_macs() {
  std::size_t rows = 0, cols = 0;
  for (std::size_t h = 0; h < H; ++h) {
    for (std::size_t k = 0; k < Kh; ++k) rows += (h + k >= Kh / 2 && h + k < H + Kh / 2) ? 1 : 0;
  }
  for (std::size_t w = 0; w < W; ++w) {
    for (std::size_t k = 0; k < Kw; ++k) cols += (w + k >= Kw / 2 && w + k < W + Kw / 2) ? 1 : 0;
  }
  return Cout * Cin * rows * cols;
}

}  // namespace mptrack::classify
