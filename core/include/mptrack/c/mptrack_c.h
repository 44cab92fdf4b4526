/* mptrack C API: the float trackers of core for C firmware (C99, no heap).
 *
 * Shape (README.md "C API"): the caller owns every byte. Per tracker
 *   mptrack_<tracker>_size() / mptrack_<tracker>_alignment()  bytes a tracker needs
 *   (or mptrack_<tracker>_storage, a union sized for every target)
 *   mptrack_<tracker>_default_params(&p)                     the C++ Params defaults
 *   (one block and mptrack_rfs_default_params for gmphd, gmcphd, cbmember)
 *   mptrack_<tracker>_init(memory, size, &p, &tracker, &err)  construct in that memory
 * then, for every tracker alike,
 *   mptrack_step(tracker, &scan)      one scan of detections
 *   mptrack_num_outputs / mptrack_output / mptrack_output_tracks   finalised scans
 *   mptrack_flush(tracker)            end of data (window smoothers hold scans back)
 *   mptrack_get_counters(tracker, &c) nothing is lost without being counted
 *   mptrack_deinit(tracker)           the memory may then be reused
 * Results are the C++ trackers' bit for bit (tests/unit/c_api_test.cpp).
 * The memory can be static (.bss), a stack array or a pool; mptrack never
 * allocates, throws or keeps a pointer to caller data beyond a call.
 * Not thread-safe per tracker; distinct trackers are independent.
 *
 * Trackers (all float, DefaultCaps: 64 tracks, 256 detections per scan):
 * mfbp (MF-BP smoother, window <= 7), gnn (GNN + Kalman), gmphd, gmcphd and
 * cbmember (the IGGM filters of seed 001, polar measurements).
 */
#ifndef MPTRACK_C_MPTRACK_C_H
#define MPTRACK_C_MPTRACK_C_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Status of every call (the values of mptrack::Status, status.h). */
typedef enum mptrack_status {
  MPTRACK_OK = 0,
  MPTRACK_INVALID_ARGUMENT = 1,  /* a parameter, pointer or memory block is unusable */
  MPTRACK_INVALID_INPUT = 2,     /* input data rejected */
  MPTRACK_CAPACITY_EXCEEDED = 3, /* a compile-time cap was hit (counted; see counters) */
  MPTRACK_OUT_OF_ORDER = 4,      /* scan time not after the previous scan: refused */
  MPTRACK_NUMERICAL_ERROR = 5,
  MPTRACK_NOT_INITIALIZED = 6,
  MPTRACK_BUFFER_FULL = 7,
  MPTRACK_BUFFER_EMPTY = 8,
  MPTRACK_PARTIAL = 9            /* accepted, some detections rejected (counted) */
} mptrack_status;

/* "ok", "invalid_argument", ... (static strings; "unknown" for other values). */
const char* mptrack_status_string(mptrack_status status);

/* One detection in polar measurement space. */
typedef struct mptrack_detection {
  float range_m;      /* slant range [m] */
  float azimuth_rad;  /* azimuth [rad], counter-clockwise from +x */
  float amplitude;    /* normalised envelope |z| / sqrt(N0) [-] */
  float doppler_mps;  /* radial velocity [m/s]; read only if the scan has_doppler */
} mptrack_detection;

/* One scan. detections may be NULL when num_detections is 0. */
typedef struct mptrack_scan {
  uint64_t time_us;  /* scan time [us], strictly increasing */
  int has_doppler;   /* non-zero: doppler_mps is filled in for every detection */
  size_t num_detections;
  const mptrack_detection* detections;
} mptrack_scan;

/* One track at one finalised scan. State order [px, vx, py, vy]. */
typedef struct mptrack_track {
  uint32_t id;             /* stable across scans, never reused within a run */
  float state[4];          /* [m, m/s, m, m/s] */
  float covariance[16];    /* of state, row-major [m^2 ...] */
  float existence;         /* P(target present) at this scan [-] */
  float snr;               /* estimated mean SNR, linear [-] (0 if not estimated) */
  int confirmed;           /* non-zero: passed the confirmation rule */
  int32_t measurement_index; /* detection index at this scan, -1 = missed */
} mptrack_track;

