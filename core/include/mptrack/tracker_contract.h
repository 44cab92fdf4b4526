// The tracker contract: what every tracker in core provides, checked at
// compile time (C++17 detection idiom, no virtual calls, no concepts).
//
// Every tracker class X (MfbpTracker, GnnTracker, GmPhdFilter, GmCphdFilter,
// CbMemberFilter, and every tracker still to come) has
//
//   using Scalar, Params, ScanType, Estimate, OutputQueue;
//   static Status validate(const Params&, ParamError* where = nullptr);
//       checks every field against its documented range and against the
//       Caps the tracker was instantiated with; on failure names the field.
//   Status init(const Params&);     validate(), then reset every state
//   Status step(const ScanType&);   consume one scan
//   Status flush();                 end of data: finalise every held scan
//   const OutputQueue& outputs() const;
//   const TrackerCounters& counters() const;
//   const Params& params() const;
//
// and obeys these rules, which tests/unit/tracker_contract_test.cpp runs
// over every tracker (docs/architecture.md, "The tracker contract"):
//
// 1. Refused scans. step() refuses a scan whole when the tracker is not
//    initialised (kNotInitialized) or its time does not increase
//    (kOutOfOrder). A refused scan changes no tracker state, counts in
//    counters().scans_rejected, and leaves outputs() EMPTY: outputs()
//    always holds what the last call finalised, and a refused call
//    finalised nothing.
// 2. Losses are statuses. An accepted scan returns kOk, or kPartial when
//    measurements were rejected (measurements_invalid, _duplicate), or
//    kCapacityExceeded when a compile-time cap dropped anything (a track,
//    a clutter component, a gate pair, a measurement); kCapacityExceeded
//    takes precedence over kPartial. Every loss is counted in exactly one
//    counter; a cap hit never returns kOk.
// 3. Finalisation. Each accepted scan is finalised exactly once, in
//    order: by the step() that accepted it (online filters) or by a later
//    step() or flush() (window smoothers). outputs() of consecutive calls
//    together list every accepted scan's estimate once.
// 4. flush() returns kNotInitialized before init(); otherwise it
//    finalises every held scan; the tracker may then continue with later
//    scans (they start a new window).
//
// Optional: a tracker whose outputs() lag (a window smoother) may also have
//   bool has_provisional() const;  const Estimate& provisional() const;
// the estimate of the scan the last step() consumed, before it is final
// (MfbpTracker; docs/algorithms/mfbp.md §Provisional output).
// has_provisional_output_v<X> says whether X has them.
#pragma once

#include <cstdint>
#include <type_traits>
#include <utility>

#include "mptrack/status.h"
#include "mptrack/track_report.h"
#include "mptrack/validate.h"

