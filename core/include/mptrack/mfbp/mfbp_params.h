// Run-time parameters of the MF-BP tracker (seed 000, "MP-RMTT").
//
// Every default equals the paper's Sec. IV value (spec 4.5) or the spec's
// [impl]/[fix] default (spec 7), except five [impl] choices of ours, each
// measured in docs/results/seed000-s1.md. The spec-7 switches are fields here
// so the paper-literal behaviour can be restored for reproduction: pd_model
// (A15), amp_loglik (A2), snr_update (A6), nw_forgetting (A9),
// clutter_rate_in_da (A4), component_absent_evidence (A5), gate_chi2 (A29).
// Ours, with the paper's setting: association_cavity (false),
// unresolved_chi2 (0), manoeuvre_noise_var_max (= process_noise_var = 0.01,
// A19), delete_run (3), report_existence_min (0.5; the one-scan tolerance
// stays). Not implemented:
// `smoother = paper` (A10; only the backward-statistics smoother exists)
// and `meas_update = ekf` (A14; cubature only). Units are in the names or
// the comments. validate() is what MfbpTracker::init() runs once; nothing
// is re-checked per scan.
#pragma once

#include <cstddef>
#include <cstdint>

#include <Eigen/Core>

#include "mptrack/model/clutter_mode.h"
#include "mptrack/status.h"
#include "mptrack/validate.h"

namespace mptrack {

/// Detection-probability model (spec 2.4, A15).
enum class PdModel : std::uint8_t {
  kExact,  ///< Pd = e^-x sum_{l<n} x^l/l!, x = n d^2/(1+snr) (Gamma(n) power), default
  kPaper,  ///< (P9) Pd = e^(-n d^2/(1+snr)); identical for Swerling I
};

/// Expected amplitude log-likelihood used by the association (spec 2.5, A2).
enum class AmpLoglik : std::uint8_t {
  kExact,  ///< -n(ln b - psi(a)) - n(m^2-d^2) a/b, default
  kPaper,  ///< (P80/86/109) (2n-1)ln m - n m^2 a/b + n/(2(a-2)); needs a > 2
};

/// Target SNR inverse-Gamma update (spec 3.9, A6).
enum class SnrUpdate : std::uint8_t {
  kMf,     ///< a += n w, b += n sum a_ij (m^2-d^2), default
  kPaper,  ///< (P48) a += n, b += n sum a_ij (m^2-d^2)/w (guarded by w > w_min)
};

/// Wishart forgetting between scans (spec 2.8, A9).
enum class NwForgetting : std::uint8_t {
  kMeanPreserving,  ///< W <- W / xi_W (covariance-like W^-1 <- xi_W W^-1), default
  kPaper,           ///< W <- xi_W W (literal; diverges over long runs)
};

/// Clutter model used by the association (model/clutter_mode.h). MF-BP
/// implements kEstimatedMap (MP-RMTT, default), kKnownRateUniform
/// (MP-RMTT-NCE, rate uniform_rate_per_scan) and kKnownMap (MP-RMTT-KCE,
/// map in known_clutter); validate() rejects the others.
using ClutterMode = model::ClutterMode;

/// One known non-uniform clutter component (measurement space), for kKnown.
template <class T>
struct KnownClutterComponent {
  T rate_per_scan = T(0);                                        ///< expected count per scan [-]
  Eigen::Matrix<T, 2, 1> mean = Eigen::Matrix<T, 2, 1>::Zero();  ///< [range m, azimuth rad]
  Eigen::Matrix<T, 2, 2> covariance = Eigen::Matrix<T, 2, 2>::Identity();  ///< [m^2, m rad; ., rad^2]
  T cnr = T(1);                                                  ///< mean CNR, linear [-]
};

/// The clutter map for ClutterMode::kKnown (Table III; rates may be updated
/// between scans with MfbpTracker::set_known_clutter()).
/// Known components a Params struct can describe (independent of Caps so
/// that MfbpParams<T> is one type for every caps preset; the tracker uses
/// the first min(num_components, Caps::kMaxClutterComponents)).
constexpr std::size_t kMaxKnownClutterComponents = 8;

template <class T>
struct KnownClutter {
  T uniform_rate_per_scan = T(30);  ///< expected uniform clutter count per scan [-]
  T uniform_cnr = T(1);             ///< uniform CNR, linear (spec A17: sigma_0 = 1) [-]
  std::size_t num_components = 0;   ///< used entries of components (<= kMaxKnownClutterComponents)
  KnownClutterComponent<T> components[kMaxKnownClutterComponents];
};

/// All tunables of MfbpTracker. Defaults: seed000 paper values (spec 4.5)
/// with the spec's recommended fixes (spec 7).
template <class T>
struct MfbpParams {
  // --- surveillance region (spec 4.1, A20) ---
  T r_min_m = T(10000);               ///< min range [m]
  T r_max_m = T(50000);               ///< max range [m]
  T az_min_rad = T(0.17453292519943295);  ///< min azimuth [rad] (10 deg)
  T az_max_rad = T(1.0471975511965976);   ///< max azimuth [rad] (60 deg)

