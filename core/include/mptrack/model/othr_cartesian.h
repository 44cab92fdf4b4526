// The OTHR ground state in the report frame of track_report.h: Cartesian
// [x m, vx m/s, y m, vy m/s] with x = g cos theta, y = g sin theta (g in km
// scaled to m; receiver at the origin), and its covariance J P J^T through
// the Jacobian J of that map (docs/algorithms/multipath.md §Track management
// and reporting; docs/algorithms/mptf.md §Reports).
#pragma once

#include <Eigen/Core>

#include "mptrack/math/detmath.h"
#include "mptrack/model/othr_measurement.h"

namespace mptrack::model {

template <class T>
void othr_ground_to_cartesian(const OthrState<T>& x, const Eigen::Matrix<T, 4, 4>& P, Eigen::Matrix<T, 4, 1>& xc,
                              Eigen::Matrix<T, 4, 4>& Pc) {
  T s;
  T c;
  dmath::dsincos(x(2), s, c);
  const T k = T(1000);  // km -> m
  const T g = x(0), gd = x(1), td = x(3);
  xc << k * g * c, k * (gd * c - g * td * s), k * g * s, k * (gd * s + g * td * c);
  Eigen::Matrix<T, 4, 4> J;
  J << k * c, T(0), -k * g * s, T(0),                               //
      -k * td * s, k * c, -k * (gd * s + g * td * c), -k * g * s,  //
      k * s, T(0), k * g * c, T(0),                                 //
      k * td * c, k * s, k * (gd * c - g * td * s), k * g * c;
  const Eigen::Matrix<T, 4, 4> JP = J * P;
  Pc = JP * J.transpose();
}

}  // namespace mptrack::model
