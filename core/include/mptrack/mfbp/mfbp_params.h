// Run-time parameters of the MF-BP tracker (seed 000, "MP-RMTT").
//
// Defaults are the paper's Sec. IV-A values, with the corrections and the
// choices of docs/algorithms/mfbp.md §Departures from the paper; each
// choice of ours ("Ours." below) is measured in docs/results/seed000-s1.md.
// The corrections with a behavioural effect are fields, so the
// paper-literal behaviour can be restored: pd_model, amp_loglik,
// snr_update, nw_forgetting, clutter_rate_in_da, component_absent_evidence,
// gate_chi2. Ours, with the paper's setting: association_cavity (false),
// unresolved_chi2 (0), manoeuvre_noise_var_max (= accel_var_m2ps4 = 0.01),
// delete_run (3), report_existence_min (0.5; the one-scan tolerance stays).
// Not implemented: the paper's literal smoother formulas and an EKF update.
// The region, noise and amplitude blocks, accel_var_m2ps4, clutter_mode and
// max_gap_s use the names shared by every tracker (tracker_params.h). Units
// are in the names or the comments. MfbpTracker::validate() runs
// MfbpParams::validate() and the caps checks once, in init(); nothing is
// re-checked per scan.
#pragma once

#include <cstddef>
#include <cstdint>

#include <Eigen/Core>

#include "mptrack/status.h"
#include "mptrack/tracker_params.h"
#include "mptrack/validate.h"

namespace mptrack {

/// Detection-probability model (docs/algorithms/models.md §Detection
/// probability; docs/algorithms/mfbp.md §Departures from the paper).
enum class PdModel : std::uint8_t {
  kExact,  ///< Pd = e^-x sum_{l<n} x^l/l!, x = n d^2/(1+snr) (Gamma(n) power), default
  kPaper,  ///< seed 000 eq. (9): Pd = e^(-n d^2/(1+snr)); identical for Swerling I
};

/// Expected amplitude log-likelihood used by the association
/// (docs/algorithms/models.md §Amplitude likelihoods; docs/algorithms/mfbp.md
/// §Departures from the paper).
enum class AmpLoglik : std::uint8_t {
  kExact,  ///< -n(ln b - psi(a)) - n(m^2-d^2) a/b, default
  kPaper,  ///< seed 000 eqs. (80), (86), (109): (2n-1)ln m - n m^2 a/b + n/(2(a-2)); needs a > 2
};

/// Target SNR inverse-Gamma update (docs/algorithms/mfbp.md §Departures from the paper).
enum class SnrUpdate : std::uint8_t {
  kMf,     ///< a += n w, b += n sum a_ij (m^2-d^2), default
  kPaper,  ///< seed 000 eq. (48): a += n, b += n sum a_ij (m^2-d^2)/w (guarded by w > w_min)
};

/// Wishart forgetting between scans (docs/algorithms/mfbp.md §Departures from the paper).
enum class NwForgetting : std::uint8_t {
  kMeanPreserving,  ///< W <- W / xi_W (covariance-like W^-1 <- xi_W W^-1), default
  kPaper,           ///< W <- xi_W W (literal; diverges over long runs)
};

/// One known non-uniform clutter component (measurement space), for kKnownMap.
template <class T>
struct KnownClutterComponent {
  T rate_per_scan = T(0);                                        ///< expected count per scan [-]
  Eigen::Matrix<T, 2, 1> mean = Eigen::Matrix<T, 2, 1>::Zero();  ///< [range m, azimuth rad]
  Eigen::Matrix<T, 2, 2> covariance = Eigen::Matrix<T, 2, 2>::Identity();  ///< [m^2, m rad; ., rad^2]
  T cnr = T(1);                                                  ///< mean CNR, linear [-]
  /// Scan times it exists in, inclusive [us]. The tracker evaluates every
  /// stored scan against the map, so a component that ends while its last
  /// scans are still in the window has to keep explaining them (and one that
  /// starts must not explain the scans before it): the KCE ablation was given
  /// the map of the newest scan only and read chaff on the older window scans
  /// as targets (docs/algorithms/mfbp.md §Clutter chain, ablations).
  std::uint64_t active_from_us = 0;
  std::uint64_t active_until_us = UINT64_MAX;

