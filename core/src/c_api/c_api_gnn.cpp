// C API of the GNN + Kalman tracker (mptrack_c.h): GnnTracker<float,
// DefaultCaps>; every GnnParams field (gnn_params.h, docs/algorithms/gnn.md).
#include "c_api_slot.h"
#include "mptrack/c/mptrack_c.h"
#include "mptrack/caps.h"
#include "mptrack/gnn/gnn_tracker.h"

namespace {
using Tracker = mptrack::GnnTracker<float, mptrack::DefaultCaps>;
using Params = mptrack::GnnParams<float>;
static_assert(sizeof(mptrack::capi::Slot<Tracker>) <= sizeof(mptrack_gnn_storage),
              "raise MPTRACK_GNN_STORAGE_BYTES (mptrack_c.h)");
static_assert(alignof(mptrack::capi::Slot<Tracker>) <= alignof(mptrack_gnn_storage),
              "mptrack_gnn_storage must be aligned for the tracker");
}  // namespace

extern "C" {

void mptrack_gnn_default_params(mptrack_gnn_params* c) {
  if (c == nullptr) return;
  const Params p{};
  c->accel_var_m2ps4 = p.accel_var_m2ps4;
  mptrack::capi::noise_to_c(p.noise, c->noise);
  c->init_velocity_std_mps = p.init_velocity_std_mps;
  c->gate_chi2 = p.gate_chi2;
  c->confirm_hits = p.confirm_hits;
  c->confirm_window = p.confirm_window;
  c->max_misses = p.max_misses;
  c->report_tentative = p.report_tentative ? 1 : 0;
  mptrack::capi::region_to_c(p.region, c->region);
  c->max_gap_s = p.max_gap_s;
  c->min_variance = p.min_variance;
}

size_t mptrack_gnn_size(void) { return sizeof(mptrack::capi::Slot<Tracker>); }
size_t mptrack_gnn_alignment(void) { return alignof(mptrack::capi::Slot<Tracker>); }

mptrack_status mptrack_gnn_init(void* memory, size_t size, const mptrack_gnn_params* params,
                                mptrack_tracker** tracker, mptrack_param_error* error) {
  if (params == nullptr) return MPTRACK_INVALID_ARGUMENT;
  Params p;
  p.accel_var_m2ps4 = params->accel_var_m2ps4;
  mptrack::capi::noise_from_c(params->noise, p.noise);
  p.init_velocity_std_mps = params->init_velocity_std_mps;
  p.gate_chi2 = params->gate_chi2;
  p.confirm_hits = params->confirm_hits;
  p.confirm_window = params->confirm_window;
  p.max_misses = params->max_misses;
  p.report_tentative = params->report_tentative != 0;
  mptrack::capi::region_from_c(params->region, p.region);
  p.max_gap_s = params->max_gap_s;
  p.min_variance = params->min_variance;
  return mptrack::capi::slot_init<Tracker>(memory, size, p, tracker, error);
}

}  // extern "C"
