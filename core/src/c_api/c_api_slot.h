// The C API's tracker slot (include/mptrack/c/mptrack_c.h): one C++ tracker
// and its scan buffer, constructed in the caller's memory, behind the
// opaque mptrack_tracker handle. Every tracker of the C API is a Slot<X>
// for a class X of the tracker contract (tracker_contract.h); the generic
// calls (mptrack_step, mptrack_output, ...) dispatch through a table of
// plain function pointers (no virtual functions, no RTTI).
#pragma once

#include <cstddef>
#include <cstdint>
#include <new>

#include "mptrack/c/mptrack_c.h"
#include "mptrack/measurement.h"
#include "mptrack/status.h"
#include "mptrack/track_report.h"
#include "mptrack/tracker_contract.h"
#include "mptrack/validate.h"

namespace mptrack::capi {

struct Ops {
  mptrack_status (*step)(mptrack_tracker*, const mptrack_scan*);
  mptrack_status (*flush)(mptrack_tracker*);
  std::size_t (*num_outputs)(const mptrack_tracker*);
  mptrack_status (*output)(const mptrack_tracker*, std::size_t, mptrack_output_info*, mptrack_track*,
                           std::size_t, std::size_t*);
  /// The provisional estimate (tracker_contract.h, optional): as output, for
  /// the one estimate; MPTRACK_INVALID_ARGUMENT when there is none.
  mptrack_status (*provisional)(const mptrack_tracker*, mptrack_output_info*, mptrack_track*, std::size_t,
                                std::size_t*);
  const TrackerCounters& (*counters)(const mptrack_tracker*);
  void (*destroy)(mptrack_tracker*);
  std::size_t max_detections;
  std::size_t max_tracks;
};

inline mptrack_status to_c(Status s) { return static_cast<mptrack_status>(s); }

}  // namespace mptrack::capi

/// The handle: first base of every Slot<X>.
struct mptrack_tracker {
  const mptrack::capi::Ops* ops = nullptr;
  std::uint64_t scans_over_detection_cap = 0;  ///< refused by mptrack_step before the tracker
  bool outputs_valid = false;  ///< false after such a refusal: outputs() are the previous call's
};

