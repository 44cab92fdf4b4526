/* C99 side of the C API test (c_api_scene.h). Built with -std=c99 -Wall
 * -Wextra -Werror -pedantic: the header must be clean C. */
#include "c_api_scene.h"

static mptrack_mfbp_storage g_mfbp_memory;
static mptrack_gnn_storage g_gnn_memory;
static mptrack_gmphd_storage g_gmphd_memory;
static mptrack_cbmember_storage g_cbmember_memory;

uint64_t c_api_scene_time_us(uint32_t k) { return 1250000u * (uint64_t)(k + 1u); }

size_t c_api_scene_scan(uint32_t k, mptrack_detection* out) {
  uint32_t x = 2463534242u + 7u * k;
  size_t n = 0;
  uint32_t j;
  /* Target 0 recedes at 40 m per scan, target 1 closes at 30 m per scan
   * while it turns slowly in azimuth; both are missed on some scans. */
  if (k % 7u != 3u) {
    out[n].range_m = 20000.0f + 40.0f * (float)k;
    out[n].azimuth_rad = 0.5f;
    out[n].amplitude = 4.5f;
    out[n].doppler_mps = 0.0f;
    ++n;
  }
  if (k % 5u != 2u) {
    out[n].range_m = 35000.0f - 30.0f * (float)k;
    out[n].azimuth_rad = 0.8f + 0.0005f * (float)k;
    out[n].amplitude = 3.5f;
    out[n].doppler_mps = 0.0f;
    ++n;
  }
  for (j = 0; j < 4u; ++j) {
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    out[n].range_m = 10000.0f + (float)(x % 40000u);
    out[n].azimuth_rad = 0.1745f + 0.0000167f * (float)((x >> 8) % 52000u);
    out[n].amplitude = 0.8f + 0.001f * (float)((x >> 4) % 1000u);
    out[n].doppler_mps = 0.0f;
    ++n;
  }
  return n;
}

/* MF-BP's default region and noise (seed 000), for the other trackers. */
static void set_scene_sensor(mptrack_polar_region* region, mptrack_polar_noise* noise) {
  region->range_min_m = 10000.0f;
  region->range_max_m = 50000.0f;
  region->azimuth_min_rad = 0.17453292f;
  region->azimuth_max_rad = 1.0471976f;
  noise->range_std_m = 20.0f;
  noise->azimuth_std_rad = 0.0104719755f;
}

void c_api_scene_gnn_params(mptrack_gnn_params* p) {
  mptrack_gnn_default_params(p);
  set_scene_sensor(&p->region, &p->noise);
  p->init_velocity_std_mps = 50.0f;
}

void c_api_scene_rfs_params(mptrack_rfs_params* p) {
  mptrack_rfs_default_params(p);
  set_scene_sensor(&p->region, &p->noise);
}

/* Appends every track of every output of the last call. */
static mptrack_status record_outputs(const mptrack_tracker* t, c_api_record* records, size_t capacity,
                                     size_t* n) {
  mptrack_track tracks[64];
  size_t o;
  for (o = 0; o < mptrack_num_outputs(t); ++o) {
    mptrack_output_info info;
    size_t count = 0;
    size_t i;
    mptrack_status s = mptrack_output(t, o, &info);
    if (s != MPTRACK_OK) return s;
    s = mptrack_output_tracks(t, o, tracks, 64u, &count);
    if (s != MPTRACK_OK) return s;
    for (i = 0; i < count; ++i) {
      if (*n >= capacity) return MPTRACK_CAPACITY_EXCEEDED;
      records[*n].scan_index = info.scan_index;
      records[*n].time_us = info.time_us;
      records[*n].track = tracks[i];
      ++*n;
    }
  }
  return MPTRACK_OK;
}

mptrack_status c_api_scene_run(c_api_tracker which, c_api_record* records, size_t capacity,
                               size_t* num_records, mptrack_counters* counters) {
  mptrack_tracker* t = NULL;
  mptrack_status s;
  uint32_t k;
  *num_records = 0;
  if (which == kCApiMfbp || which == kCApiMfbpEveryScan) {
    mptrack_mfbp_params p;
    if (which == kCApiMfbp) {
      mptrack_mfbp_default_params(&p);
    } else {
      mptrack_mfbp_every_scan_params(&p);
    }
    s = mptrack_mfbp_init(&g_mfbp_memory, sizeof g_mfbp_memory, &p, &t, NULL);
  } else if (which == kCApiGnn) {
    mptrack_gnn_params p;
    c_api_scene_gnn_params(&p);
    s = mptrack_gnn_init(&g_gnn_memory, sizeof g_gnn_memory, &p, &t, NULL);
  } else {
    mptrack_rfs_params p;
    c_api_scene_rfs_params(&p);
    if (which == kCApiGmPhd) {
      s = mptrack_gmphd_init(&g_gmphd_memory, sizeof g_gmphd_memory, &p, &t, NULL);
    } else if (which == kCApiGmCphd) {
      s = mptrack_gmcphd_init(&g_gmphd_memory, sizeof g_gmphd_memory, &p, &t, NULL);
    } else {
      s = mptrack_cbmember_init(&g_cbmember_memory, sizeof g_cbmember_memory, &p, &t, NULL);
    }
  }
  if (s != MPTRACK_OK) return s;
  for (k = 0; k < kCApiSceneScans; ++k) {
    mptrack_detection d[kCApiSceneMaxDetections];
    mptrack_scan scan;
    scan.time_us = c_api_scene_time_us(k);
    scan.has_doppler = 0;
    scan.num_detections = c_api_scene_scan(k, d);
    scan.detections = d;
    s = mptrack_step(t, &scan);
    if (s != MPTRACK_OK && s != MPTRACK_PARTIAL) break;
    s = record_outputs(t, records, capacity, num_records);
    if (s != MPTRACK_OK) break;
  }
  if (s == MPTRACK_OK || s == MPTRACK_PARTIAL) {
    s = mptrack_flush(t);
    if (s == MPTRACK_OK) s = record_outputs(t, records, capacity, num_records);
  }
  (void)mptrack_get_counters(t, counters);
  mptrack_deinit(t);
  return s;
}
