// Differential tracker harness shared by the tracker fuzzers.
//
// Tracker `a` gets every decoded scan; its twin `b` gets only the scans `a`
// accepted. Rejected input must leave no trace (issue: "the tracker state
// after any rejected input is identical, bit for bit, to the state before
// it"), so after every accepted scan both must report identical bits. Also
// checked after every step: the status is one the tracker documents,
// reported numbers are finite, covariances SPD, and the counters add up
// (measurements_in = measurements of accepted scans, scans + rejected =
// steps), and the contract rules of tracker_contract.h (kCapacityExceeded
// exactly when a cap counter moved; a refused scan leaves outputs() empty).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "fuzz_common.h"
#include "mptrack/tracker_contract.h"

namespace mptrack::fuzz {

template <class Tracker>
bool is_rejection(Status s) {
  return s == Status::kOutOfOrder || s == Status::kNotInitialized;
}

template <class Tracker>
void check_outputs_identical(const Tracker& a, const Tracker& b) {
  FUZZ_CHECK(a.outputs().size() == b.outputs().size());
  for (std::size_t k = 0; k < a.outputs().size(); ++k) {
    check_estimate_sane(a.outputs()[k]);
    FUZZ_CHECK(estimates_identical(a.outputs()[k], b.outputs()[k]));
  }
}

/// Runs up to max_scans decoded scans through a and its twin b (both
/// already initialised with the same params).
template <class Tracker>
void run_twin(FuzzReader& in, const Region& reg, Tracker& a, Tracker& b, std::size_t max_scans,
              typename Tracker::ScanType& scan, typename Tracker::ScanType& prev) {
  std::uint64_t last_time = 1000000000u;
  std::uint64_t accepted_meas = 0;
  std::uint64_t steps = 0;
  std::uint64_t rejected = 0;
  prev.measurements.clear();
  const bool trace = std::getenv("MPTRACK_FUZZ_TRACE") != nullptr;
  for (std::size_t k = 0; k < max_scans && !in.empty(); ++k) {
    decode_scan(in, reg, prev, last_time, scan);
    if (trace) {  // MPTRACK_FUZZ_TRACE=1: print the decoded scans (for regression tests)
      std::fprintf(stderr, "scan %zu t=%llu doppler=%d n=%zu\n", k,
                   static_cast<unsigned long long>(scan.time_us), scan.has_doppler ? 1 : 0,
                   scan.measurements.size());
      for (const auto& m : scan.measurements) {
        std::fprintf(stderr, "  {%.9gf, %.9gf, %.9gf, %.9gf}\n", static_cast<double>(m.range_m),
                     static_cast<double>(m.azimuth_rad), static_cast<double>(m.amplitude),
                     static_cast<double>(m.doppler_mps));
      }
    }
    const std::uint64_t caps_before = total_cap_hits(a.counters());
    const Status sa = a.step(scan);
    ++steps;
    FUZZ_CHECK(sa == Status::kOk || sa == Status::kPartial || sa == Status::kOutOfOrder ||
               sa == Status::kCapacityExceeded);
    // tracker_contract.h rule 2: kCapacityExceeded exactly when a cap counter moved.
    FUZZ_CHECK((sa == Status::kCapacityExceeded) == (total_cap_hits(a.counters()) != caps_before));
    if (is_rejection<Tracker>(sa)) {
      ++rejected;
      FUZZ_CHECK(scan.time_us <= last_time);
      FUZZ_CHECK(a.outputs().empty());  // rule 1: a refused scan finalises nothing
    } else {
      accepted_meas += scan.measurements.size();
      const Status sb = b.step(scan);
      FUZZ_CHECK(sb == sa);
      check_outputs_identical(a, b);
      last_time = scan.time_us;
      prev = scan;
    }
    FUZZ_CHECK(a.counters().measurements_in == accepted_meas);
    FUZZ_CHECK(a.counters().measurements_invalid + a.counters().measurements_duplicate <=
               accepted_meas);
    FUZZ_CHECK(a.counters().scans + a.counters().scans_rejected == steps);
    FUZZ_CHECK(a.counters().scans_rejected == rejected);
  }
  const Status fa = a.flush();
  const Status fb = b.flush();
  FUZZ_CHECK(fa == fb);
  FUZZ_CHECK(fa == Status::kOk || fa == Status::kCapacityExceeded);
  check_outputs_identical(a, b);
}

}  // namespace mptrack::fuzz
