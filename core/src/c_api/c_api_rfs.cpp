// C API of the IGGM filters (mptrack_c.h): GmPhdFilter, GmCphdFilter and
// CbMemberFilter<float, DefaultCaps> in polar measurement space, one
// parameter block for the three (rfs_params.h, docs/algorithms/gm-phd.md).
#include "c_api_slot.h"
#include "mptrack/c/mptrack_c.h"
#include "mptrack/caps.h"
#include "mptrack/cbmember/cbmember_filter.h"
#include "mptrack/phd/phd_filter.h"

namespace {
using Params = mptrack::RfsFilterParams<float>;
using Phd = mptrack::GmPhdFilter<float, mptrack::DefaultCaps>;
using Cphd = mptrack::GmCphdFilter<float, mptrack::DefaultCaps>;
using Cbm = mptrack::CbMemberFilter<float, mptrack::DefaultCaps>;

static_assert(sizeof(mptrack::capi::Slot<Phd>) <= sizeof(mptrack_gmphd_storage),
              "raise MPTRACK_GMPHD_STORAGE_BYTES (mptrack_c.h)");
static_assert(sizeof(mptrack::capi::Slot<Cphd>) <= sizeof(mptrack_gmphd_storage),
              "raise MPTRACK_GMPHD_STORAGE_BYTES (mptrack_c.h)");
static_assert(sizeof(mptrack::capi::Slot<Cbm>) <= sizeof(mptrack_cbmember_storage),
              "raise MPTRACK_CBMEMBER_STORAGE_BYTES (mptrack_c.h)");
static_assert(alignof(mptrack::capi::Slot<Phd>) <= alignof(mptrack_gmphd_storage) &&
                  alignof(mptrack::capi::Slot<Cphd>) <= alignof(mptrack_gmphd_storage) &&
                  alignof(mptrack::capi::Slot<Cbm>) <= alignof(mptrack_cbmember_storage),
              "the storage unions must be aligned for the filters");

/// The C++ defaults in polar space with a polar hot-spot box (mptrack_c.h).
Params polar_defaults() {
  Params p;
  p.space = mptrack::MeasurementSpace::kPolar;
  p.hotspot_half_width0 = 500.0f;          // [m]
  p.hotspot_half_width1 = 0.034906585f;    // 2 deg [rad]
  return p;
}

/// false if a C enum holds a value with no C++ counterpart.
bool params_from_c(const mptrack_rfs_params& c, Params& p) {
  p = polar_defaults();
  mptrack::capi::region_from_c(c.region, p.region);
  mptrack::capi::noise_from_c(c.noise, p.noise);
  p.scan_period_s = c.scan_period_s;
  p.max_gap_s = c.max_gap_s;
  p.accel_var_m2ps4 = c.accel_var_m2ps4;
  p.survival_prob = c.survival_prob;
  p.birth_rate = c.birth_rate;
  p.birth_velocity_std_mps = c.birth_velocity_std_mps;
  p.amplitude.use_amplitude = c.use_amplitude != 0;
  p.amplitude.threshold = c.amplitude_threshold;
  p.target_power_prior = c.target_power_prior;
  p.detection_prob = c.detection_prob;
  p.clutter_rate = c.clutter_rate;
  p.clutter_scale = c.clutter_scale;
  p.hotspot_half_width0 = c.hotspot_half_width_range_m;
  p.hotspot_half_width1 = c.hotspot_half_width_azimuth_rad;
  p.gate_probability = c.gate_probability;
  p.extract_threshold = c.extract_threshold;
  p.existence_extract = c.existence_extract;
  switch (c.clutter_mode) {
    case MPTRACK_RFS_CLUTTER_ESTIMATED_MAP: p.clutter_mode = mptrack::ClutterMode::kEstimatedMap; return true;
    case MPTRACK_RFS_CLUTTER_ESTIMATED_UNIFORM:
      p.clutter_mode = mptrack::ClutterMode::kEstimatedUniform;
      return true;
    case MPTRACK_RFS_CLUTTER_KNOWN_UNIFORM: p.clutter_mode = mptrack::ClutterMode::kKnownUniform; return true;
  }
  return false;
}

template <class X>
mptrack_status init(void* memory, size_t size, const mptrack_rfs_params* params, mptrack_tracker** tracker,
                    mptrack_param_error* error) {
  if (params == nullptr) return MPTRACK_INVALID_ARGUMENT;
  Params p;
  if (!params_from_c(*params, p)) {
    if (error != nullptr) *error = mptrack_param_error{"clutter_mode", "a mptrack_rfs_clutter_mode value"};
    return MPTRACK_INVALID_ARGUMENT;
  }
  return mptrack::capi::slot_init<X>(memory, size, p, tracker, error);
}
}  // namespace

extern "C" {

void mptrack_rfs_default_params(mptrack_rfs_params* c) {
  if (c == nullptr) return;
  const Params p = polar_defaults();
  mptrack::capi::region_to_c(p.region, c->region);
  mptrack::capi::noise_to_c(p.noise, c->noise);
  c->scan_period_s = p.scan_period_s;
  c->max_gap_s = p.max_gap_s;
  c->accel_var_m2ps4 = p.accel_var_m2ps4;
  c->survival_prob = p.survival_prob;
  c->birth_rate = p.birth_rate;
  c->birth_velocity_std_mps = p.birth_velocity_std_mps;
  c->use_amplitude = p.amplitude.use_amplitude ? 1 : 0;
  c->amplitude_threshold = p.amplitude.threshold;
  c->target_power_prior = p.target_power_prior;
  c->detection_prob = p.detection_prob;
  c->clutter_mode = MPTRACK_RFS_CLUTTER_ESTIMATED_MAP;  // ClutterMode::kEstimatedMap, Params' default
  c->clutter_rate = p.clutter_rate;
  c->clutter_scale = p.clutter_scale;
  c->hotspot_half_width_range_m = p.hotspot_half_width0;
  c->hotspot_half_width_azimuth_rad = p.hotspot_half_width1;
  c->gate_probability = p.gate_probability;
  c->extract_threshold = p.extract_threshold;
  c->existence_extract = p.existence_extract;
}

size_t mptrack_gmphd_size(void) { return sizeof(mptrack::capi::Slot<Phd>); }
size_t mptrack_gmphd_alignment(void) { return alignof(mptrack::capi::Slot<Phd>); }
mptrack_status mptrack_gmphd_init(void* memory, size_t size, const mptrack_rfs_params* params,
                                  mptrack_tracker** tracker, mptrack_param_error* error) {
  return init<Phd>(memory, size, params, tracker, error);
}

size_t mptrack_gmcphd_size(void) { return sizeof(mptrack::capi::Slot<Cphd>); }
size_t mptrack_gmcphd_alignment(void) { return alignof(mptrack::capi::Slot<Cphd>); }
mptrack_status mptrack_gmcphd_init(void* memory, size_t size, const mptrack_rfs_params* params,
                                   mptrack_tracker** tracker, mptrack_param_error* error) {
  return init<Cphd>(memory, size, params, tracker, error);
}

size_t mptrack_cbmember_size(void) { return sizeof(mptrack::capi::Slot<Cbm>); }
size_t mptrack_cbmember_alignment(void) { return alignof(mptrack::capi::Slot<Cbm>); }
mptrack_status mptrack_cbmember_init(void* memory, size_t size, const mptrack_rfs_params* params,
                                     mptrack_tracker** tracker, mptrack_param_error* error) {
  return init<Cbm>(memory, size, params, tracker, error);
}

}  // extern "C"
