/* The small scene of the C API test (c_api_scene.c, compiled as C99) and
 * its run through the C API, recorded for the C++ side (c_api_test.cpp),
 * which runs the C++ trackers on the same detections and compares bits. */
#ifndef MPTRACK_TESTS_C_API_SCENE_H
#define MPTRACK_TESTS_C_API_SCENE_H

#include <stddef.h>
#include <stdint.h>

#include "mptrack/c/mptrack_c.h"

#ifdef __cplusplus
extern "C" {
#endif

enum { kCApiSceneScans = 24, kCApiSceneMaxDetections = 12, kCApiSceneMaxRecords = 2048 };

/* Detections of scan k (0-based): two targets moving in range and azimuth
 * and a few xorshift clutter points, inside MF-BP's default region.
 * Returns the count written to out (<= kCApiSceneMaxDetections). */
size_t c_api_scene_scan(uint32_t k, mptrack_detection* out);
/* Scan time of scan k [us] (1.25 s period). */
uint64_t c_api_scene_time_us(uint32_t k);
/* The GNN parameters of the scene (defaults with the scene's region and noise). */
void c_api_scene_gnn_params(mptrack_gnn_params* p);

/* One reported track of one finalised scan, in output order. */
typedef struct c_api_record {
  uint32_t scan_index;
  uint64_t time_us;
  mptrack_track track;
} c_api_record;

/* The scene's GM-PHD / GM-CPHD / CBMeMBer parameters (polar defaults with
 * the scene's region and noise). */
void c_api_scene_rfs_params(mptrack_rfs_params* p);

typedef enum c_api_tracker {
  kCApiMfbp = 0,
  kCApiGnn = 1,
  kCApiGmPhd = 2,
  kCApiGmCphd = 3,
  kCApiCbMember = 4,
  kCApiMfbpEveryScan = 5 /* MF-BP with mptrack_mfbp_every_scan_params */
} c_api_tracker;

/* Runs the scene through the C API (static memory), flushes, and records
 * every track of every finalised scan. Returns MPTRACK_OK or the first
 * failing status; *num_records and counters are set. */
mptrack_status c_api_scene_run(c_api_tracker which, c_api_record* records, size_t capacity,
                               size_t* num_records, mptrack_counters* counters);

#ifdef __cplusplus
}
#endif

#endif