/* One finalised scan of mptrack_output(). */
typedef struct mptrack_output_info {
  uint64_t time_us;     /* time of the scan this estimate is for [us] */
  uint32_t scan_index;  /* 0-based index of that scan in the tracker's input */
  size_t num_tracks;
} mptrack_output_info;

/* TrackerCounters (track_report.h), plus the C layer's own refusals. */
typedef struct mptrack_counters {
  uint64_t scans;
  uint64_t scans_rejected;
  uint64_t measurements_in;
  uint64_t measurements_invalid;
  uint64_t measurements_over_cap;
  uint64_t tracks_born;
  uint64_t tracks_confirmed;
  uint64_t tracks_deleted;
  uint64_t track_cap_hits;
  uint64_t clutter_born;
  uint64_t clutter_deleted;
  uint64_t clutter_cap_hits;
  uint64_t bp_not_converged;
  uint64_t numerical_repairs;
  uint64_t gap_resets;
  uint64_t measurements_duplicate;
  uint64_t association_cap_hits;
  uint64_t tentative_evicted; /* tentative tracks deleted to make room for a more likely birth */
  uint64_t mixture_truncated; /* left out by a cap, never reportable (GM components beyond J_max, CBMeMBer raw components, low-r Bernoullis); not an error */
  /* Scans refused by mptrack_step() before the tracker saw them: more
   * detections than mptrack_max_detections() (MPTRACK_CAPACITY_EXCEEDED). */
  uint64_t scans_over_detection_cap;
} mptrack_counters;

/* Surveillance region; detections outside are rejected and counted. */
typedef struct mptrack_polar_region {
  float range_min_m;
  float range_max_m;
  float azimuth_min_rad;  /* in [-pi, pi] */
  float azimuth_max_rad;
} mptrack_polar_region;

/* Measurement noise standard deviations. */
typedef struct mptrack_polar_noise {
  float range_std_m;
  float azimuth_std_rad;
  float doppler_std_mps;
} mptrack_polar_noise;

/* Which parameter init() refused: field as named in the C++ Params
 * ("gate_chi2", "region.range_max_m") and the failed rule. Static strings. */
typedef struct mptrack_param_error {
  const char* field;
  const char* rule;
} mptrack_param_error;

/* Opaque handle; lives inside the caller's memory block. */
typedef struct mptrack_tracker mptrack_tracker;

/* Static storage. mptrack_<tracker>_size() is the exact figure for the
 * target; these are compile-time bounds of it on every supported target
 * (64- and 32-bit; the library static_asserts them), so firmware can place
 * a tracker in .bss:
 *   static mptrack_mfbp_storage g_mem;
 *   mptrack_mfbp_init(&g_mem, sizeof g_mem, &params, &tracker, &err);
 * The union members give the alignment the trackers need (8 bytes). */
#define MPTRACK_MFBP_STORAGE_BYTES 356352u /* 348 KiB: MF-BP, DefaultCaps (342.7 KiB on x86-64) */
#define MPTRACK_GNN_STORAGE_BYTES 122880u  /* 120 KiB: GNN, DefaultCaps (~114 KiB) */
typedef union mptrack_mfbp_storage {
  unsigned char bytes[MPTRACK_MFBP_STORAGE_BYTES];
  uint64_t align_u64;
  double align_double;
  void* align_pointer;
} mptrack_mfbp_storage;
typedef union mptrack_gnn_storage {
  unsigned char bytes[MPTRACK_GNN_STORAGE_BYTES];
  uint64_t align_u64;
  double align_double;
  void* align_pointer;
} mptrack_gnn_storage;

/* ---- MF-BP (seed 000; docs/algorithms/mfbp.md) ----------------------- */

