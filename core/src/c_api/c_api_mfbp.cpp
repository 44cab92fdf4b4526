// C API of the MF-BP tracker (mptrack_c.h): MfbpTracker<float, DefaultCaps>,
// the parameter block a firmware sets; every other field keeps the C++
// default (mfbp_params.h, docs/algorithms/mfbp.md).
#include "c_api_slot.h"
#include "mptrack/c/mptrack_c.h"
#include "mptrack/caps.h"
#include "mptrack/mfbp/mfbp_tracker.h"

namespace {
using Tracker = mptrack::MfbpTracker<float, mptrack::DefaultCaps>;
using Params = mptrack::MfbpParams<float>;

/// false if a C enum holds a value with no C++ counterpart.
bool params_from_c(const mptrack_mfbp_params& c, Params& p) {
  p = Params{};
  mptrack::capi::region_from_c(c.region, p.region);
  mptrack::capi::noise_from_c(c.noise, p.noise);
  p.scan_period_s = c.scan_period_s;
  p.max_gap_s = c.max_gap_s;
  p.accel_var_m2ps4 = c.accel_var_m2ps4;
  p.gate_chi2 = c.gate_chi2;
  p.amplitude.use_amplitude = c.use_amplitude != 0;
  p.amplitude.threshold = c.amplitude_threshold;
  p.use_doppler = c.use_doppler != 0;
  p.doppler_span_mps = c.doppler_span_mps;
  p.p_survive = c.p_survive;
  p.p_birth = c.p_birth;
  p.window_length = c.window_length;
  p.slide = c.slide;
  p.confirm_lookahead_in_clutter = c.confirm_lookahead_in_clutter;
  p.birth_in_clutter_max_cnr = c.birth_in_clutter_max_cnr;
  p.uniform_rate_per_scan = c.uniform_rate_per_scan;
  p.v_max_x_mps = c.v_max_x_mps;
  p.v_max_y_mps = c.v_max_y_mps;
  p.confirm_threshold = c.confirm_threshold;
  p.delete_threshold = c.delete_threshold;
  switch (c.clutter_mode) {
    case MPTRACK_MFBP_CLUTTER_ESTIMATED_MAP: p.clutter_mode = mptrack::ClutterMode::kEstimatedMap; return true;
    case MPTRACK_MFBP_CLUTTER_KNOWN_RATE_UNIFORM:
      p.clutter_mode = mptrack::ClutterMode::kKnownRateUniform;
      return true;
  }
  return false;
}
static_assert(sizeof(mptrack::capi::Slot<Tracker>) <= sizeof(mptrack_mfbp_storage),
              "raise MPTRACK_MFBP_STORAGE_BYTES (mptrack_c.h)");
static_assert(alignof(mptrack::capi::Slot<Tracker>) <= alignof(mptrack_mfbp_storage),
              "mptrack_mfbp_storage must be aligned for the tracker");

/// The C block of p (the inverse of params_from_c on the fields it holds).
void params_to_c(const Params& p, mptrack_mfbp_params* c) {
  mptrack::capi::region_to_c(p.region, c->region);
  mptrack::capi::noise_to_c(p.noise, c->noise);
  c->scan_period_s = p.scan_period_s;
  c->max_gap_s = p.max_gap_s;
  c->accel_var_m2ps4 = p.accel_var_m2ps4;
  c->gate_chi2 = p.gate_chi2;
  c->use_amplitude = p.amplitude.use_amplitude ? 1 : 0;
  c->amplitude_threshold = p.amplitude.threshold;
  c->use_doppler = p.use_doppler ? 1 : 0;
  c->doppler_span_mps = p.doppler_span_mps;
  c->p_survive = p.p_survive;
  c->p_birth = p.p_birth;
  c->window_length = static_cast<uint32_t>(p.window_length);
  c->slide = static_cast<uint32_t>(p.slide);
  c->confirm_lookahead_in_clutter = static_cast<uint32_t>(p.confirm_lookahead_in_clutter);
  c->birth_in_clutter_max_cnr = p.birth_in_clutter_max_cnr;
  c->clutter_mode = MPTRACK_MFBP_CLUTTER_ESTIMATED_MAP;  // ClutterMode::kEstimatedMap, Params' default
  c->uniform_rate_per_scan = p.uniform_rate_per_scan;
  c->v_max_x_mps = p.v_max_x_mps;
  c->v_max_y_mps = p.v_max_y_mps;
  c->confirm_threshold = p.confirm_threshold;
  c->delete_threshold = p.delete_threshold;
}
}  // namespace

extern "C" {

void mptrack_mfbp_default_params(mptrack_mfbp_params* c) {
  if (c == nullptr) return;
  params_to_c(Params{}, c);
}

void mptrack_mfbp_every_scan_params(mptrack_mfbp_params* c) {
  if (c == nullptr) return;
  params_to_c(mptrack::every_scan_smoother_params<float>(), c);
}

size_t mptrack_mfbp_size(void) { return sizeof(mptrack::capi::Slot<Tracker>); }
size_t mptrack_mfbp_alignment(void) { return alignof(mptrack::capi::Slot<Tracker>); }

mptrack_status mptrack_mfbp_init(void* memory, size_t size, const mptrack_mfbp_params* params,
                                 mptrack_tracker** tracker, mptrack_param_error* error) {
  if (params == nullptr) return MPTRACK_INVALID_ARGUMENT;
  Params p;
  if (!params_from_c(*params, p)) {
    if (error != nullptr) *error = mptrack_param_error{"clutter_mode", "a mptrack_mfbp_clutter_mode value"};
    return MPTRACK_INVALID_ARGUMENT;
  }
  return mptrack::capi::slot_init<Tracker>(memory, size, p, tracker, error);
}

}  // extern "C"
