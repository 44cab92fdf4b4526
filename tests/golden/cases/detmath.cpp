// Golden case of the deterministic elementary functions
// (mptrack/math/detmath.h): every function in float and double on fixed
// grids of about 200 arguments (two grids of 100, plus its special values).
// The grid is built with + - * / only (linear steps and geometric ladders by
// repeated multiplication), so it is bit-identical everywhere too. Each
// line's label carries the argument's bits: "dexp_f@3f800000 f32 ...".
#include <limits>

#include "golden_cases.h"
#include "mptrack/math/detmath.h"

namespace mptrack::test {

namespace dm = mptrack::dmath;

namespace {

constexpr int kGrid = 100;
constexpr int kSpecials = 13;

/// A grid of arguments (fixed capacity: kGrid points plus the specials).
template <class T>
struct Grid {
  T v[kGrid + kSpecials];
  int n = 0;
  void push(T x) { v[n++] = x; }
};

/// kGrid points from lo to hi, evenly spaced in double, then rounded to T.
template <class T>
Grid<T> linear(double lo, double hi) {
  Grid<T> xs;
  for (int i = 0; i < kGrid; ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(kGrid - 1);
    xs.push(static_cast<T>(lo + (hi - lo) * t));
  }
  return xs;
}

/// kGrid points from lo, each `ratio` times the previous (computed in double,
/// so rounding to float happens once per point).
template <class T>
Grid<T> ladder(double lo, double ratio) {
  Grid<T> xs;
  double x = lo;
  for (int i = 0; i < kGrid; ++i) {
    xs.push(static_cast<T>(x));
    x *= ratio;
  }
  return xs;
}

template <class T>
Grid<T> specials() {
  using L = std::numeric_limits<T>;
  const T inf = L::infinity();
  const T s[kSpecials] = {T(0), -T(0), T(1), T(-1), T(2), T(0.5), L::denorm_min(), L::min(), L::max(),
                          -L::max(), inf, -inf, L::quiet_NaN()};
  Grid<T> g;
  for (const T x : s) g.push(x);
  return g;
}

template <class T>
const char* suffix() {
  return sizeof(T) == sizeof(float) ? "_f" : "_d";
}

template <class T, class F>
void record(GoldenSink& g, const char* name, F f, Grid<T> xs) {
  const Grid<T> sp = specials<T>();
  for (int i = 0; i < sp.n; ++i) xs.push(sp.v[i]);
  const Label prefix = Label(name) + suffix<T>() + "@";
  for (int i = 0; i < xs.n; ++i) g.add(prefix.bits(xs.v[i]), f(xs.v[i]));
}

template <class T>
void record_all(GoldenSink& g) {
  const bool f32 = sizeof(T) == sizeof(float);
  record<T>(g, "dexp", [](T x) { return dm::dexp(x); }, linear<T>(f32 ? -110.0 : -760.0, f32 ? 95.0 : 720.0));
  record<T>(g, "dexp", [](T x) { return dm::dexp(x); }, linear<T>(-2.0, 2.0));
  record<T>(g, "dexpm1", [](T x) { return dm::dexpm1(x); }, linear<T>(-45.0, 45.0));
  record<T>(g, "dexpm1", [](T x) { return dm::dexpm1(x); }, ladder<T>(1e-12, 1.32));
  record<T>(g, "dlog", [](T x) { return dm::dlog(x); }, ladder<T>(f32 ? 1e-44 : 1e-320, f32 ? 6.8 : 2.0e6));
  record<T>(g, "dlog", [](T x) { return dm::dlog(x); }, linear<T>(0.25, 4.0));
  record<T>(g, "dlog1p", [](T x) { return dm::dlog1p(x); }, linear<T>(-0.999, 3.0));
  record<T>(g, "dlog1p", [](T x) { return dm::dlog1p(x); }, ladder<T>(1e-10, 1.44));
  record<T>(g, "dsin", [](T x) { return dm::dsin(x); }, linear<T>(-20.0, 20.0));
  record<T>(g, "dsin", [](T x) { return dm::dsin(x); }, linear<T>(-1.0e5, 1.0e5));
  record<T>(g, "dcos", [](T x) { return dm::dcos(x); }, linear<T>(-20.0, 20.0));
  record<T>(g, "dcos", [](T x) { return dm::dcos(x); }, linear<T>(-1.0e5, 1.0e5));
  // Neighbours of k pi/2, where the exact float reduction path runs.
  Grid<T> near_pio2;
  for (int k = 1; k <= kGrid; ++k) {
    near_pio2.push(static_cast<T>(static_cast<double>(k * 317) * 1.5707963267948966));
  }
  record<T>(g, "dsin", [](T x) { return dm::dsin(x); }, near_pio2);
  record<T>(g, "dcos", [](T x) { return dm::dcos(x); }, near_pio2);
  record<T>(g, "dsincos_s", [](T x) { T s; T c; dm::dsincos(x, s, c); return s; }, linear<T>(-7.0, 7.0));
  record<T>(g, "dsincos_c", [](T x) { T s; T c; dm::dsincos(x, s, c); return c; }, linear<T>(-7.0, 7.0));
  record<T>(g, "datan", [](T x) { return dm::datan(x); }, linear<T>(-30.0, 30.0));
  record<T>(g, "datan", [](T x) { return dm::datan(x); }, ladder<T>(1e-8, 1.44));
  // datan2 on points of a 2D grid covering the four quadrants and both axes.
  {
    const Label prefix = Label("datan2") + suffix<T>() + "@";
    for (int i = 0; i < kGrid; ++i) {
      const T y = static_cast<T>(-5.0 + 10.0 * static_cast<double>(i % 10) / 9.0);
      const T x = static_cast<T>(-5.0 + 10.0 * static_cast<double>(i / 10) / 9.0);
      g.add((prefix.bits(y) + ",").bits(x), dm::datan2(y, x));
    }
    const Grid<T> sp = specials<T>();
    for (int i = 0; i < sp.n; ++i) {
      for (int j = 0; j < sp.n; ++j) g.add((prefix.bits(sp.v[i]) + ",").bits(sp.v[j]), dm::datan2(sp.v[i], sp.v[j]));
    }
  }
  record<T>(g, "dlgamma", [](T x) { return dm::dlgamma(x); }, linear<T>(0.001, 12.0));
  record<T>(g, "dlgamma", [](T x) { return dm::dlgamma(x); }, ladder<T>(1e-7, 1.35));
  record<T>(g, "ddigamma", [](T x) { return dm::ddigamma(x); }, linear<T>(0.001, 12.0));
  record<T>(g, "ddigamma", [](T x) { return dm::ddigamma(x); }, ladder<T>(1e-7, 1.35));
  record<T>(g, "derf", [](T x) { return dm::derf(x); }, linear<T>(-6.0, 6.0));
  record<T>(g, "derfc", [](T x) { return dm::derfc(x); }, linear<T>(-6.0, f32 ? 10.5 : 28.0));
}

}  // namespace

void golden_case_detmath(GoldenSink& g) {
  record_all<float>(g);
  record_all<double>(g);
}

}  // namespace mptrack::test
