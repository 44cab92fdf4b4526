// The tracker-independent calls of the C API (mptrack_c.h): they check the
// handle and dispatch to the tracker's Slot<X> (c_api_slot.h).
#include "mptrack/c/mptrack_c.h"

#include "c_api_slot.h"
#include "mptrack/status.h"

namespace {
using mptrack::Status;
// The C enum carries mptrack::Status's values, so conversions are casts.
static_assert(MPTRACK_OK == static_cast<int>(Status::kOk));
static_assert(MPTRACK_INVALID_ARGUMENT == static_cast<int>(Status::kInvalidArgument));
static_assert(MPTRACK_INVALID_INPUT == static_cast<int>(Status::kInvalidInput));
static_assert(MPTRACK_CAPACITY_EXCEEDED == static_cast<int>(Status::kCapacityExceeded));
static_assert(MPTRACK_OUT_OF_ORDER == static_cast<int>(Status::kOutOfOrder));
static_assert(MPTRACK_NUMERICAL_ERROR == static_cast<int>(Status::kNumericalError));
static_assert(MPTRACK_NOT_INITIALIZED == static_cast<int>(Status::kNotInitialized));
static_assert(MPTRACK_BUFFER_FULL == static_cast<int>(Status::kBufferFull));
static_assert(MPTRACK_BUFFER_EMPTY == static_cast<int>(Status::kBufferEmpty));
static_assert(MPTRACK_PARTIAL == static_cast<int>(Status::kPartial));
static_assert(sizeof(mptrack_counters) == (mptrack::kTrackerCounterFields + 1) * sizeof(std::uint64_t),
              "mptrack_counters lists every TrackerCounters field (track_report.h)");

bool live(const mptrack_tracker* t) { return t != nullptr && t->ops != nullptr; }
}  // namespace

extern "C" {

const char* mptrack_status_string(mptrack_status status) {
  const int v = static_cast<int>(status);
  if (v < MPTRACK_OK || v > MPTRACK_PARTIAL) return "unknown";
  return mptrack::to_string(static_cast<Status>(v));
}

mptrack_status mptrack_step(mptrack_tracker* tracker, const mptrack_scan* scan) {
  if (!live(tracker)) return MPTRACK_NOT_INITIALIZED;
  if (scan == nullptr || (scan->num_detections > 0u && scan->detections == nullptr)) {
    return MPTRACK_INVALID_ARGUMENT;
  }
  return tracker->ops->step(tracker, scan);
}

mptrack_status mptrack_flush(mptrack_tracker* tracker) {
  if (!live(tracker)) return MPTRACK_NOT_INITIALIZED;
  return tracker->ops->flush(tracker);
}

size_t mptrack_num_outputs(const mptrack_tracker* tracker) {
  return live(tracker) ? tracker->ops->num_outputs(tracker) : 0u;
}

mptrack_status mptrack_output(const mptrack_tracker* tracker, size_t output, mptrack_output_info* info) {
  if (!live(tracker)) return MPTRACK_NOT_INITIALIZED;
  if (info == nullptr) return MPTRACK_INVALID_ARGUMENT;
  return tracker->ops->output(tracker, output, info, nullptr, 0u, nullptr);
}

mptrack_status mptrack_output_tracks(const mptrack_tracker* tracker, size_t output, mptrack_track* tracks,
                                     size_t capacity, size_t* count) {
  if (!live(tracker)) return MPTRACK_NOT_INITIALIZED;
  if (count == nullptr || (capacity > 0u && tracks == nullptr)) return MPTRACK_INVALID_ARGUMENT;
  *count = 0;
  return tracker->ops->output(tracker, output, nullptr, tracks, capacity, count);
}

mptrack_status mptrack_provisional(const mptrack_tracker* tracker, mptrack_output_info* info, mptrack_track* tracks,
                                   size_t capacity, size_t* count) {
  if (!live(tracker)) return MPTRACK_NOT_INITIALIZED;
  if (info == nullptr || count == nullptr || (capacity > 0u && tracks == nullptr)) return MPTRACK_INVALID_ARGUMENT;
  *count = 0;
  return tracker->ops->provisional(tracker, info, tracks, capacity, count);
}

mptrack_status mptrack_get_counters(const mptrack_tracker* tracker, mptrack_counters* counters) {
  if (!live(tracker)) return MPTRACK_NOT_INITIALIZED;
  if (counters == nullptr) return MPTRACK_INVALID_ARGUMENT;
  const mptrack::TrackerCounters& c = tracker->ops->counters(tracker);
  counters->scans = c.scans;
  counters->scans_rejected = c.scans_rejected;
  counters->measurements_in = c.measurements_in;
  counters->measurements_invalid = c.measurements_invalid;
  counters->measurements_over_cap = c.measurements_over_cap;
  counters->tracks_born = c.tracks_born;
  counters->tracks_confirmed = c.tracks_confirmed;
  counters->tracks_deleted = c.tracks_deleted;
  counters->track_cap_hits = c.track_cap_hits;
  counters->clutter_born = c.clutter_born;
  counters->clutter_deleted = c.clutter_deleted;
  counters->clutter_cap_hits = c.clutter_cap_hits;
  counters->bp_not_converged = c.bp_not_converged;
  counters->numerical_repairs = c.numerical_repairs;
  counters->gap_resets = c.gap_resets;
  counters->measurements_duplicate = c.measurements_duplicate;
  counters->association_cap_hits = c.association_cap_hits;
  counters->tentative_evicted = c.tentative_evicted;
  counters->mixture_truncated = c.mixture_truncated;
  counters->scans_over_detection_cap = tracker->scans_over_detection_cap;
  return MPTRACK_OK;
}

size_t mptrack_max_detections(const mptrack_tracker* tracker) {
  return live(tracker) ? tracker->ops->max_detections : 0u;
}

size_t mptrack_max_tracks(const mptrack_tracker* tracker) {
  return live(tracker) ? tracker->ops->max_tracks : 0u;
}

void mptrack_deinit(mptrack_tracker* tracker) {
  if (live(tracker)) tracker->ops->destroy(tracker);
}

}  // extern "C"
