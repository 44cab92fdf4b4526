// Deterministic elementary functions for mptrack (umbrella header).
//
// Every function here returns the same bits for the same input on x86-64
// (SSE2), aarch64, armhf (VFPv4) and Cortex-M7 (fpv5-d16), provided the code
// is built with mptrack::deterministic (-ffp-contract=off, never fast-math flags).
// That is what lets host-sim, the qemu legs and the board share golden files.
// How it is achieved:
// - only + - * / and sqrt (all correctly rounded by IEEE 754), comparisons,
//   integer operations and bit manipulation through std::memcpy; no libm
//   transcendental call, no long double, no FMA (contraction is off), no
//   table whose content depends on the platform;
// - polynomials are evaluated in a fixed order (Horner) with coefficients
//   written as hexadecimal literals; float paths use float arithmetic only,
//   with their own shorter float-minimax coefficient sets;
// - NaN results are produced explicitly with one fixed payload (x86 and Arm
//   would otherwise disagree on the sign of a default NaN).
//
// API (namespace mptrack::dmath, T = float or double; others are rejected by
// static_assert; "d" for deterministic, which also keeps these names apart
// from <cmath>):
//   dexp dexpm1 dlog dlog1p          exp_log.h
//   dsin dcos dsincos datan datan2   trig.h
//   dlgamma ddigamma (x > 0)         gamma.h
//   derf derfc                       erf.h
//   kPi<T>, kHalfPi<T>, kLn2<T>, kEulerGamma<T>, ...   constants.h
//
// Accuracy: maximum error in ulps of the result, measured by
// tests/unit/detmath_accuracy_test.cpp against the x86-64 long double libm
// (64-bit significand; digamma against a long double series) on dense
// jittered sweeps (2^17 points per sweep and type, several sweeps per
// function). The test asserts the "bound" column.
//
//   function  domain swept                      float   double   bound
//   dexp      [-87, 88] / [-708, 709]           0.65    0.70     1
//   dexpm1    [-87, 88] / [-708, 709], tiny x   1.07    1.09     1.5
//   dlog      [denorm_min, max]                 0.81    0.79     1
//   dlog1p    (-0.99, 1e6], tiny x              0.79    0.78     1
//   dsin      |x| <= 1e5                        0.76    0.77     1
//   dcos      |x| <= 1e5                        0.77    0.75     1
//   datan     all x                             0.96    0.90     1.5
//   datan2    all quadrants, |y/x| 1e-30..1e30  1.43    1.34     2
//   dlgamma   [1e-6, 1e6]                       1.37    1.29     2
//   ddigamma  [1e-6, 1e6]                       1.28    1.19     2
//   derf      [-10, 10]                         0.78    0.84     1
//   derfc     [-10, 9.1] / [-10, 26.5]          1.14    1.19     1.5
//
// - Exhaustive float checks (every float of the domain, same reference):
//   dexp 0.68 and dexpm1 1.11 on [-87.3, 88.7]; dlog 0.84 on [denorm_min,
//   max]; dlog1p 0.84 on [-0.999999, max]; dsin 0.80 and dcos 0.81 on
//   |x| <= 102943 (2.4e9 values each).
// - Near the zeros of lgamma (x = 1, 2) and digamma (x0 = 1.4616...) both
//   zeros are built into the formulas, so the relative error stays small
//   there too (lgamma <= 0.92 ulp for 1e-16 <= |x - zero| <= 0.1 against
//   lgammal; digamma <= 0.57 ulp against 40-digit mpmath). The test measures
//   the windows |x - zero| < 1/16 in absolute error (0.02 ulp of 1 measured,
//   bound 0.5) because its digamma reference cancels there.
// - dsin/dcos: full accuracy up to kTrigMaxArg<T> (2^16 pi/2 ~ 1.0e5 float,
//   2^20 pi/2 ~ 1.6e6 double); beyond it, and for +-inf, the result is NaN.
//   The float reduction is exact (integer fallback next to multiples of pi/2).
// - derfc is subnormal beyond 9.19 (float) / 26.5 (double): there only the
//   absolute error (< 1 subnormal ulp) is meaningful.
//
// Special values (NaN in -> NaN out everywhere): see each function's comment.
#pragma once

#include "mptrack/math/constants.h"
#include "mptrack/math/erf.h"
#include "mptrack/math/exp_log.h"
#include "mptrack/math/gamma.h"
#include "mptrack/math/trig.h"
