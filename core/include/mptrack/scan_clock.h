// ScanClock: the scan-admission rule of the tracker contract (track_report.h),
// shared by every tracker so the rule is written once.
//
// A scan is refused whole, before any tracker state is touched, when the
// tracker is not initialised (kNotInitialized) or when its time does not
// increase strictly (kOutOfOrder); both count in
// TrackerCounters::scans_rejected. An admitted scan gets the time elapsed
// since the previous accepted scan; advance() records it as accepted.
#pragma once

#include <cstdint>

#include "mptrack/status.h"
#include "mptrack/track_report.h"

namespace mptrack {

class ScanClock {
 public:
  /// Forgets every scan: the next admitted scan is the first.
  void reset() {
    has_time_ = false;
    last_time_us_ = 0;
  }

  /// kOk if a scan at time_us may be processed; otherwise the refusal,
  /// counted in counters.scans_rejected. Does not advance the clock.
  Status admit(bool initialized, std::uint64_t time_us, TrackerCounters& counters) const {
    if (!initialized) {
      ++counters.scans_rejected;
      return Status::kNotInitialized;
    }
    if (has_time_ && !(time_us > last_time_us_)) {
      ++counters.scans_rejected;
      return Status::kOutOfOrder;
    }
    return Status::kOk;
  }

  /// Time since the previous accepted scan [s]; first_dt_s for the first scan.
  template <class T>
  T elapsed_s(std::uint64_t time_us, T first_dt_s) const {
    return has_time_ ? static_cast<T>(time_us - last_time_us_) * T(1e-6) : first_dt_s;
  }

  /// Records the scan at time_us as accepted.
  void advance(std::uint64_t time_us) {
    last_time_us_ = time_us;
    has_time_ = true;
  }

  bool has_time() const { return has_time_; }
  std::uint64_t last_time_us() const { return last_time_us_; }

 private:
  std::uint64_t last_time_us_ = 0;  ///< time of the last accepted scan [us]
  bool has_time_ = false;
};

}  // namespace mptrack