  // --- kinematics (spec 2.1, 2.6) ---
  T max_gap_s = T(60);                ///< a scan later than this after the previous one restarts
                                      ///< the tracker (scan_clock.h, docs/reliability.md F1) [s]
  T scan_period_s = T(1.25);          ///< nominal T [s]; only used for birth gates and the
                                      ///< first prediction; dt comes from the timestamps
  T process_noise_var = T(0.01);      ///< sigma_v^2 [(m/s^2)^2] (white-acceleration CV model) while
                                      ///< the CV model holds (paper, spec 2.1)
  T manoeuvre_noise_var_max = T(1);   ///< [impl] ceiling of the manoeuvre-adaptive level
                                      ///< (MfbpTracker::manoeuvre_noise): the paper's 0.01 cannot
                                      ///< follow S1's |a_y| = 0.33 m/s^2 for 122 s (spec 4.1, A19).
                                      ///< At or below process_noise_var: fixed level (paper)
                                      ///< [(m/s^2)^2]
  T manoeuvre_fading = T(0.97);       ///< [impl] fading factor rho of the innovation mean
                                      ///< (memory ~1/(1 - rho) = 33 scans) [-]
  T sigma_r_m = T(20);                ///< range noise std [m]
  T sigma_az_rad = T(0.010471975511965976);  ///< azimuth noise std [rad] (0.6 deg)
  T gate_chi2 = T(30);                ///< target gate on e^T (S+R)^-1 e (spec A29, 2 dof) [-]
  bool association_cavity = true;     ///< [impl] target evidence from the extrinsic (cavity)
                                      ///< moments: the smoothed belief without the scan's own
                                      ///< pseudo-measurement (see mfbp_tracker.h); false = the
                                      ///< MF belief itself (paper, P79)
  T unresolved_chi2 = T(4);           ///< [impl] tracks whose predicted measurements differ by
                                      ///< less than this (Mahalanobis^2 under Sz_a + Sz_b) score
                                      ///< measurements from their common mean (see
                                      ///< couple_unresolved in mfbp_tracker.h); 0 = off (paper)
  bool unresolved_pooling = true;     ///< [impl] a track coupled by unresolved_chi2 updates its
                                      ///< kinematics on the pooled pseudo-measurement of itself and
                                      ///< its nearest unresolved neighbour (SNR, visibility and
                                      ///< identity stay its own); false = own measurements only
  T clutter_gate_chi2 = T(30);        ///< component gate under E[D] (spec 3.3 optional) [-]

  // --- Doppler (not in the paper [impl]; used only for scans with has_doppler) ---
  bool use_doppler = true;            ///< add radial velocity to likelihood and update when present
  T sigma_doppler_mps = T(1);         ///< radial-velocity noise std [m/s]
  T doppler_span_mps = T(150);        ///< clutter Doppler uniform on [-span, span] [m/s];
                                      ///< |doppler| > span is rejected as invalid

  // --- amplitude (spec 2.4, 2.5) ---
  T amplitude_threshold = T(0.715);   ///< d: detector threshold on the normalised envelope [-]
  T max_amplitude = T(1e4);           ///< larger amplitudes are invalid (measurements_invalid):
                                      ///< m^2 must stay finite in float sums (reliability F4) [-]
  int swerling = 1;                   ///< 1 (n = 1) or 3 (n = 2)
  bool use_amplitude = true;          ///< false: kinematics only (MP-RMTT-KI)
  T pd_no_amplitude = T(0.9);         ///< Pd(s=1) used when use_amplitude == false [-] [impl]
  PdModel pd_model = PdModel::kExact;
  AmpLoglik amp_loglik = AmpLoglik::kExact;
  SnrUpdate snr_update = SnrUpdate::kMf;  ///< with kPaper the SNR IG is not smoothed backward

