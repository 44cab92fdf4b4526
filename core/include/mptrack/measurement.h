// Measurements and scans: what a detector (CFAR + peak extraction) hands
// to a tracker. docs/algorithms/README.md §Notation and units: Y_j = (y_j, m_j),
// y = (r, theta).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

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

/// The bit pattern of x as an unsigned integer of the same size.
template <class T>
auto bits_of(T x) {
  static_assert(sizeof(T) == 4 || sizeof(T) == 8, "float or double");
  using U = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
  U u;
  std::memcpy(&u, &x, sizeof u);
  return u;
}

/// True if a and b have the same range and azimuth bit patterns (a
/// bitwise test: -0 and +0 differ, equal NaNs match, no rounding).
template <class T>
bool same_position(const Measurement<T>& a, const Measurement<T>& b) {
  return bits_of(a.range_m) == bits_of(b.range_m) && bits_of(a.azimuth_rad) == bits_of(b.azimuth_rad);
}

/// Duplicate rule shared by every tracker's intake (docs/reliability.md
/// F11): measurement j of a scan is an exact duplicate if an earlier
/// measurement i < j that the tracker kept (kept(i) == true) has the same
/// range and azimuth bits. The first copy is kept, later ones are dropped
/// and counted in TrackerCounters::measurements_duplicate; the step then
/// returns kPartial. A real detector never reports one cell twice, so two
/// copies are a front-end or transport fault, and kept they would make two
/// tracks of one target. Cost: j bit compares (O(n^2) per scan, about 25 us
/// at 225 measurements on the development machine).
/// @param[in] scan  the scan
/// @param[in] j     index of the measurement to test
/// @param[in] kept  callable bool(std::size_t i) for i < j: was i kept
template <class T, std::size_t N, class Kept>
bool is_duplicate(const Scan<T, N>& scan, std::size_t j, const Kept& kept) {
  const Measurement<T>& m = scan.measurements[j];
  for (std::size_t i = 0; i < j; ++i) {
    if (kept(i) && same_position(scan.measurements[i], m)) return true;
  }
  return false;
}

}  // namespace mptrack
