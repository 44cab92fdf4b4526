// Angle conventions between the radar front end and the trackers.
//
// Seed 004 eq. (1) measures the bearing theta_b from the boresight (+y)
// axis towards +x, theta_b = atan2(x, y), so x = r sin(theta_b) and
// y = r cos(theta_b). Measurement::azimuth_rad (seed 000) is the usual
// mathematical angle, counter-clockwise from +x: phi = atan2(y, x).
// For the same point, phi = pi/2 - theta_b (exact identity; wrapped into
// (-pi, pi]). Front-end detections lie in |theta_b| < pi/2, i.e. phi in (0, pi).
#pragma once

#include "mptrack/math/constants.h"

namespace mptrack::frontend {

/// Bearing from boresight (+y towards +x) [rad] -> azimuth CCW from +x [rad].
template <class T>
T bearing_to_azimuth(T bearing_rad) {
  T phi = mptrack::dmath::kHalfPi<T> - bearing_rad;
  if (phi > mptrack::dmath::kPi<T>) phi -= mptrack::dmath::kTwoPi<T>;
  if (!(phi > -mptrack::dmath::kPi<T>)) phi += mptrack::dmath::kTwoPi<T>;
  return phi;
}

/// Azimuth CCW from +x [rad] -> bearing from boresight (+y towards +x) [rad].
template <class T>
T azimuth_to_bearing(T azimuth_rad) {
  T th = mptrack::dmath::kHalfPi<T> - azimuth_rad;
  if (th > mptrack::dmath::kPi<T>) th -= mptrack::dmath::kTwoPi<T>;
  if (!(th > -mptrack::dmath::kPi<T>)) th += mptrack::dmath::kTwoPi<T>;
  return th;
}

}  // namespace mptrack::frontend