  // --- SNR / CNR inverse-Gamma (spec 2.2, 2.9, A16) ---
  T forgetting_target = T(1.05);      ///< u^t [-]
  T forgetting_clutter = T(1.05);     ///< u^c [-]
  T ig_birth_shape = T(3);            ///< a at track / component birth [-]
  T ig_birth_scale_factor = T(2);     ///< b = factor * mean(m^2 - d^2) at birth [-]

  // --- visibility Markov chain (spec 2.3, 2.4) ---
  T p_survive = T(0.8);               ///< p_s = P(s_k=1 | s_k-1=1) [-]
  T p_birth = T(0.15);                ///< p_b = P(s_k=1 | s_k-1=0) [-]
  T pd_invisible = T(0.01);           ///< epsilon = Pd(s=0) [-]
  T visibility_at_birth = T(0.5);     ///< f_s [-]

  // --- window and iterations (spec 3.0, 3.11) ---
  std::size_t window_length = 7;      ///< K scans (<= Caps::kMaxWindow); 1 = online filter
  std::size_t slide = 3;              ///< s scans finalised per window (1 <= s <= K)
  std::size_t mp_max_iterations = 3;  ///< r_max^MP (1 = MP-RMTTst, first iteration only)
  T mp_tolerance = T(1e-3);           ///< delta^MP on max |delta a_hat| [-]
  std::size_t bp_max_iterations = 200;  ///< r_max^BP (paper 1000; spec 3.11 caps at 200)
  T bp_tolerance = T(1e-6);           ///< delta^BP on max |delta eta| [-]
  T bp_damping = T(0);                ///< gamma: eta <- gamma eta_old + (1-gamma) eta_new [-].
                                      ///< [impl] Paper 0.9. Damping does not move BP's fixed
                                      ///< point, only the path to it; the association BP converges
                                      ///< undamped (Williams and Lau 2014). S2, float online
                                      ///< filter, 340 scans, ~910 BP runs: gamma 0.9 / 0.5 / 0.3 /
                                      ///< 0 take 147 / 41 / 28 / 16 iterations per run, with 225 /
                                      ///< 15 / 5 / 3 runs at the 200 cap; S2 OSPA (double, 10
                                      ///< runs) equal for 0.5, 0.3 and 0
  T w_min = T(1e-6);                  ///< skip pseudo-measurement updates below this weight (A8) [-]

  // --- clutter (spec 2.7, 2.8, 3.6, 3.8) ---
  ClutterMode clutter_mode = ClutterMode::kEstimate;
  bool clutter_rate_in_da = true;     ///< multiply clutter evidence by lambda_hat (A4)
  T uniform_rate_per_scan = T(30);    ///< known uniform clutter rate for kUniformKnownRate [-]
  T nw_forgetting_factor = T(0.99);   ///< xi_W [-]
  NwForgetting nw_forgetting = NwForgetting::kMeanPreserving;
  T dirichlet_kappa = T(5);           ///< kappa [-]
  T component_absent_evidence = T(1); ///< theta^c_{tau,0} for tau >= 1 (A5); 0 disables E^c
  T uniform_cnr_prior = T(1);         ///< prior mean CNR of the uniform component, linear [-]
  T uniform_cnr_prior_shape = T(3);   ///< IG shape of that prior [-]
  KnownClutter<T> known_clutter{};  ///< used by kKnown only

