// Over-the-horizon radar (OTHR) measurement model over ionospheric paths
// (seed 002 Sec. IV-A, eq. (57); docs/algorithms/multipath.md §OTHR geometry).
//
// State (ground coordinates): x = [g km, g_dot km/s, theta rad, theta_dot rad/s],
// ground range g from the receiver and bearing theta from the axis
// perpendicular to the baseline; the transmitter is d km from the receiver
// along the baseline (quasi-monostatic). Measurement (slant coordinates):
// y = [r km, r_dot km/s, zeta rad].
//
// A path reflects its transmit leg at virtual height h_t and its receive
// leg at h_r (flat-earth mirror at each leg's midpoint). With
//   r_a = sqrt(g^2/4 + h_r^2)                            (receive leg, half)
//   r_b = sqrt((g^2 - 2 d g sin theta + d^2)/4 + h_t^2)   (transmit leg, half)
// eq. (57) gives
//   r     = r_a + r_b,
//   r_dot = g_dot/4 (g/r_a + (g - d sin theta)/r_b),  (theta_dot terms dropped)
//   zeta  = asin(g sin theta / (2 r_a)).
// The azimuth depends on h_r only; with h_t = h_r = d = 0, h(x) = [g, g_dot, theta].
// The Jacobian below is the analytic derivative of these three functions
// (docs/algorithms/multipath.md §OTHR geometry); the inverse map (slant to
// ground for one path) is a 2-D Newton iteration, used by births.
// Only dmath is used for transcendental functions (fixed bits on every target).
#pragma once

#include <cstddef>

#include <Eigen/Core>

#include "mptrack/math/detmath.h"

