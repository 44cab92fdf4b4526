// Measurements and scans: what a detector (CFAR + peak extraction) hands
// to a tracker. Seed 000 spec section 1.4: Y_j = (y_j, m_j), y = (r, theta).
#pragma once

#include <cstddef>
#include <cstdint>

#include "mptrack/static_vector.h"

namespace mptrack {

/// One detection in polar measurement space.
template <class T>
struct Measurement {
  T range_m = T(0);       ///< slant range [m]
  T azimuth_rad = T(0);   ///< azimuth [rad], counter-clockwise from the +x axis
  T amplitude = T(0);     ///< normalised envelope m = |z| / sqrt(N0) (m^2 is SNR-like power) [-]
  T doppler_mps = T(0);   ///< radial velocity [m/s]; only meaningful if the scan has_doppler
};

/// One scan: a timestamp and up to MaxMeasurements detections.
template <class T, std::size_t MaxMeasurements>
struct Scan {
  std::uint64_t time_us = 0;   ///< scan time [us], strictly increasing across scans
  bool has_doppler = false;    ///< true if doppler_mps is filled in for every measurement
  StaticVector<Measurement<T>, MaxMeasurements> measurements;
};

}  // namespace mptrack