  // --- track management (spec 2.9, 3.10) ---
  T v_max_x_mps = T(120);             ///< two-point birth gate |dx| <= delta T v_max_x [m/s]
  T v_max_y_mps = T(120);             ///< two-point birth gate [m/s]
  std::size_t birth_max_lag = 3;      ///< L_max: scans between the two birth points (<= 3)
  std::size_t birth_max_per_window = 20;  ///< N_birth,max, ranked by amplitude sum
  bool late_birth = true;             ///< [impl] second birth pass after the MP loop, using the
                                      ///< association beliefs of new scans (see mfbp_tracker.h)
  T unexplained_threshold = T(0.2);   ///< measurement "unexplained" if sum_i a_ij below [-]
  T birth_max_component_share = T(0.9);  ///< [impl] no birth from a measurement that Gaussian
                                         ///< clutter components explain with at least this
                                         ///< probability; 1 = spec 3.10. With 1, S2's chaff
                                         ///< starts ~4 600 tentative tracks per run (vs ~2 000)
                                         ///< and fills the 64-track table on ~40% of scans, so
                                         ///< real targets cannot be born: S2 OSPA 122.7 m vs 89.9
                                         ///< m at 0.9 (docs/results/seed000-s1.md). Lower values
                                         ///< also block targets inside chaff.
  T confirm_threshold = T(0.75);      ///< confirm when b_s(1) >= this at any window scan [-]
  T delete_threshold = T(0.5);        ///< delete after delete_run scans with b_s(1) below [-]
  std::size_t delete_run = 5;         ///< consecutive low-visibility scans before deletion. [impl]
                                      ///< Spec 3.10 says L_max = 3, but with p_s = 0.8 one missed
                                      ///< detection already drops b_s below 0.5, and three misses
                                      ///< of S1's 10/3-SNR target (Pd 0.89) occur in ~1/3 of runs
  std::size_t tentative_timeout_scans = 6;  ///< tentative tracks older than this are dropped
                                            ///< (spec: 2 windows = 2 s = 6 scans)
  T report_existence_min = T(0.1);    ///< report confirmed tracks with b_s(1) >= this at the scan
                                      ///< or at the previous finalised scan [-]. [impl] Spec 3.10
                                      ///< says 0.5 at the scan alone, but p_s = 0.8 puts b_s near
                                      ///< 0.5 (smoother) or 0.09-0.16 (filter) after one missed
                                      ///< detection: ~5% of S1 scans then lose a target, ~20 m of
                                      ///< mean OSPA. S1/S2/S3 sweep: docs/results/seed000-s1.md.

