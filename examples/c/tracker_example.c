/* mptrack C API example (C99): MF-BP over 30 scans of two targets and
 * uniform clutter, the tracker in static memory, no heap, no stdio (the
 * caller's print callback writes each line). */
#include "tracker_example.h"

#include <stddef.h>
#include <stdint.h>

#include "mptrack/c/mptrack_c.h"

enum { kScans = 30, kClutter = 5, kMaxLine = 160 };

static mptrack_mfbp_storage g_tracker_memory; /* .bss: ~328 KiB on a Cortex-M7 */

/* --- tiny formatting, so the example needs no printf on a board --- */
typedef struct line_buf {
  char text[kMaxLine];
  size_t len;
} line_buf;

static void put_str(line_buf* b, const char* s) {
  while (*s != '\0' && b->len + 1u < sizeof b->text) b->text[b->len++] = *s++;
  b->text[b->len] = '\0';
}

static void put_uint(line_buf* b, uint64_t v) {
  char digits[24];
  size_t n = 0;
  do {
    digits[n++] = (char)('0' + (int)(v % 10u));
    v /= 10u;
  } while (v != 0u);
  while (n > 0u && b->len + 1u < sizeof b->text) b->text[b->len++] = digits[--n];
  b->text[b->len] = '\0';
}

/* v with one decimal, rounded half away from zero. */
static void put_fixed1(line_buf* b, float v) {
  const int negative = v < 0.0f;
  const uint64_t tenths = (uint64_t)((negative ? -v : v) * 10.0f + 0.5f);
  if (negative) put_str(b, "-");
  put_uint(b, tenths / 10u);
  put_str(b, ".");
  put_uint(b, tenths % 10u);
}

/* --- the scene: what a detector would hand over each scan --- */
static size_t scene_scan(uint32_t k, mptrack_detection* d) {
  static uint32_t x = 2463534242u; /* xorshift state for the clutter */
  size_t n = 0;
  uint32_t j;
  if (k % 9u != 4u) { /* target A: receding 40 m per scan, one miss in nine */
    d[n].range_m = 20000.0f + 40.0f * (float)k;
    d[n].azimuth_rad = 0.5f;
    d[n].amplitude = 4.5f;
    d[n].doppler_mps = 0.0f;
    ++n;
  }
  if (k % 6u != 1u) { /* target B: closing 30 m per scan while turning */
    d[n].range_m = 35000.0f - 30.0f * (float)k;
    d[n].azimuth_rad = 0.8f + 0.0005f * (float)k;
    d[n].amplitude = 3.5f;
    d[n].doppler_mps = 0.0f;
    ++n;
  }
  for (j = 0; j < kClutter; ++j) {
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    d[n].range_m = 10000.0f + (float)(x % 40000u);
    d[n].azimuth_rad = 0.1745f + 0.0000167f * (float)((x >> 8) % 52000u);
    d[n].amplitude = 0.8f + 0.001f * (float)((x >> 4) % 1000u);
    d[n].doppler_mps = 0.0f;
    ++n;
  }
  return n;
}

/* Prints the confirmed tracks of every scan the last call finalised;
 * returns a bit mask of the track ids seen (ids < 32). */
static uint32_t print_outputs(const mptrack_tracker* t, mptrack_example_print print) {
  mptrack_track tracks[16];
  uint32_t seen = 0;
  size_t o;
  size_t i;
  for (o = 0; o < mptrack_num_outputs(t); ++o) {
    mptrack_output_info info;
    size_t count = 0;
    if (mptrack_output(t, o, &info) != MPTRACK_OK) continue;
    /* CAPACITY_EXCEEDED would mean more than 16 tracks: the first 16 are kept. */
    (void)mptrack_output_tracks(t, o, tracks, 16u, &count);
    for (i = 0; i < count; ++i) {
      line_buf b = {{0}, 0};
      if (!tracks[i].confirmed) continue;
      put_str(&b, "scan ");
      put_uint(&b, info.scan_index);
      put_str(&b, " t=");
      put_fixed1(&b, (float)info.time_us * 1e-6f);
      put_str(&b, " s  track ");
      put_uint(&b, tracks[i].id);
      put_str(&b, "  x=");
      put_fixed1(&b, tracks[i].state[0]);
      put_str(&b, " m  y=");
      put_fixed1(&b, tracks[i].state[2]);
      put_str(&b, " m  vx=");
      put_fixed1(&b, tracks[i].state[1]);
      put_str(&b, " m/s  vy=");
      put_fixed1(&b, tracks[i].state[3]);
      put_str(&b, " m/s");
      print(b.text);
      if (tracks[i].id < 32u) seen |= 1u << tracks[i].id;
    }
  }
  return seen;
}

