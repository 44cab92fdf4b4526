// The detections one scan of the multipath tracker works on
// (docs/algorithms/multipath.md §Measurements): the valid ones (inside the
// region and the range-rate span, finite, not an exact duplicate) as
// [slant range km, range rate km/s, azimuth rad], and their order in slant
// range, which gating searches and births sweep.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

#include "mptrack/measurement.h"
#include "mptrack/model/measurement_validator.h"
#include "mptrack/model/othr_measurement.h"
#include "mptrack/static_vector.h"
#include "mptrack/track_report.h"

namespace mptrack::multipath {

template <class T, std::size_t MaxMeasurements>
struct DetectionIntake {
  StaticVector<std::uint16_t, MaxMeasurements> valid;       ///< scan index of each valid detection
  std::array<bool, MaxMeasurements> kept{};
  std::array<model::OthrMeas<T>, MaxMeasurements> y{};     ///< valid detections [km, km/s, rad]
  std::array<std::uint16_t, MaxMeasurements> by_range{};  ///< valid indices in increasing slant range

  /// Keeps the valid detections of `scan` (counting measurements_in,
  /// _invalid and _duplicate) and sorts them; returns how many were skipped.
  template <class Scan>
  std::size_t select(const Scan& scan, model::MeasurementValidator<T> check, TrackerCounters& counters) {
    valid.clear();
    std::size_t invalid = 0;
    std::size_t duplicate = 0;
    counters.measurements_in += scan.measurements.size();
    check.check_doppler = scan.has_doppler;
    for (std::size_t j = 0; j < scan.measurements.size(); ++j) {
      const Measurement<T>& m = scan.measurements[j];
      kept[j] = false;
      if (!check.valid(m)) {
        ++invalid;
      } else if (is_duplicate(scan, j, [this](std::size_t i) { return kept[i]; })) {
        ++duplicate;
      } else {
        kept[j] = true;
        const std::size_t k = valid.size();
        y[k] << m.range_m * T(1e-3), scan.has_doppler ? m.doppler_mps * T(1e-3) : T(0), m.azimuth_rad;
        static_cast<void>(valid.push_back(static_cast<std::uint16_t>(j)));  // scan capacity
      }
    }
    counters.measurements_invalid += invalid;
    counters.measurements_duplicate += duplicate;
    sort_by_range();
    return invalid + duplicate;
  }

  /// First position in by_range whose slant range is >= r_km (binary search).
  std::size_t first_at_or_above(T r_km) const {
    std::size_t lo = 0;
    std::size_t hi = valid.size();
    while (lo < hi) {
      const std::size_t mid = lo + (hi - lo) / 2;
      if (y[by_range[mid]](0) < r_km) {
        lo = mid + 1;
      } else {
        hi = mid;
      }
    }
    return lo;
  }

 private:
  // Index breaks ties: a total order, the same on every target.
  void sort_by_range() {
    const std::size_t n = valid.size();
    for (std::size_t j = 0; j < n; ++j) by_range[j] = static_cast<std::uint16_t>(j);
    std::sort(by_range.begin(), by_range.begin() + static_cast<std::ptrdiff_t>(n),
              [this](std::uint16_t a, std::uint16_t b) { return y[a](0) < y[b](0) || (!(y[b](0) < y[a](0)) && a < b); });
  }
};

}  // namespace mptrack::multipath