  // --- clutter component birth / death (spec 3.10, [impl]) ---
  bool clutter_birth = true;          ///< grid-seeded birth of Gaussian components
  T clutter_cell_range_m = T(2000);   ///< birth grid cell size in range [m]
  T clutter_cell_az_rad = T(0.06981317007977318);  ///< birth grid cell size in azimuth [rad] (4 deg)
  T clutter_seed_factor = T(10);      ///< seed if count >= max(2 n_scans, factor * mu_cell)
  T clutter_death_count = T(2);       ///< component dies if M_tau < this per scan ... [-]
  std::size_t clutter_death_windows = 2;  ///< ... on all finalised scans of this many windows
};

/// The paper's Sec. IV configuration (spec 4.5) with the spec's fixes:
/// the "mfbp" tracker (window 7, slide 3). Adjust window_length/slide,
/// use_amplitude, clutter_mode or mp_max_iterations for the ablations.
template <class T>
MfbpParams<T> seed000_default_params() {
  return MfbpParams<T>{};
}

/// Checks every documented constraint; kInvalidArgument on the first failure.
///
/// Bounds beyond the sign checks (docs/reliability.md F5, F9, F12): every
/// std is squared in float, the clutter-birth grid has
/// (span_r / clutter_cell_range_m) x (span_az / clutter_cell_az_rad) cells
/// and its seed threshold is clutter_seed_factor x (expected count per
/// cell), whose cell-to-region volume ratio multiplies the clutter rate.
/// The limits below keep all of these finite and the grid sizes and the
/// threshold far inside size_t:
///   r_max_m <= 1e7 m; region volume >= 1e-3 m rad;
///   cells per axis <= 1e6 and range x azimuth cells <= 1e8;
///   one cell at most 1e3 region volumes; clutter_seed_factor <= 1e6;
///   sigma_r_m in [1e-3, 1e5] m, sigma_az_rad in [1e-6, 1] rad,
///   sigma_doppler_mps <= 1e4 m/s, process_noise_var <= 1e6 (m/s^2)^2;
///   rates, IG shapes, dirichlet_kappa, evidence and death counts <= 1e6
///   (uniform rates and dirichlet_kappa >= 1e-6);
///   CNR priors, known CNRs and ig_birth_scale_factor in [1e-6, 1e12]
///   (known CNRs may be 0); forgetting factors in [1, 10]; v_max <= 1e4 m/s;
///   amplitude_threshold <= 1e3.
template <class T>
Status validate(const MfbpParams<T>& p, std::size_t max_window) {
  constexpr T kMaxRangeM = T(1e7);
  constexpr T kMinVolume = T(1e-3);        // [m rad]
  constexpr T kMaxCellsPerAxis = T(1e6);
  constexpr T kMaxSeedCells = T(1e8);      // range x azimuth cells of the birth grid
  constexpr T kMaxCellVolumeRatio = T(1e3);
  constexpr T kMaxSeedFactor = T(1e6);
  constexpr T kMinCount = T(1e-6);         // positive rates and dirichlet_kappa [-]
  constexpr T kMaxCount = T(1e6);          // rates, shapes, Dirichlet kappa [-]
  constexpr T kMaxPower = T(1e12);         // CNR / SNR priors and scales, linear [-]
  MPTRACK_TRY(check_positive(p.r_min_m));
  MPTRACK_TRY(check(is_finite(p.r_max_m) && p.r_max_m > p.r_min_m && !(p.r_max_m > kMaxRangeM)));
  MPTRACK_TRY(check_range(p.az_min_rad, T(-3.141592653589793), T(3.141592653589793)));
  MPTRACK_TRY(check(is_finite(p.az_max_rad) && p.az_max_rad > p.az_min_rad &&
                    p.az_max_rad - p.az_min_rad <= T(6.283185307179586)));
  const T span_r = p.r_max_m - p.r_min_m;
  const T span_a = p.az_max_rad - p.az_min_rad;
  MPTRACK_TRY(check(!(span_r * span_a < kMinVolume)));
  MPTRACK_TRY(check(p.scan_period_s > T(0) && !(p.scan_period_s > T(3600))));
  MPTRACK_TRY(check_range(p.max_gap_s, T(1e-3), T(1e6)));
  MPTRACK_TRY(check(p.process_noise_var > T(0) && !(p.process_noise_var > T(1e6))));
  MPTRACK_TRY(check(p.manoeuvre_noise_var_max > T(0) && !(p.manoeuvre_noise_var_max > T(1e6))));
  MPTRACK_TRY(check(p.manoeuvre_fading >= T(0) && p.manoeuvre_fading < T(1)));
  MPTRACK_TRY(check_range(p.sigma_r_m, T(1e-3), T(1e5)));
  MPTRACK_TRY(check_range(p.sigma_az_rad, T(1e-6), T(1)));
  MPTRACK_TRY(check(p.gate_chi2 > T(0) && !(p.gate_chi2 > T(1e6))));
  MPTRACK_TRY(check(p.clutter_gate_chi2 > T(0) && !(p.clutter_gate_chi2 > T(1e6))));
  MPTRACK_TRY(check(p.unresolved_chi2 >= T(0) && !(p.unresolved_chi2 > T(1e6))));
  MPTRACK_TRY(check_range(p.sigma_doppler_mps, T(1e-3), T(1e4)));
  MPTRACK_TRY(check(p.doppler_span_mps > T(0) && !(p.doppler_span_mps > T(1e6))));
  MPTRACK_TRY(check(p.amplitude_threshold > T(0) && !(p.amplitude_threshold > T(1e3))));
  MPTRACK_TRY(check(p.max_amplitude > p.amplitude_threshold && !(p.max_amplitude > T(1e15))));
  MPTRACK_TRY(check(p.swerling == 1 || p.swerling == 3));
  MPTRACK_TRY(check_open_probability(p.pd_no_amplitude));
  MPTRACK_TRY(check_range(p.forgetting_target, T(1), T(10)));
  MPTRACK_TRY(check_range(p.forgetting_clutter, T(1), T(10)));
  MPTRACK_TRY(check(p.ig_birth_shape > T(2) && !(p.ig_birth_shape > kMaxCount)));
  MPTRACK_TRY(check_range(p.ig_birth_scale_factor, T(1e-6), kMaxPower));
  MPTRACK_TRY(check_open_probability(p.p_survive));
  MPTRACK_TRY(check_open_probability(p.p_birth));
  MPTRACK_TRY(check_open_probability(p.pd_invisible));
  MPTRACK_TRY(check_open_probability(p.visibility_at_birth));
  MPTRACK_TRY(check(p.window_length >= 1 && p.window_length <= max_window));
  MPTRACK_TRY(check(p.slide >= 1 && p.slide <= p.window_length));
  MPTRACK_TRY(check(p.mp_max_iterations >= 1 && p.mp_max_iterations <= 100));
  MPTRACK_TRY(check_positive(p.mp_tolerance));
  MPTRACK_TRY(check(p.bp_max_iterations >= 1 && p.bp_max_iterations <= 100000));
  MPTRACK_TRY(check_positive(p.bp_tolerance));
  MPTRACK_TRY(check(is_finite(p.bp_damping) && p.bp_damping >= T(0) && p.bp_damping < T(1)));
  MPTRACK_TRY(check_positive(p.w_min));
  MPTRACK_TRY(check_range(p.uniform_rate_per_scan, kMinCount, kMaxCount));
  MPTRACK_TRY(check(is_finite(p.nw_forgetting_factor) && p.nw_forgetting_factor > T(0) &&
                    !(p.nw_forgetting_factor > T(1))));
  MPTRACK_TRY(check_range(p.dirichlet_kappa, kMinCount, kMaxCount));
  MPTRACK_TRY(check_range(p.component_absent_evidence, T(0), kMaxCount));
  MPTRACK_TRY(check_range(p.uniform_cnr_prior, T(1e-6), kMaxPower));
  MPTRACK_TRY(check(p.uniform_cnr_prior_shape > T(1) && !(p.uniform_cnr_prior_shape > kMaxCount)));
  MPTRACK_TRY(check(p.v_max_x_mps > T(0) && !(p.v_max_x_mps > T(1e4))));
  MPTRACK_TRY(check(p.v_max_y_mps > T(0) && !(p.v_max_y_mps > T(1e4))));
  MPTRACK_TRY(check(p.birth_max_lag >= 1 && p.birth_max_lag <= 3));
  MPTRACK_TRY(check(p.birth_max_per_window >= 1));
  MPTRACK_TRY(check_open_probability(p.unexplained_threshold));
  MPTRACK_TRY(check_range(p.birth_max_component_share, T(0), T(1)));
  MPTRACK_TRY(check_open_probability(p.confirm_threshold));
  MPTRACK_TRY(check_open_probability(p.delete_threshold));
  MPTRACK_TRY(check(p.delete_run >= 1));
  MPTRACK_TRY(check(p.tentative_timeout_scans >= 1));
  MPTRACK_TRY(check_range(p.report_existence_min, T(0), T(1)));
  MPTRACK_TRY(check_positive(p.clutter_cell_range_m));
  MPTRACK_TRY(check_positive(p.clutter_cell_az_rad));
  MPTRACK_TRY(check(!(span_r > kMaxCellsPerAxis * p.clutter_cell_range_m)));
  MPTRACK_TRY(check(!(span_a > kMaxCellsPerAxis * p.clutter_cell_az_rad)));
  MPTRACK_TRY(check(!((span_r / p.clutter_cell_range_m) * (span_a / p.clutter_cell_az_rad) >
                      kMaxSeedCells)));
  MPTRACK_TRY(check(!(p.clutter_cell_range_m * p.clutter_cell_az_rad >
                      kMaxCellVolumeRatio * span_r * span_a)));
  MPTRACK_TRY(check(p.clutter_seed_factor > T(0) && !(p.clutter_seed_factor > kMaxSeedFactor)));
  MPTRACK_TRY(check_range(p.clutter_death_count, T(0), kMaxCount));
  MPTRACK_TRY(check(p.clutter_death_windows >= 1));
  MPTRACK_TRY(check(p.clutter_mode == ClutterMode::kEstimatedMap ||
                    p.clutter_mode == ClutterMode::kKnownRateUniform ||
                    p.clutter_mode == ClutterMode::kKnownMap));
  const auto& kc = p.known_clutter;
  MPTRACK_TRY(check(kc.num_components <= kMaxKnownClutterComponents));
  if (p.clutter_mode == ClutterMode::kKnown) {
    MPTRACK_TRY(check_range(kc.uniform_rate_per_scan, kMinCount, kMaxCount));
    MPTRACK_TRY(check_range(kc.uniform_cnr, T(0), kMaxPower));
    for (std::size_t c = 0; c < kc.num_components; ++c) {
      const auto& comp = kc.components[c];
      MPTRACK_TRY(check_range(comp.rate_per_scan, T(0), kMaxCount));
      MPTRACK_TRY(check_range(comp.cnr, T(0), kMaxPower));
      const T det = comp.covariance(0, 0) * comp.covariance(1, 1) -
                    comp.covariance(0, 1) * comp.covariance(1, 0);
      MPTRACK_TRY(check(is_finite(det) && det > T(0) && comp.covariance(0, 0) > T(0)));
    }
  }
  return Status::kOk;
}

}  // namespace mptrack