/* The smoother finalises a scan only when it leaves the window (here 2
 * scans later); for a picture of the scan just consumed it hands out a
 * provisional estimate, revised by later windows. Prints its confirmed
 * track count; nothing before the first window. */
static void print_provisional(const mptrack_tracker* t, mptrack_example_print print) {
  mptrack_track tracks[16];
  mptrack_output_info info;
  size_t count = 0;
  size_t i;
  unsigned confirmed = 0;
  line_buf b = {{0}, 0};
  if (mptrack_provisional(t, &info, tracks, 16u, &count) == MPTRACK_INVALID_ARGUMENT) return;
  for (i = 0; i < count; ++i) confirmed += tracks[i].confirmed ? 1u : 0u;
  put_str(&b, "now: scan ");
  put_uint(&b, info.scan_index);
  put_str(&b, ", ");
  put_uint(&b, confirmed);
  put_str(&b, " confirmed track(s), provisional");
  print(b.text);
}

static int count_bits(uint32_t v) {
  int n = 0;
  for (; v != 0u; v &= v - 1u) ++n;
  return n;
}

int mptrack_example_run(mptrack_example_print print) {
  mptrack_mfbp_params params;
  mptrack_param_error err = {NULL, NULL};
  mptrack_tracker* tracker = NULL;
  mptrack_counters c;
  mptrack_status s;
  uint32_t seen = 0;
  uint32_t k;
  line_buf b = {{0}, 0};

  mptrack_mfbp_default_params(&params); /* seed 000 defaults: 10-50 km, 10-60 deg */
  params.window_length = 4;             /* smoother: finalise 2 scans per 4-scan window */
  params.slide = 2;
  s = mptrack_mfbp_init(&g_tracker_memory, sizeof g_tracker_memory, &params, &tracker, &err);
  if (s != MPTRACK_OK) {
    put_str(&b, "init failed: ");
    put_str(&b, mptrack_status_string(s));
    put_str(&b, err.field != NULL ? " field " : "");
    put_str(&b, err.field != NULL ? err.field : "");
    print(b.text);
    return 1;
  }
  put_str(&b, "MF-BP in ");
  put_uint(&b, mptrack_mfbp_size());
  put_str(&b, " bytes of static memory, up to ");
  put_uint(&b, mptrack_max_detections(tracker));
  put_str(&b, " detections per scan");
  print(b.text);

  for (k = 0; k < kScans; ++k) {
    mptrack_detection d[2 + kClutter];
    mptrack_scan scan;
    scan.time_us = 1250000u * (uint64_t)(k + 1u); /* 1.25 s scans */
    scan.has_doppler = 0;
    scan.num_detections = scene_scan(k, d);
    scan.detections = d;
    s = mptrack_step(tracker, &scan);
    if (s != MPTRACK_OK && s != MPTRACK_PARTIAL) break; /* PARTIAL: some clutter rejected, counted */
    seen |= print_outputs(tracker, print);
    print_provisional(tracker, print);
  }
  if (s == MPTRACK_OK || s == MPTRACK_PARTIAL) s = mptrack_flush(tracker);
  seen |= print_outputs(tracker, print);

  (void)mptrack_get_counters(tracker, &c);
  b.len = 0;
  put_str(&b, "scans ");
  put_uint(&b, c.scans);
  put_str(&b, ", detections ");
  put_uint(&b, c.measurements_in);
  put_str(&b, " (");
  put_uint(&b, c.measurements_invalid);
  put_str(&b, " rejected), tracks born ");
  put_uint(&b, c.tracks_born);
  put_str(&b, ", confirmed ");
  put_uint(&b, c.tracks_confirmed);
  put_str(&b, ", last status ");
  put_str(&b, mptrack_status_string(s));
  print(b.text);
  mptrack_deinit(tracker);

  b.len = 0;
  put_str(&b, count_bits(seen) == 2 && s == MPTRACK_OK ? "c example: PASS" : "c example: FAIL");
  print(b.text);
  return count_bits(seen) == 2 && s == MPTRACK_OK ? 0 : 1;
}
