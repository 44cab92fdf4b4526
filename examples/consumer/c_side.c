/* The consumer's C part: a GNN tracker through the C API, in .bss. */
#include "mptrack/c/mptrack_c.h"

static mptrack_gnn_storage g_gnn;

/* One scan with one detection; returns the number of tracks reported. */
int consumer_c_side(void) {
  mptrack_gnn_params p;
  mptrack_tracker* t = NULL;
  mptrack_detection d = {100.0f, 0.25f, 5.0f, 0.0f};
  mptrack_scan scan = {1000000u, 0, 1u, NULL};
  mptrack_output_info info = {0u, 0u, 0u};
  scan.detections = &d;
  mptrack_gnn_default_params(&p);
  p.report_tentative = 1;
  if (mptrack_gnn_init(&g_gnn, sizeof g_gnn, &p, &t, NULL) != MPTRACK_OK) return -1;
  if (mptrack_step(t, &scan) != MPTRACK_OK) return -1;
  if (mptrack_output(t, 0u, &info) != MPTRACK_OK) return -1;
  mptrack_deinit(t);
  return (int)info.num_tracks;
}