namespace mptrack {
namespace contract_detail {

template <class X, class = void>
struct HasTypes : std::false_type {};
template <class X>
struct HasTypes<X, std::void_t<typename X::Scalar, typename X::Params, typename X::ScanType,
                               typename X::Estimate, typename X::OutputQueue>> : std::true_type {};

template <class X, class = void>
struct HasValidate : std::false_type {};
template <class X>
struct HasValidate<X, std::void_t<decltype(X::validate(std::declval<const typename X::Params&>(),
                                                       std::declval<ParamError*>()))>>
    : std::is_same<decltype(X::validate(std::declval<const typename X::Params&>(),
                                        std::declval<ParamError*>())),
                   Status> {};

template <class X, class = void>
struct HasInit : std::false_type {};
template <class X>
struct HasInit<X, std::void_t<decltype(std::declval<X&>().init(std::declval<const typename X::Params&>()))>>
    : std::is_same<decltype(std::declval<X&>().init(std::declval<const typename X::Params&>())), Status> {};

template <class X, class = void>
struct HasStep : std::false_type {};
template <class X>
struct HasStep<X, std::void_t<decltype(std::declval<X&>().step(std::declval<const typename X::ScanType&>()))>>
    : std::is_same<decltype(std::declval<X&>().step(std::declval<const typename X::ScanType&>())), Status> {};

template <class X, class = void>
struct HasFlush : std::false_type {};
template <class X>
struct HasFlush<X, std::void_t<decltype(std::declval<X&>().flush())>>
    : std::is_same<decltype(std::declval<X&>().flush()), Status> {};

template <class X, class = void>
struct HasOutputs : std::false_type {};
template <class X>
struct HasOutputs<X, std::void_t<decltype(std::declval<const X&>().outputs())>>
    : std::is_same<decltype(std::declval<const X&>().outputs()), const typename X::OutputQueue&> {};

template <class X, class = void>
struct HasCounters : std::false_type {};
template <class X>
struct HasCounters<X, std::void_t<decltype(std::declval<const X&>().counters())>>
    : std::is_same<decltype(std::declval<const X&>().counters()), const TrackerCounters&> {};

template <class X, class = void>
struct HasParams : std::false_type {};
template <class X>
struct HasParams<X, std::void_t<decltype(std::declval<const X&>().params())>>
    : std::is_same<decltype(std::declval<const X&>().params()), const typename X::Params&> {};

template <class X, class = void>
struct EstimatesMatch : std::false_type {};
template <class X>
struct EstimatesMatch<X, std::void_t<typename X::OutputQueue::value_type>>
    : std::is_same<typename X::OutputQueue::value_type, typename X::Estimate> {};

template <class X, class = void>
struct HasProvisional : std::false_type {};
template <class X>
struct HasProvisional<X, std::void_t<decltype(std::declval<const X&>().has_provisional()),
                                     decltype(std::declval<const X&>().provisional())>>
    : std::is_same<decltype(std::declval<const X&>().provisional()), const typename X::Estimate&> {};

}  // namespace contract_detail

/// Does tracker X hand out a provisional estimate (the optional members above)?
template <class X>
inline constexpr bool has_provisional_output_v = contract_detail::HasProvisional<X>::value;

/// Every compile-time cap counter of TrackerCounters: the sum rule 2 watches.
inline std::uint64_t total_cap_hits(const TrackerCounters& c) {
  return c.track_cap_hits + c.clutter_cap_hits + c.measurements_over_cap + c.association_cap_hits;
}

/// Rule 2 in one place: the status of an accepted step() or flush() whose
/// call began with total_cap_hits() == caps_before. kCapacityExceeded if
/// any cap counter moved, else kPartial if measurements were rejected,
/// else kOk.
inline Status accepted_status(const TrackerCounters& c, std::uint64_t caps_before, bool partial) {
  if (total_cap_hits(c) != caps_before) return Status::kCapacityExceeded;
  return partial ? Status::kPartial : Status::kOk;
}

/// True if X has every member of the contract with the documented types.
template <class X>
inline constexpr bool is_tracker_v = [] {
  using namespace contract_detail;
  if constexpr (!HasTypes<X>::value) {
    return false;
  } else {
    return HasValidate<X>::value && HasInit<X>::value && HasStep<X>::value && HasFlush<X>::value &&
           HasOutputs<X>::value && HasCounters<X>::value && HasParams<X>::value &&
           EstimatesMatch<X>::value;
  }
}();

/// For a static_assert in each tracker (placed in a member function body,
/// where the class is complete): one readable message per missing member.
template <class X>
constexpr bool tracker_contract_holds() {
  using namespace contract_detail;
  static_assert(HasTypes<X>::value,
                "tracker contract: needs Scalar, Params, ScanType, Estimate, OutputQueue");
  if constexpr (HasTypes<X>::value) {
    static_assert(HasValidate<X>::value,
                  "tracker contract: static Status validate(const Params&, ParamError*)");
    static_assert(HasInit<X>::value, "tracker contract: Status init(const Params&)");
    static_assert(HasStep<X>::value, "tracker contract: Status step(const ScanType&)");
    static_assert(HasFlush<X>::value, "tracker contract: Status flush()");
    static_assert(HasOutputs<X>::value, "tracker contract: const OutputQueue& outputs() const");
    static_assert(HasCounters<X>::value,
                  "tracker contract: const TrackerCounters& counters() const");
    static_assert(HasParams<X>::value, "tracker contract: const Params& params() const");
    static_assert(EstimatesMatch<X>::value, "tracker contract: OutputQueue holds Estimate");
  }
  return true;
}

}  // namespace mptrack
