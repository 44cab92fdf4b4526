// A plain complex scalar for the raw-signal models (model/mimo_atom.h, vmp/):
// written as real operations so the operation order is fixed and no libgcc
// helper (__mulsc3, __divsc3, which std::complex operator* and / may call for
// their NaN/Inf handling) is reached from core. Same reason as in dsp/fft.h.
#pragma once

namespace mptrack::model {

template <class T>
struct Cx {
  T re = T(0);
  T im = T(0);
};

template <class T>
inline Cx<T> cx_add(Cx<T> a, Cx<T> b) { return {a.re + b.re, a.im + b.im}; }
template <class T>
inline Cx<T> cx_sub(Cx<T> a, Cx<T> b) { return {a.re - b.re, a.im - b.im}; }
/// a b.
template <class T>
inline Cx<T> cx_mul(Cx<T> a, Cx<T> b) { return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re}; }
/// conj(a) b.
template <class T>
inline Cx<T> cx_cmul(Cx<T> a, Cx<T> b) { return {a.re * b.re + a.im * b.im, a.re * b.im - a.im * b.re}; }
template <class T>
inline Cx<T> cx_scale(Cx<T> a, T s) { return {a.re * s, a.im * s}; }
template <class T>
inline Cx<T> cx_conj(Cx<T> a) { return {a.re, -a.im}; }
/// |a|^2.
template <class T>
inline T cx_norm2(Cx<T> a) { return a.re * a.re + a.im * a.im; }

}  // namespace mptrack::model