/* Clutter models of MF-BP (mptrack::ClutterMode subset). */
typedef enum mptrack_mfbp_clutter_mode {
  MPTRACK_MFBP_CLUTTER_ESTIMATED_MAP = 0,      /* uniform + Gaussian sources, estimated */
  MPTRACK_MFBP_CLUTTER_KNOWN_RATE_UNIFORM = 1  /* uniform, rate uniform_rate_per_scan */
} mptrack_mfbp_clutter_mode;

/* The MF-BP tunables a firmware usually sets; every other MfbpParams field
 * keeps its C++ default (docs/algorithms/mfbp.md). */
typedef struct mptrack_mfbp_params {
  mptrack_polar_region region;
  mptrack_polar_noise noise;
  float scan_period_s;        /* nominal scan period [s] (birth gates, first prediction) */
  float max_gap_s;            /* a later scan restarts the tracker [s] */
  float accel_var_m2ps4;      /* CV white-acceleration variance per axis [m^2/s^4] */
  float gate_chi2;            /* target gate, 2 dof [-] */
  int use_amplitude;          /* non-zero: amplitude likelihoods (MP-RMTT), 0: kinematics only */
  float amplitude_threshold;  /* detector threshold d on the normalised envelope [-] */
  int use_doppler;            /* non-zero: use Doppler of scans that have it */
  float doppler_span_mps;     /* clutter Doppler uniform on [-span, span] [m/s] */
  float p_survive;            /* P(visible at k | visible at k-1) [-] */
  float p_birth;              /* P(visible at k | invisible at k-1) [-] */
  uint32_t window_length;     /* smoothing window K [scans], <= 7; 1 = online filter */
  uint32_t slide;             /* scans finalised per window, 1 <= slide <= window_length */
  uint32_t confirm_lookahead_in_clutter; /* later window scans a young track in weaker clutter
                                            needs on its confirming scan (0 = any scan) */
  float birth_in_clutter_max_cnr; /* no amplitude birth under Gaussian clutter of mean CNR
                                     above this, linear (0 = no limit) [-] */
  mptrack_mfbp_clutter_mode clutter_mode;
  float uniform_rate_per_scan;  /* known clutter rate (KNOWN_RATE_UNIFORM) [-] */
  float v_max_x_mps;          /* two-point birth gate [m/s] */
  float v_max_y_mps;
  float confirm_threshold;    /* confirm when visibility belief >= this [-] */
  float delete_threshold;     /* delete after a run of scans below this [-] */
} mptrack_mfbp_params;

void mptrack_mfbp_default_params(mptrack_mfbp_params* params);
/* The "mfbp-s1" configuration (every_scan_smoother_params): the defaults with
 * a window processed every scan (slide 1), confirm_lookahead_in_clutter 2 and
 * birth_in_clutter_max_cnr 6: births inside clutter are confirmed ~3 scans
 * sooner for ~2.5x the mean compute (docs/algorithms/mfbp.md, Window
 * schedule). */
void mptrack_mfbp_every_scan_params(mptrack_mfbp_params* params);
size_t mptrack_mfbp_size(void);
size_t mptrack_mfbp_alignment(void);
/* Constructs an MF-BP tracker in memory (size >= mptrack_mfbp_size(),
 * aligned to mptrack_mfbp_alignment()) and sets *tracker. On
 * MPTRACK_INVALID_ARGUMENT, error (if not NULL) names the refused field. */
mptrack_status mptrack_mfbp_init(void* memory, size_t size, const mptrack_mfbp_params* params,
                                 mptrack_tracker** tracker, mptrack_param_error* error);

/* ---- GNN + Kalman (seed 004 baseline; docs/algorithms/gnn.md) ------------ */

