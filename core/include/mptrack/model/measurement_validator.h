// The one measurement validator of every tracker's intake: which detections
// a tracker accepts (the rest are counted in
// TrackerCounters::measurements_invalid and the step returns kPartial).
//
// A measurement is valid when
//  - range [m] and azimuth [rad] are finite;
//  - its position (c0, c1) lies inside the region [min0, max0] x [min1, max1],
//    bounds included. The position is (range m, azimuth rad) for a polar
//    tracker, or (x m, y m) after conversion for a Cartesian one;
//  - by the amplitude rule (normalised envelope, measurement.h):
//      kIgnored:     not looked at (the tracker does not use amplitude);
//      kPositive:    finite and > 0 (amplitude carried, not modelled);
//      kThresholded: finite, > threshold d and <= max_amplitude: the
//                    detector only reports amplitudes above d, and values
//                    past max_amplitude overflow the amplitude moments in
//                    float (docs/reliability.md F4). At exactly d the
//                    truncated amplitude densities vanish, so d itself is
//                    rejected (the stricter of the earlier copies);
//  - when Doppler is used: doppler_mps finite and within +- doppler_span_mps.
// Exact duplicates are a separate rule (measurement.h, is_duplicate).
#pragma once

#include <cstdint>

#include "mptrack/measurement.h"
#include "mptrack/validate.h"

namespace mptrack::model {

enum class AmplitudeRule : std::uint8_t { kIgnored, kPositive, kThresholded };

template <class T>
struct MeasurementValidator {
  T min0 = T(0);  ///< region, first coordinate: range [m] or x [m]
  T max0 = T(0);
  T min1 = T(0);  ///< region, second coordinate: azimuth [rad] or y [m]
  T max1 = T(0);
  AmplitudeRule amplitude = AmplitudeRule::kIgnored;
  T threshold = T(0);      ///< amplitude threshold d [-] (kThresholded)
  T max_amplitude = T(0);  ///< amplitude ceiling [-] (kThresholded)
  bool check_doppler = false;
  T doppler_span_mps = T(0);  ///< |doppler_mps| bound [m/s] (check_doppler)

  /// Everything but the region: finite position, amplitude rule, Doppler.
  bool values_valid(const Measurement<T>& m) const {
    if (!is_finite(m.range_m) || !is_finite(m.azimuth_rad)) return false;
    if (amplitude != AmplitudeRule::kIgnored) {
      if (!is_finite(m.amplitude) || !(m.amplitude > T(0))) return false;
      if (amplitude == AmplitudeRule::kThresholded &&
          (!(m.amplitude > threshold) || m.amplitude > max_amplitude)) {
        return false;
      }
    }
    if (check_doppler) {
      if (!is_finite(m.doppler_mps) || m.doppler_mps > doppler_span_mps ||
          m.doppler_mps < -doppler_span_mps) {
        return false;
      }
    }
    return true;
  }

  /// (c0, c1) inside the region, bounds included (NaN is outside).
  bool inside(T c0, T c1) const {
    return c0 >= min0 && c0 <= max0 && c1 >= min1 && c1 <= max1;
  }

  /// values_valid and inside at (range, azimuth): the polar trackers' test.
  bool valid(const Measurement<T>& m) const {
    return values_valid(m) && inside(m.range_m, m.azimuth_rad);
  }
};

}  // namespace mptrack::model