  bool exists_at(std::uint64_t t_us) const { return active_from_us <= t_us && t_us <= active_until_us; }
  /// Produces clutter on a scan at time t_us.
  bool produces_at(std::uint64_t t_us) const { return rate_per_scan > T(0) && exists_at(t_us); }
};

/// Known components a Params struct can describe (independent of Caps so
/// that MfbpParams<T> is one type for every caps preset; MfbpTracker<T, Caps>
/// refuses more than Caps::kMaxClutterComponents).
constexpr std::size_t kMaxKnownClutterComponents = 8;

/// The clutter map for ClutterMode::kKnownMap (seed 000 Table III; rates may
/// be updated between scans with MfbpTracker::set_known_clutter()).
template <class T>
struct KnownClutter {
  T uniform_rate_per_scan = T(30);  ///< expected uniform clutter count per scan [-]
  /// Uniform CNR, linear [-] (sigma_0 = 1: docs/algorithms/mfbp.md §Departures from the paper).
  T uniform_cnr = T(1);
  std::size_t num_components = 0;   ///< used entries of components (<= kMaxKnownClutterComponents)
  KnownClutterComponent<T> components[kMaxKnownClutterComponents];
};

/// All tunables of MfbpTracker. Defaults: seed 000 Sec. IV-A values with the
/// corrections of docs/algorithms/mfbp.md §Departures from the paper.
/// "Ours." marks a choice of ours (same section), measured in
/// docs/results/seed000-s1.md.
template <class T>
struct MfbpParams {
  // --- surveillance region (docs/algorithms/scenarios.md §Seed 000): 10-50 km, 10-60 deg ---
  PolarRegion<T> region{T(10000), T(50000), T(0.17453292519943295), T(1.0471975511965976)};

  // --- kinematics (seed 000 eq. (103); docs/algorithms/models.md §Polar measurement model) ---
  T max_gap_s = T(60);                ///< a scan later than this after the previous one restarts
                                      ///< the tracker (scan_clock.h, docs/reliability.md F1) [s]
  T scan_period_s = T(1.25);          ///< nominal T [s]; only used for birth gates and the
                                      ///< first prediction; dt comes from the timestamps
  /// Per-axis white-acceleration variance q of the CV model while it holds
  /// (seed 000 eq. (103): sigma_v^2 = 0.01) [m^2/s^4]
  /// (docs/algorithms/models.md §CV motion model).
  T accel_var_m2ps4 = T(0.01);
  T manoeuvre_noise_var_max = T(1);   ///< Ours. Ceiling of the manoeuvre-adaptive level
                                      ///< (target_chain.h, manoeuvre_noise): the paper's 0.01
                                      ///< cannot follow S1's |a_y| = 0.33 m/s^2 for 122 s. At or
                                      ///< below accel_var_m2ps4: fixed level (paper) [m^2/s^4]
  T manoeuvre_fading = T(0.97);       ///< Ours. Fading factor rho of the innovation mean
                                      ///< (memory ~1/(1 - rho) = 33 scans) [-]
  /// Measurement noise: range 20 m, azimuth 0.6 deg; Doppler (not in the
  /// paper; used only for scans with has_doppler) 1 m/s.
  PolarNoise<T> noise{T(20), T(0.010471975511965976), T(1)};
  T gate_chi2 = T(30);                ///< target gate on e^T (S+R)^-1 e, 2 dof [-]
                                      ///< (docs/algorithms/mfbp.md §Departures from the paper)
  bool association_cavity = true;     ///< Ours. Target evidence from the extrinsic (cavity)
                                      ///< moments: the smoothed belief without the scan's own
                                      ///< pseudo-measurement (cavity.h); false = the MF belief
                                      ///< itself (paper, seed 000 eq. (79))
  T unresolved_chi2 = T(4);           ///< Ours. Tracks whose predicted measurements differ by
                                      ///< less than this (Mahalanobis^2 under Sz_a + Sz_b) score
                                      ///< measurements from their common mean (see
                                      ///< couple_unresolved); 0 = off (paper)
  bool unresolved_taper = true;       ///< Ours. In a confirmed track's common mean neighbours
                                      ///< weigh (1 - d2 / unresolved_chi2)^2 (unresolved_weight);
                                      ///< false = equal weights (before 2026-12-07)
  bool unresolved_pooling = true;     ///< Ours. A track coupled by unresolved_chi2 updates its
                                      ///< kinematics on the pooled pseudo-measurement of itself and
                                      ///< its nearest unresolved neighbour (SNR, visibility and
                                      ///< identity stay its own); false = own measurements only
  T clutter_gate_chi2 = T(30);        ///< component gate under E[D] [-]
                                      ///< (docs/algorithms/mfbp.md §Evidence and association)