typedef struct mptrack_gnn_params {
  float accel_var_m2ps4;        /* CV white-acceleration variance per axis [m^2/s^4] */
  mptrack_polar_noise noise;    /* Doppler unused */
  float init_velocity_std_mps;  /* velocity std of a track at its birth [m/s] */
  float gate_chi2;              /* gate on nu^T S^-1 nu [-] */
  uint32_t confirm_hits;        /* M of the M-of-N confirmation [-] */
  uint32_t confirm_window;      /* N [scans], <= 32 */
  uint32_t max_misses;          /* delete after this many consecutive misses [scans] */
  int report_tentative;         /* non-zero: outputs hold tentative tracks too */
  mptrack_polar_region region;
  float max_gap_s;              /* a later scan drops every track [s] */
  float min_variance;           /* covariance repair floor [m^2 or (m/s)^2] */
} mptrack_gnn_params;

void mptrack_gnn_default_params(mptrack_gnn_params* params);
size_t mptrack_gnn_size(void);
size_t mptrack_gnn_alignment(void);
mptrack_status mptrack_gnn_init(void* memory, size_t size, const mptrack_gnn_params* params,
                                mptrack_tracker** tracker, mptrack_param_error* error);

/* ---- GM-PHD, GM-CPHD, CBMeMBer (seed 001; docs/algorithms/gm-phd.md) ----- */

/* Clutter models of the IGGM filters (mptrack::ClutterMode subset). */
typedef enum mptrack_rfs_clutter_mode {
  MPTRACK_RFS_CLUTTER_ESTIMATED_MAP = 0,      /* uniform + hot spots, estimated */
  MPTRACK_RFS_CLUTTER_ESTIMATED_UNIFORM = 1,  /* uniform, rate and scale estimated */
  MPTRACK_RFS_CLUTTER_KNOWN_UNIFORM = 2       /* uniform, clutter_rate and clutter_scale known */
} mptrack_rfs_clutter_mode;

/* One block for the three filters, in polar measurement space; every other
 * RfsFilterParams field keeps its C++ default (rfs_params.h). */
typedef struct mptrack_rfs_params {
  mptrack_polar_region region;
  mptrack_polar_noise noise;     /* Doppler unused */
  float scan_period_s;           /* nominal scan period [s] */
  float max_gap_s;               /* a later scan drops the target mixture [s] */
  float accel_var_m2ps4;         /* CV white-acceleration variance per axis [m^2/s^4] */
  float survival_prob;           /* p_S [-] */
  float birth_rate;              /* expected births per scan [-] */
  float birth_velocity_std_mps;  /* velocity std of a birth component [m/s] */
  int use_amplitude;             /* non-zero: amplitude likelihoods */
  float amplitude_threshold;     /* detector threshold d on the normalised envelope [-] */
  float target_power_prior;      /* prior mean of 1 + SNR at birth [-] */
  float detection_prob;          /* P_D when use_amplitude is 0 [-] */
  mptrack_rfs_clutter_mode clutter_mode;
  float clutter_rate;            /* known (or prior) clutter detections per scan [-] */
  float clutter_scale;           /* known (or prior) clutter Weibull scale, normalised [-] */
  float hotspot_half_width_range_m;     /* hot-spot seed box half-width in range [m] */
  float hotspot_half_width_azimuth_rad; /* ... in azimuth [rad] */
  float gate_probability;        /* kinematic gate probability [-] */
  float extract_threshold;       /* GM-PHD / GM-CPHD: report components above this weight [-] */
  float existence_extract;       /* CBMeMBer: report tracks with existence above this [-] */
} mptrack_rfs_params;

/* RfsFilterParams's defaults in polar space, with a 500 m x 2 deg hot-spot
 * box (the Cartesian default of 30 would be 30 rad). */
void mptrack_rfs_default_params(mptrack_rfs_params* params);

#define MPTRACK_GMPHD_STORAGE_BYTES 253952u    /* 248 KiB: GM-PHD or GM-CPHD, DefaultCaps (~242 KiB) */
#define MPTRACK_CBMEMBER_STORAGE_BYTES 614400u /* 600 KiB: CBMeMBer, DefaultCaps (~595 KiB) */
typedef union mptrack_gmphd_storage {
  unsigned char bytes[MPTRACK_GMPHD_STORAGE_BYTES];
  uint64_t align_u64;
  double align_double;
  void* align_pointer;
} mptrack_gmphd_storage;
typedef union mptrack_cbmember_storage {
  unsigned char bytes[MPTRACK_CBMEMBER_STORAGE_BYTES];
  uint64_t align_u64;
  double align_double;
  void* align_pointer;
} mptrack_cbmember_storage;