namespace mptrack::model {

template <class T>
using OthrState = Eigen::Matrix<T, 4, 1>;
template <class T>
using OthrMeas = Eigen::Matrix<T, 3, 1>;
template <class T>
using OthrJacobian = Eigen::Matrix<T, 3, 4>;

/// One propagation path: the virtual reflection heights of its two legs [km].
template <class T>
struct OthrPath {
  T tx_height_km = T(0);  ///< transmit leg (h_t)
  T rx_height_km = T(0);  ///< receive leg (h_r); the azimuth depends on it alone
};

namespace othr_detail {

/// The two half-leg lengths and the intermediate terms h and H share.
template <class T>
struct Legs {
  T s = T(0), c = T(0);    ///< sin theta, cos theta
  T ra = T(0), rb = T(0);  ///< receive and transmit half-legs [km]
  T gb = T(0);             ///< g - d sin theta [km]
};

template <class T>
Legs<T> legs(const OthrState<T>& x, const OthrPath<T>& p, T baseline_km) {
  Legs<T> l;
  dmath::dsincos(x(2), l.s, l.c);
  const T g = x(0);
  const T d = baseline_km;
  l.ra = std::sqrt(g * g / T(4) + p.rx_height_km * p.rx_height_km);
  l.rb = std::sqrt((g * g - T(2) * d * g * l.s + d * d) / T(4) + p.tx_height_km * p.tx_height_km);
  l.gb = g - d * l.s;
  return l;
}

/// asin(u) for |u| < 1 through atan2 (dmath has no asin).
template <class T>
T asin_of(T u) {
  const T w2 = T(1) - u * u;
  return dmath::datan2(u, std::sqrt(w2 > T(0) ? w2 : T(0)));
}

}  // namespace othr_detail

/// h^tau(x) of seed 002 eq. (57): [slant range km, slant range rate km/s, azimuth rad].
template <class T>
OthrMeas<T> othr_measure(const OthrState<T>& x, const OthrPath<T>& path, T baseline_km) {
  const othr_detail::Legs<T> l = othr_detail::legs(x, path, baseline_km);
  OthrMeas<T> y;
  y(0) = l.ra + l.rb;
  y(1) = x(1) / T(4) * (x(0) / l.ra + l.gb / l.rb);
  y(2) = othr_detail::asin_of(x(0) * l.s / (T(2) * l.ra));
  return y;
}

/// h^tau(x) and its Jacobian H = dh/dx (columns g, g_dot, theta, theta_dot).
/// Derivation: d r_a/d g = g/(4 r_a), d r_b/d g = (g - d s)/(4 r_b),
/// d r_b/d theta = -d g c/(4 r_b); r_dot = g_dot dr/dg; zeta = asin(u) with
/// u = g s/(2 r_a), du/dg = s h_r^2/(2 r_a^3), du/dtheta = g c/(2 r_a).
template <class T>
void othr_linearize(const OthrState<T>& x, const OthrPath<T>& path, T baseline_km, OthrMeas<T>& y,
                    OthrJacobian<T>& H) {
  const othr_detail::Legs<T> l = othr_detail::legs(x, path, baseline_km);
  const T g = x(0);
  const T gd = x(1);
  const T d = baseline_km;
  const T hr2 = path.rx_height_km * path.rx_height_km;
  const T ht2 = path.tx_height_km * path.tx_height_km;
  const T ra3 = l.ra * l.ra * l.ra;
  const T rb3 = l.rb * l.rb * l.rb;
  const T dr_dg = g / (T(4) * l.ra) + l.gb / (T(4) * l.rb);
  const T dr_dth = -d * g * l.c / (T(4) * l.rb);
  const T u = g * l.s / (T(2) * l.ra);
  const T w2 = T(1) - u * u;
  const T w = std::sqrt(w2 > T(0) ? w2 : T(0));
  y(0) = l.ra + l.rb;
  y(1) = gd * dr_dg;
  y(2) = dmath::datan2(u, w);
  H.setZero();
  H(0, 0) = dr_dg;
  H(0, 2) = dr_dth;
  // d/dg of (g/r_a) = h_r^2/r_a^3; d/dg of (g_b/r_b) = (d^2 c^2 + 4 h_t^2)/(4 r_b^3).
  H(1, 0) = gd / T(4) * (hr2 / ra3 + (d * d * l.c * l.c + T(4) * ht2) / (T(4) * rb3));
  H(1, 1) = dr_dg;
  H(1, 2) = gd / T(4) * (-d * l.c / l.rb + l.gb * d * g * l.c / (T(4) * rb3));
  H(2, 0) = l.s * hr2 / (T(2) * ra3 * w);
  H(2, 2) = g * l.c / (T(2) * l.ra * w);
}

/// Slant to ground for one path: solves h^tau(g, theta) = (r, zeta) by 2-D
/// Newton from g = r, theta = zeta (r_a + r_b ~ g when the heights and d are
/// small against g), then g_dot from r_dot (linear in g_dot); theta_dot = 0.
/// Returns false if an iterate leaves g > 0 or the Newton matrix is singular.
template <class T>
bool othr_invert(const OthrMeas<T>& y, const OthrPath<T>& path, T baseline_km, OthrState<T>& x,
                 std::size_t iterations = 6) {
  x << y(0), T(0), y(2), T(0);
  OthrMeas<T> z;
  OthrJacobian<T> H;
  for (std::size_t it = 0; it < iterations; ++it) {
    othr_linearize(x, path, baseline_km, z, H);
    const T a = H(0, 0), b = H(0, 2), c = H(2, 0), e = H(2, 2);
    const T det = a * e - b * c;
    if (!(det > T(0) || det < T(0))) return false;
    const T f0 = y(0) - z(0);
    const T f2 = y(2) - z(2);
    x(0) += (e * f0 - b * f2) / det;
    x(2) += (a * f2 - c * f0) / det;
    if (!(x(0) > T(0))) return false;
  }
  othr_linearize(x, path, baseline_km, z, H);
  if (!(H(1, 1) > T(0))) return false;
  x(1) = y(1) / H(1, 1);
  return true;
}

}  // namespace mptrack::model