  // --- Doppler (not in the paper; used only for scans with has_doppler) ---
  bool use_doppler = true;            ///< add radial velocity to likelihood and update when present
  T doppler_span_mps = T(150);        ///< clutter Doppler uniform on [-span, span] [m/s];
                                      ///< |doppler| > span is rejected as invalid

  // --- amplitude (docs/algorithms/models.md §Detection probability, §Amplitude likelihoods) ---
  /// use_amplitude false: kinematics only (MP-RMTT-KI); threshold d 0.715 on
  /// the normalised envelope; Swerling I.
  AmplitudeModel<T> amplitude{true, T(0.715), T(1e4), 1};
  T pd_no_amplitude = T(0.9);         ///< Ours. Pd(s=1) used when amplitude.use_amplitude is false [-]
  PdModel pd_model = PdModel::kExact;
  AmpLoglik amp_loglik = AmpLoglik::kExact;
  SnrUpdate snr_update = SnrUpdate::kMf;  ///< with kPaper the SNR IG is not smoothed backward

  // --- SNR / CNR inverse-Gamma (docs/algorithms/models.md §Inverse-gamma power belief) ---
  T forgetting_target = T(1.05);      ///< u^t [-]
  T forgetting_clutter = T(1.05);     ///< u^c [-]
  T ig_birth_shape = T(3);            ///< a at track / component birth [-]
  T ig_birth_scale_factor = T(2);     ///< b = factor * mean(m^2 - d^2) at birth [-]

  // --- visibility Markov chain (seed 000 eqs. (3), (21); docs/algorithms/mfbp.md §Model) ---
  T p_survive = T(0.8);               ///< p_s = P(s_k=1 | s_k-1=1) [-]
  T p_birth = T(0.15);                ///< p_b = P(s_k=1 | s_k-1=0) [-]
  T pd_invisible = T(0.01);           ///< epsilon = Pd(s=0) [-]
  T visibility_at_birth = T(0.5);     ///< f_s [-]

  // --- window and iterations (docs/algorithms/mfbp.md §Window schedule) ---
  std::size_t window_length = 7;      ///< K scans (<= Caps::kMaxWindow); 1 = online filter
  std::size_t slide = 3;              ///< s scans finalised per window (1 <= s <= K); 1 in
                                      ///< every_scan_smoother_params()
  std::size_t mp_max_iterations = 3;  ///< r_max^MP (1 = MP-RMTTst, first iteration only)
  T mp_tolerance = T(1e-3);           ///< delta^MP on max |delta a_hat| [-]
  std::size_t bp_max_iterations = 200;  ///< r_max^BP (paper 1000; docs/algorithms/mfbp.md
                                        ///< §Departures from the paper)
  T bp_tolerance = T(1e-6);           ///< delta^BP on max |delta eta| [-]
  T bp_damping = T(0);                ///< gamma: eta <- gamma eta_old + (1-gamma) eta_new [-].
                                      ///< Ours; paper 0.9. Damping does not move BP's fixed
                                      ///< point, only the path to it; the association BP converges
                                      ///< undamped (Williams and Lau 2014). S2, float online
                                      ///< filter, 340 scans, ~910 BP runs: gamma 0.9 / 0.5 / 0.3 /
                                      ///< 0 take 147 / 41 / 28 / 16 iterations per run, with 225 /
                                      ///< 15 / 5 / 3 runs at the 200 cap; S2 OSPA (double, 10
                                      ///< runs) equal for 0.5, 0.3 and 0
  T w_min = T(1e-6);                  ///< skip pseudo-measurement updates below this weight [-]
                                      ///< (docs/algorithms/mfbp.md §Departures from the paper)