size_t mptrack_gmphd_size(void);
size_t mptrack_gmphd_alignment(void);
mptrack_status mptrack_gmphd_init(void* memory, size_t size, const mptrack_rfs_params* params,
                                  mptrack_tracker** tracker, mptrack_param_error* error);
/* GM-CPHD: same storage as GM-PHD (mptrack_gmphd_storage). */
size_t mptrack_gmcphd_size(void);
size_t mptrack_gmcphd_alignment(void);
mptrack_status mptrack_gmcphd_init(void* memory, size_t size, const mptrack_rfs_params* params,
                                   mptrack_tracker** tracker, mptrack_param_error* error);
size_t mptrack_cbmember_size(void);
size_t mptrack_cbmember_alignment(void);
mptrack_status mptrack_cbmember_init(void* memory, size_t size, const mptrack_rfs_params* params,
                                     mptrack_tracker** tracker, mptrack_param_error* error);

/* ---- every tracker -------------------------------------------------------- */

/* Consumes one scan (copied into the tracker's memory; scan may be reused
 * at once). Refused whole, tracker unchanged: MPTRACK_NOT_INITIALIZED,
 * MPTRACK_OUT_OF_ORDER, and MPTRACK_CAPACITY_EXCEEDED when num_detections >
 * mptrack_max_detections() (counted in scans_over_detection_cap). Accepted:
 * MPTRACK_OK, MPTRACK_PARTIAL or MPTRACK_CAPACITY_EXCEEDED (tracker_contract.h). */
mptrack_status mptrack_step(mptrack_tracker* tracker, const mptrack_scan* scan);
/* End of data: finalises every scan held back by a window smoother. */
mptrack_status mptrack_flush(mptrack_tracker* tracker);
/* Scans finalised by the last step()/flush() (0 after a refused call). */
size_t mptrack_num_outputs(const mptrack_tracker* tracker);
/* Time, scan index and track count of finalised scan `output` (0-based,
 * < mptrack_num_outputs(); otherwise MPTRACK_INVALID_ARGUMENT). */
mptrack_status mptrack_output(const mptrack_tracker* tracker, size_t output, mptrack_output_info* info);
/* Copies up to capacity tracks of finalised scan `output`; *count = tracks
 * copied. MPTRACK_CAPACITY_EXCEEDED if the scan has more than capacity. */
mptrack_status mptrack_output_tracks(const mptrack_tracker* tracker, size_t output, mptrack_track* tracks,
                                     size_t capacity, size_t* count);
/* The provisional (lag-0) estimate of the scan the last mptrack_step()
 * consumed, before it is final (window smoothers: MF-BP with slide <
 * window_length; on steps between windows the last window's estimate
 * predicted to the scan; docs/algorithms/mfbp.md "Provisional output").
 * Fills *info and copies up to capacity tracks as mptrack_output_tracks
 * does; MPTRACK_INVALID_ARGUMENT when the last call left none (before the
 * first window, flush(), a refused scan, or a tracker whose outputs have no
 * lag). */
mptrack_status mptrack_provisional(const mptrack_tracker* tracker, mptrack_output_info* info, mptrack_track* tracks,
                                   size_t capacity, size_t* count);
mptrack_status mptrack_get_counters(const mptrack_tracker* tracker, mptrack_counters* counters);
size_t mptrack_max_detections(const mptrack_tracker* tracker);  /* per scan */
size_t mptrack_max_tracks(const mptrack_tracker* tracker);      /* per finalised scan */
/* Ends the tracker; its memory may then be reused. */
void mptrack_deinit(mptrack_tracker* tracker);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif /* MPTRACK_C_MPTRACK_C_H */