namespace mptrack::capi {

template <class X>
struct Slot : mptrack_tracker {
  X tracker;
  typename X::ScanType scan;
};

/// Detections per scan and tracks per finalised scan of tracker X.
template <class X>
inline constexpr std::size_t kMaxDetections = decltype(X::ScanType::measurements)::capacity();
template <class X>
inline constexpr std::size_t kMaxTracks = decltype(X::Estimate::tracks)::capacity();

template <class X>
Slot<X>* slot_of(mptrack_tracker* t) {
  return static_cast<Slot<X>*>(t);
}
template <class X>
const Slot<X>* slot_of(const mptrack_tracker* t) {
  return static_cast<const Slot<X>*>(t);
}

/// Copies a C scan into the slot's scan buffer and steps the tracker. More
/// detections than the buffer holds: refused whole (mptrack_c.h).
template <class X>
mptrack_status slot_step(mptrack_tracker* t, const mptrack_scan* in) {
  Slot<X>* s = slot_of<X>(t);
  if (in->num_detections > kMaxDetections<X>) {
    ++s->scans_over_detection_cap;
    s->outputs_valid = false;
    return MPTRACK_CAPACITY_EXCEEDED;
  }
  s->scan.time_us = in->time_us;
  s->scan.has_doppler = in->has_doppler != 0;
  s->scan.measurements.clear();
  for (std::size_t j = 0; j < in->num_detections; ++j) {
    const mptrack_detection& d = in->detections[j];
    Measurement<typename X::Scalar> m;
    m.range_m = d.range_m;
    m.azimuth_rad = d.azimuth_rad;
    m.amplitude = d.amplitude;
    m.doppler_mps = d.doppler_mps;
    static_cast<void>(s->scan.measurements.push_back(m));  // fits: checked above
  }
  s->outputs_valid = true;
  return to_c(s->tracker.step(s->scan));
}

template <class X>
mptrack_status slot_flush(mptrack_tracker* t) {
  Slot<X>* s = slot_of<X>(t);
  s->outputs_valid = true;
  return to_c(s->tracker.flush());
}

template <class X>
std::size_t slot_num_outputs(const mptrack_tracker* t) {
  const Slot<X>* s = slot_of<X>(t);
  return s->outputs_valid ? s->tracker.outputs().size() : 0u;
}

template <class T>
void copy_track(const TrackReport<T>& r, mptrack_track& o) {
  o.id = r.id;
  for (int i = 0; i < 4; ++i) {
    o.state[i] = r.state(i);
    for (int j = 0; j < 4; ++j) o.covariance[4 * i + j] = r.covariance(i, j);
  }
  o.existence = r.existence;
  o.snr = r.snr;
  o.confirmed = r.confirmed ? 1 : 0;
  o.measurement_index = r.measurement_index;
}

/// Estimate e: its info and up to `capacity` tracks (count: nullptr = info only).
template <class Estimate>
mptrack_status copy_estimate(const Estimate& e, mptrack_output_info* info, mptrack_track* tracks,
                             std::size_t capacity, std::size_t* count) {
  if (info != nullptr) {
    info->time_us = e.time_us;
    info->scan_index = e.scan_index;
    info->num_tracks = e.tracks.size();
  }
  if (count == nullptr) return MPTRACK_OK;
  std::size_t n = 0;
  for (; n < e.tracks.size() && n < capacity; ++n) copy_track(e.tracks[n], tracks[n]);
  *count = n;
  return n < e.tracks.size() ? MPTRACK_CAPACITY_EXCEEDED : MPTRACK_OK;
}

/// Output `k` of the last call: its info and up to `capacity` tracks.
template <class X>
mptrack_status slot_output(const mptrack_tracker* t, std::size_t k, mptrack_output_info* info,
                           mptrack_track* tracks, std::size_t capacity, std::size_t* count) {
  if (k >= slot_num_outputs<X>(t)) return MPTRACK_INVALID_ARGUMENT;
  return copy_estimate(slot_of<X>(t)->tracker.outputs()[k], info, tracks, capacity, count);
}

/// The provisional estimate of the last step(), if X has one and the step
/// was not refused by mptrack_step.
template <class X>
mptrack_status slot_provisional(const mptrack_tracker* t, mptrack_output_info* info, mptrack_track* tracks,
                                std::size_t capacity, std::size_t* count) {
  if constexpr (has_provisional_output_v<X>) {
    const Slot<X>* s = slot_of<X>(t);
    if (!s->outputs_valid || !s->tracker.has_provisional()) return MPTRACK_INVALID_ARGUMENT;
    return copy_estimate(s->tracker.provisional(), info, tracks, capacity, count);
  } else {
    static_cast<void>(t), static_cast<void>(info), static_cast<void>(tracks), static_cast<void>(capacity),
        static_cast<void>(count);
    return MPTRACK_INVALID_ARGUMENT;
  }
}

template <class X>
const TrackerCounters& slot_counters(const mptrack_tracker* t) {
  return slot_of<X>(t)->tracker.counters();
}

template <class X>
void slot_destroy(mptrack_tracker* t) {
  slot_of<X>(t)->~Slot<X>();
  // A fresh, empty handle in its place: later calls see ops == nullptr
  // (a store to the dying slot itself could be dropped as dead).
  ::new (static_cast<void*>(t)) mptrack_tracker{};
}

template <class X>
inline constexpr Ops kOps = {&slot_step<X>,        &slot_flush<X>,    &slot_num_outputs<X>,
                             &slot_output<X>,      &slot_provisional<X>,
                             &slot_counters<X>,    &slot_destroy<X>,
                             kMaxDetections<X>,    kMaxTracks<X>};

/// mptrack_<tracker>_init: checks the memory block and the params (naming
/// the refused field), then constructs Slot<X> in the block and inits it.
template <class X>
mptrack_status slot_init(void* memory, std::size_t size, const typename X::Params& params,
                         mptrack_tracker** out, mptrack_param_error* error) {
  static_assert(tracker_contract_holds<X>());
  if (out == nullptr) return MPTRACK_INVALID_ARGUMENT;
  *out = nullptr;
  if (memory == nullptr || size < sizeof(Slot<X>) ||
      reinterpret_cast<std::uintptr_t>(memory) % alignof(Slot<X>) != 0u) {
    return MPTRACK_INVALID_ARGUMENT;
  }
  ParamError where;
  const Status valid = X::validate(params, &where);
  if (valid != Status::kOk) {
    if (error != nullptr) {
      error->field = where.field;
      error->rule = where.rule;
    }
    return to_c(valid);
  }
  // Placement construction in the caller's storage: no allocation (the nm
  // checks c_api_library_no_heap / m7_c_api_no_heap find no operator new).
  Slot<X>* s = ::new (memory) Slot<X>;
  s->ops = &kOps<X>;
  s->scans_over_detection_cap = 0;
  s->outputs_valid = false;
  const Status st = s->tracker.init(params);
  if (st != Status::kOk) {
    slot_destroy<X>(s);
    return to_c(st);
  }
  *out = s;
  return MPTRACK_OK;
}

/// A C region / noise block as the C++ one (tracker_params.h).
template <class Region>
void region_from_c(const mptrack_polar_region& c, Region& r) {
  r.range_min_m = c.range_min_m;
  r.range_max_m = c.range_max_m;
  r.azimuth_min_rad = c.azimuth_min_rad;
  r.azimuth_max_rad = c.azimuth_max_rad;
}
template <class Region>
void region_to_c(const Region& r, mptrack_polar_region& c) {
  c.range_min_m = r.range_min_m;
  c.range_max_m = r.range_max_m;
  c.azimuth_min_rad = r.azimuth_min_rad;
  c.azimuth_max_rad = r.azimuth_max_rad;
}
template <class Noise>
void noise_from_c(const mptrack_polar_noise& c, Noise& n) {
  n.range_std_m = c.range_std_m;
  n.azimuth_std_rad = c.azimuth_std_rad;
  n.doppler_std_mps = c.doppler_std_mps;
}
template <class Noise>
void noise_to_c(const Noise& n, mptrack_polar_noise& c) {
  c.range_std_m = n.range_std_m;
  c.azimuth_std_rad = n.azimuth_std_rad;
  c.doppler_std_mps = n.doppler_std_mps;
}

}  // namespace mptrack::capi