  // --- clutter (docs/algorithms/mfbp.md §Clutter chain) ---
  ClutterMode clutter_mode = ClutterMode::kEstimatedMap;  ///< kEstimatedMap (MP-RMTT),
                                      ///< kKnownRateUniform (MP-RMTT-NCE, rate
                                      ///< uniform_rate_per_scan) or kKnownMap (MP-RMTT-KCE,
                                      ///< map in known_clutter); validate() rejects the others
  bool clutter_rate_in_da = true;     ///< multiply clutter evidence by lambda_hat
                                      ///< (docs/algorithms/mfbp.md §Departures from the paper)
  T uniform_rate_per_scan = T(30);    ///< known uniform clutter rate for kKnownRateUniform;
                                      ///< also the Dirichlet prior of the estimated uniform
                                      ///< share. 0 is valid (a scene of Gaussian clutter
                                      ///< only): the floor below applies [-]
  T uniform_rate_floor_per_scan = T(1);  ///< Ours. The uniform clutter rate (known or prior,
                                         ///< here and in known_clutter) is used as at least
                                         ///< this, so that the uniform component stays the
                                         ///< catch-all of a measurement nothing else explains
                                         ///< and its log-rate is finite (effective_uniform_rate).
                                         ///< Rates at or above it are used unchanged [-]
  T nw_forgetting_factor = T(0.99);   ///< xi_W [-]
  NwForgetting nw_forgetting = NwForgetting::kMeanPreserving;
  T dirichlet_kappa = T(5);           ///< kappa [-]
  T component_absent_evidence = T(1); ///< theta^c_{tau,0} for tau >= 1; 0 disables E^c
                                      ///< (docs/algorithms/mfbp.md §Departures from the paper)
  T uniform_cnr_prior = T(1);         ///< prior mean CNR of the uniform component, linear [-]
  T uniform_cnr_prior_shape = T(3);   ///< IG shape of that prior [-]
  KnownClutter<T> known_clutter{};  ///< used by kKnownMap only

