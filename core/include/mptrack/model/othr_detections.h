// The valid detections of one OTHR scan in slant units [km, km/s, rad],
// sorted by slant range for range-window searches (gating a track touches
// only the detections within its gate's range extent). Intake rule:
// inside the slant region and the range-rate span, finite, not an exact
// duplicate of an earlier detection of the scan (measurement.h); without
// Doppler the range rate is 0 (docs/algorithms/multipath.md §Measurements).
// Used by the multipath MF-BP tracker (docs/algorithms/multipath.md) and
// the multipath track fusion tracker (docs/algorithms/mptf.md §Online filter).
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
#include "mptrack/tracker_params.h"

namespace mptrack::model {

template <class T, std::size_t MaxMeasurements>
class OthrDetections {
 public:
  /// Takes the valid detections of scan; counts measurements_in,
  /// measurements_invalid and measurements_duplicate in c. Returns the
  /// number rejected (invalid + duplicate).
  std::size_t select(const Scan<T, MaxMeasurements>& scan, const PolarRegion<T>& region, T range_rate_span_mps,
                     TrackerCounters& c) {
    valid_.clear();
    std::size_t invalid = 0;
    std::size_t duplicate = 0;
    c.measurements_in += scan.measurements.size();
    MeasurementValidator<T> check = region.validator();
    check.check_doppler = scan.has_doppler;
    check.doppler_span_mps = range_rate_span_mps;
    for (std::size_t j = 0; j < scan.measurements.size(); ++j) {
      const Measurement<T>& m = scan.measurements[j];
      kept_[j] = false;
      if (!check.valid(m)) {
        ++invalid;
      } else if (is_duplicate(scan, j, [this](std::size_t i) { return kept_[i]; })) {
        ++duplicate;
      } else {
        kept_[j] = true;
        const std::size_t k = valid_.size();
        y_[k] << m.range_m * T(1e-3), scan.has_doppler ? m.doppler_mps * T(1e-3) : T(0), m.azimuth_rad;
        static_cast<void>(valid_.push_back(static_cast<std::uint16_t>(j)));  // scan capacity
      }
    }
    c.measurements_invalid += invalid;
    c.measurements_duplicate += duplicate;
    sort_by_range();
    return invalid + duplicate;
  }

  std::size_t size() const { return valid_.size(); }
  /// Valid detection j [km, km/s, rad].
  const OthrMeas<T>& y(std::size_t j) const { return y_[j]; }
  /// Index of valid detection j in the scan.
  std::size_t scan_index(std::size_t j) const { return valid_[j]; }
  /// The valid detection at position q of the slant-range order.
  std::size_t by_range(std::size_t q) const { return by_range_[q]; }

  /// First position in the slant-range order whose range is >= r_km (binary search).
  std::size_t first_at_or_above(T r_km) const {
    std::size_t lo = 0;
    std::size_t hi = valid_.size();
    while (lo < hi) {
      const std::size_t mid = lo + (hi - lo) / 2;
      if (y_[by_range_[mid]](0) < r_km) {
        lo = mid + 1;
      } else {
        hi = mid;
      }
    }
    return lo;
  }

 private:
  // Increasing slant range, index breaking ties: a total order, the same on every target.
  void sort_by_range() {
    const std::size_t n = valid_.size();
    for (std::size_t j = 0; j < n; ++j) by_range_[j] = static_cast<std::uint16_t>(j);
    std::sort(by_range_.begin(), by_range_.begin() + static_cast<std::ptrdiff_t>(n),
              [this](std::uint16_t a, std::uint16_t b) {
                return y_[a](0) < y_[b](0) || (!(y_[b](0) < y_[a](0)) && a < b);
              });
  }

  StaticVector<std::uint16_t, MaxMeasurements> valid_;  ///< scan index of each valid detection
  std::array<bool, MaxMeasurements> kept_{};
  std::array<OthrMeas<T>, MaxMeasurements> y_{};
  std::array<std::uint16_t, MaxMeasurements> by_range_{};
};

}  // namespace mptrack::model