  // --- track management (docs/algorithms/mfbp.md §Birth, §Confirmation and reporting) ---
  T v_max_x_mps = T(120);             ///< two-point birth gate |dx| <= delta T v_max_x [m/s]
  T v_max_y_mps = T(120);             ///< two-point birth gate [m/s]
  std::size_t birth_max_lag = 3;      ///< L_max: scans between the two birth points (<= 3)
  std::size_t birth_max_per_window = 20;  ///< N_birth,max, ranked by amplitude sum
                                          ///< (<= Caps::kMaxBirthCandidates, mfbp_caps.h)
  bool late_birth = true;             ///< Ours. Second birth pass after the MP loop, using the
                                      ///< association beliefs of new scans (track_spawn.h)
  T unexplained_threshold = T(0.2);   ///< measurement "unexplained" if sum_i a_ij below [-]
  T birth_max_component_share = T(0.9);  ///< Ours. No birth from a measurement that Gaussian
                                         ///< clutter components explain with at least this
                                         ///< probability; 1 = no such test. With 1, S2's chaff
                                         ///< starts ~4 600 tentative tracks per run (vs ~2 000)
                                         ///< and fills the 64-track table on ~40% of scans, so
                                         ///< real targets cannot be born: S2 OSPA 122.7 m vs 89.9
                                         ///< m at 0.9 (docs/results/seed000-s1.md). Lower values
                                         ///< also block targets inside chaff.
  T birth_amplitude_tail = T(0.2);    ///< Ours. A measurement that fails the component-share
                                      ///< test above may still seed a track if its amplitude is
                                      ///< this unlikely under every Gaussian component whose gate
                                      ///< holds it: P(u > m^2 | u > d^2) at the component's mean
                                      ///< CNR (track_birth.h, amplitude_tail; docs/algorithms/
                                      ///< mfbp.md §Birth). 0 = off (the birth path of before) [-]
  T birth_single_point_tail = T(0.1);  ///< Ours. A measurement inside Gaussian clutter whose
                                      ///< amplitude tail (as birth_amplitude_tail) is below
                                      ///< this, outside every track's gate, starts a track
                                      ///< alone (one_point_state), within the
                                      ///< birth_max_in_clutter left after the pairs
                                      ///< (docs/algorithms/mfbp.md §Birth). At most
                                      ///< birth_amplitude_tail; 0 = off [-]
  T birth_in_clutter_max_cnr = T(0);  ///< Ours. The amplitude test above holds only under
                                      ///< components of mean CNR at most this (linear): under
                                      ///< a stronger one a target's amplitude is as likely as
                                      ///< the clutter's and the point is explained
                                      ///< (docs/algorithms/mfbp.md §Birth); 0 = no limit,
                                      ///< 6 in every_scan_smoother_params() [-]
  std::size_t birth_max_in_clutter = 3;  ///< Ours. Births per window whose points passed only
                                         ///< by that amplitude test (inside Gaussian clutter)
  T confirm_threshold = T(0.75);      ///< confirm when b_s(1) >= this at any window scan [-]
  bool tentative_predictive_in_clutter = true;  ///< Ours. A tentative track whose predicted
                                      ///< measurement lies in the gate of a Gaussian clutter
                                      ///< component of lower mean power than its own
                                      ///< (weaker_clutter.h) scores measurements with the
                                      ///< predictive density N(y; z, Sz + R) instead of seed 000
                                      ///< eq. (79)'s MF expectation, and is confirmed at
                                      ///< confirm_threshold_in_clutter (docs/algorithms/mfbp.md
                                      ///< §Birth). false = the paper's evidence everywhere
  T confirm_threshold_in_clutter = T(0.99);  ///< Ours. confirm_threshold of a tentative track
                                      ///< whose smoothed position on the scan lies in such a
                                      ///< component (with tentative_predictive_in_clutter) [-]
  std::size_t confirm_lookahead_in_clutter = 0;  ///< Ours. Such a track confirms only on a
                                      ///< window scan with at least this many window scans after
                                      ///< it (any value: capped at window_length - 1, 0 at
                                      ///< flush()). 2 in every_scan_smoother_params(): with a
                                      ///< window every scan the newest scans' b_s, which rest on
                                      ///< one or two detections, are tested in every window and
                                      ///< confirmed chaff tracks (docs/algorithms/mfbp.md §Window
                                      ///< schedule). 0 = any window scan [scans]
  T filter_confirm_score_in_clutter = T(9.21);  ///< Ours. Online filter (window_length 1) only:
                                      ///< such a track is also confirmed once its score, the sum
                                      ///< of ln(xi(1)/xi(0)) over its scans, reaches this
                                      ///< (9.21 = logit 0.9999; docs/algorithms/mfbp.md §Birth);
                                      ///< 0 = off [nats]
  bool filter_score_in_any_component = true;  ///< Ours. Online filter (window_length 1) only: a
                                      ///< tentative track whose predicted measurement lies in the
                                      ///< gate of any Gaussian clutter component, weaker or not,
                                      ///< is held to confirm_threshold_in_clutter and so to the
                                      ///< score test above, not only one in weaker clutter: a
                                      ///< filter confirms a clutter-born track on two lucky
                                      ///< scans at confirm_threshold (docs/algorithms/mfbp.md
                                      ///< §Birth). false = weaker components only
  T delete_threshold = T(0.5);        ///< delete after delete_run scans with b_s(1) below [-]
  std::size_t delete_run = 5;         ///< consecutive low-visibility scans before deletion. Ours:
                                      ///< the paper deletes after L_max = 3, but with p_s = 0.8
                                      ///< one missed detection already drops b_s below 0.5, and
                                      ///< three misses of S1's 10/3-SNR target (Pd 0.89) occur
                                      ///< in ~1/3 of runs
  std::size_t delete_run_in_clutter = 12;  ///< Ours. delete_run of a confirmed track inside a
                                           ///< Gaussian clutter component at least as strong as
                                           ///< itself (track_management.h, deletion_run): the
                                           ///< clutter explains its detections away, so a run of
                                           ///< misses there says little. At or below delete_run:
                                           ///< off
  std::size_t tentative_timeout_scans = 6;  ///< tentative tracks older than this are dropped
                                            ///< (two windows: docs/algorithms/mfbp.md
                                            ///< §Confirmation and reporting)
  std::size_t tentative_timeout_in_clutter_scans = 10;  ///< Ours. The same for a young track
                                            ///< that must reach confirm_threshold_in_clutter
                                            ///< (confirmation_threshold, track_management.h:
                                            ///< predictive_evidence, or in the online filter
                                            ///< predicted_in_component); at or below
                                            ///< tentative_timeout_scans: off (docs/algorithms/
                                            ///< mfbp.md §Birth)
  T duplicate_chi2 = T(0);            ///< Ours. Two live tracks, at least one confirmed, whose
                                      ///< smoothed 4-D states on the last window scan differ by
                                      ///< less than this Mahalanobis^2 under P_a + P_b are one
                                      ///< target: the younger (or tentative) one is deleted
                                      ///< (track_management.h, suppress_duplicates). 0 = off
                                      ///< (seed 000: its formation pair is two targets that the
                                      ///< pooled tracks keep together); the raw-frame adapter
                                      ///< sets it (docs/algorithms/mfbp.md §Confirmation) [-]
  T report_existence_min = T(0.1);    ///< report confirmed tracks with b_s(1) >= this at the scan
                                      ///< or at the previous finalised scan [-]. Ours: the
                                      ///< paper's threshold is 0.5 at the scan alone, but p_s =
                                      ///< 0.8 puts b_s near 0.5 (smoother) or 0.09-0.16 (filter)
                                      ///< after one missed detection: ~5% of S1 scans then lose
                                      ///< a target, ~20 m of mean OSPA. S1/S2/S3 sweep:
                                      ///< docs/results/seed000-s1.md.

  // --- clutter component birth / death (docs/algorithms/mfbp.md §Birth) ---
  bool clutter_birth = true;          ///< grid-seeded birth of Gaussian components
  T clutter_cell_range_m = T(2000);   ///< birth grid cell size in range [m]
  T clutter_cell_az_rad = T(0.06981317007977318);  ///< birth grid cell size in azimuth [rad] (4 deg)
  T clutter_seed_factor = T(10);      ///< seed if count >= max(2 n_scans, factor * mu_cell)
  bool retire_in_new_clutter = true;  ///< Ours. A new component deletes the tracks born on the
                                      ///< scans it was seeded from whose state lies in its gate:
                                      ///< a cloud's points start tracks until it is a component
                                      ///< (docs/algorithms/mfbp.md §Birth, tracks a new component
                                      ///< explains). false: the paper's behaviour
  T clutter_death_count = T(2);       ///< component dies if M_tau < this per scan ... [-]
  std::size_t clutter_death_windows = 2;  ///< ... on all finalised scans of this many windows

  /// Every documented constraint that does not depend on the caps (below).
  Status validate(ParamError* where = nullptr) const;

 private:
  Status validate_clutter_grid(T span_r, T span_a, T max_cells_per_axis, T max_seed_cells,
                               T max_cell_volume_ratio, T max_seed_factor, T max_count,
                               ParamError* w) const;
  Status validate_known_clutter(T max_count, T max_power, ParamError* w) const;
};

/// A uniform clutter rate as the tracker uses it: at least
/// uniform_rate_floor_per_scan (a scene without uniform clutter, rate 0,
/// keeps a weak catch-all uniform component; docs/algorithms/mfbp.md
/// §Clutter chain). Rates at or above the floor are returned unchanged.
template <class T>
T effective_uniform_rate(T rate_per_scan, const MfbpParams<T>& p) {
  return rate_per_scan < p.uniform_rate_floor_per_scan ? p.uniform_rate_floor_per_scan : rate_per_scan;
}

/// The paper's Sec. IV-A configuration with the corrections of
/// docs/algorithms/mfbp.md §Departures from the paper: the "mfbp" tracker
/// (window 7, slide 3). Adjust window_length/slide, amplitude.use_amplitude,
/// clutter_mode or mp_max_iterations for the ablations.
template <class T>
MfbpParams<T> seed000_default_params() {
  return MfbpParams<T>{};
}

/// The "mfbp-s1" tracker: seed000_default_params() with a window processed at
/// every scan (slide 1), in-clutter confirmation on scans with 2 later
/// window scans (docs/algorithms/mfbp.md §Window schedule) and no amplitude
/// birth under clutter of mean CNR above 6 (§Birth, a CNR limit). A target
/// born inside weaker clutter is confirmed after ~3 scans instead of ~6, and
/// every seed 000 scene's OSPA is lower, for 2-2.5x the mean step time (the
/// p99, one window, is about the same) and a 6-scan output lag.
template <class T>
MfbpParams<T> every_scan_smoother_params() {
  MfbpParams<T> p = seed000_default_params<T>();
  p.slide = 1;
  p.confirm_lookahead_in_clutter = 2;
  // At slide 1 every window offers the amplitude births again, so strong
  // chaff (S2's clouds, CNR 6.7 and 10) feeds them 3x as often as at slide 3.
  // The tail test favours an SNR-10 target over CNR-6 clutter by only 1.8x
  // (t^(varsigma_c / varsigma_t - 1), t = 0.2), and a CNR-4 component's
  // estimate rarely reaches 6 (docs/algorithms/mfbp.md §Birth).
  p.birth_in_clutter_max_cnr = T(6);
  return p;
}

}  // namespace mptrack

#include "mptrack/mfbp/mfbp_params_validate.h"  // IWYU pragma: export
