// Loopy belief propagation for the data association of one scan
// (docs/algorithms/mfbp.md §Evidence and association, seed 000 eqs. (99)-(102),
// Appendix B of the paper).
//
// Sources: targets i (one-to-one, constraint E^t_i), clutter components
// tau (one-to-many, E^c_tau; tau = 0 is the uniform component, always
// present) and measurements j (exactly one source each, I_j).
// Target-measurement edges are sparse (only gated pairs are stored), the
// clutter side is dense (few components). Local evidence is given in the
// log domain and rescaled per measurement by its maximum before
// exponentiation (docs/algorithms/mfbp.md §Evidence and association). Leave-one-out
// sums use prefix and suffix sums, not S - rho, which loses precision when one source
// dominates (same section). Products prod(1 + phi) are sums of log1p.
// The damped messages are eta (docs/algorithms/mfbp.md §Departures from the paper).
//
// Shared: MF-BP runs it over targets and clutter components; multipath
// MF-BP over (target, path) pseudo-targets with the uniform clutter source
// only (docs/algorithms/multipath.md §Association).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "mptrack/math/detmath.h"
#include "mptrack/status.h"

namespace mptrack::assoc {

template <class T, std::size_t MaxTargets, std::size_t MaxMeas, std::size_t MaxSources,
          std::size_t MaxEdges>
class AssociationBp {
 public:
  static_assert(MaxEdges < 65536 && MaxMeas < 65536, "16-bit edge and measurement indices");
  static_assert(MaxSources < 256 && MaxMeas * MaxSources < 65536, "8-bit source, 16-bit list indices");

  /// Log-evidence marking a gated-out clutter pair (its theta is exactly 0).
  static constexpr T kGatedOut = T(-1e30);

  struct Result {
    std::size_t iterations = 0;
    bool converged = false;
  };

  /// Starts a new problem with num_meas measurements and num_sources
  /// clutter sources (uniform first). Every clutter log-evidence starts
  /// gated out; the uniform's absence evidence is 0, the others' 1.
  Status reset(std::size_t num_meas, std::size_t num_sources) {
    if (num_meas > MaxMeas || num_sources > MaxSources || num_sources < 1) {
      return Status::kCapacityExceeded;
    }
    nm_ = num_meas;
    nc_ = num_sources;
    nt_ = 0;
    ne_ = 0;
    for (std::size_t t = 0; t < nc_; ++t) {
      theta_c0_[t] = t == 0 ? T(0) : T(1);
      for (std::size_t j = 0; j < nm_; ++j) theta_c_[t][j] = kGatedOut;
    }
    return Status::kOk;
  }

  /// Adds a target with missed-detection ratio theta0 (absolute; docs/algorithms/mfbp.md
  /// §Evidence and association).
  /// Its edges follow with add_edge(). Returns kCapacityExceeded when full.
  Status add_target(T theta0) {
    if (nt_ == MaxTargets) return Status::kCapacityExceeded;
    theta_t0_[nt_] = theta0;
    edge_begin_[nt_] = static_cast<std::uint16_t>(ne_);
    edge_end_[nt_] = static_cast<std::uint16_t>(ne_);
    ++nt_;
    return Status::kOk;
  }

  /// Edge (last added target, measurement j) with log-evidence ln theta^t_ij.
  Status add_edge(std::size_t j, T log_theta) {
    if (nt_ == 0 || j >= nm_) return Status::kInvalidArgument;
    if (ne_ == MaxEdges) return Status::kCapacityExceeded;
    edge_meas_[ne_] = static_cast<std::uint16_t>(j);
    theta_e_[ne_] = log_theta;
    ++ne_;
    edge_end_[nt_ - 1] = static_cast<std::uint16_t>(ne_);
    return Status::kOk;
  }

  void set_clutter_log(std::size_t tau, std::size_t j, T log_theta) { theta_c_[tau][j] = log_theta; }
  void set_clutter_absent(std::size_t tau, T theta0) { theta_c0_[tau] = theta0; }
  /// Adds delta to every gated-in clutter log-evidence of measurement j
  /// (before run()): a per-measurement factor e^delta on "j is clutter",
  /// the NEMP message of docs/algorithms/nemp.md §NEMP loop.
  void add_clutter_log(std::size_t j, T delta) {
    for (std::size_t t = 0; t < nc_; ++t) {
      if (theta_c_[t][j] > T(-1e29)) theta_c_[t][j] += delta;
    }
  }

  /// Runs damped loopy BP (docs/algorithms/mfbp.md §Evidence and association) and
  /// computes the beliefs.
  Result run(T damping, T tolerance, std::size_t max_iterations) {
    exponentiate_evidence();
    build_measurement_index();
    build_active_lists();
    for (std::size_t e = 0; e < ne_; ++e) eta_e_[e] = T(1);
    for (std::size_t t = 0; t < nc_; ++t) {
      for (std::size_t j = 0; j < nm_; ++j) eta_c_[t][j] = T(1);
    }
    Result res;
    for (std::size_t it = 0; it < max_iterations; ++it) {
      res.iterations = it + 1;
      measurement_side(false);
      const T delta = target_and_clutter_side(damping);
      if (delta < tolerance) {
        res.converged = true;
        break;
      }
    }
    measurement_side(true);
    compute_beliefs();
    return res;
  }

  std::size_t num_targets() const { return nt_; }
  std::size_t num_meas() const { return nm_; }
  std::size_t num_sources() const { return nc_; }
  std::size_t edge_begin(std::size_t i) const { return edge_begin_[i]; }
  std::size_t edge_end(std::size_t i) const { return edge_end_[i]; }
  std::size_t edge_meas(std::size_t e) const { return edge_meas_[e]; }
  /// a_hat^t_ij of edge e.
  T edge_belief(std::size_t e) const { return belief_e_[e]; }
  /// a_hat^t_i0: probability that target i is missed.
  T missed_belief(std::size_t i) const { return belief_t0_[i]; }
  /// Lambda_i = sum_j>=1 phi^t_ij: extrinsic evidence for the visibility chain.
  T lambda(std::size_t i) const { return lambda_[i]; }
  /// a_hat^c_tau,j, j >= 1 (measurement-side normalisation).
  T clutter_belief(std::size_t tau, std::size_t j) const { return rho_c_[tau][j]; }
  /// a_hat^c_tau,0: probability that component tau generated nothing.
  T clutter_absent_belief(std::size_t tau) const { return belief_c0_[tau]; }

 private:
  static constexpr T kTiny = T(1e-30);

  static constexpr T kBig = T(1e30);

  static T safe_div(T num, T den) { return num / (den > kTiny ? den : kTiny); }
  static T saturate(T x) { return x < kBig ? x : kBig; }

  void exponentiate_evidence() {
    for (std::size_t j = 0; j < nm_; ++j) max_log_[j] = kGatedOut;
    for (std::size_t e = 0; e < ne_; ++e) {
      const std::size_t j = edge_meas_[e];
      if (theta_e_[e] > max_log_[j]) max_log_[j] = theta_e_[e];
    }
    for (std::size_t t = 0; t < nc_; ++t) {
      for (std::size_t j = 0; j < nm_; ++j) {
        if (theta_c_[t][j] > max_log_[j]) max_log_[j] = theta_c_[t][j];
      }
    }
    for (std::size_t e = 0; e < ne_; ++e) {
      theta_e_[e] = to_linear(theta_e_[e], max_log_[edge_meas_[e]]);
    }
    for (std::size_t t = 0; t < nc_; ++t) {
      for (std::size_t j = 0; j < nm_; ++j) theta_c_[t][j] = to_linear(theta_c_[t][j], max_log_[j]);
    }
  }

  static T to_linear(T log_theta, T max_log) {
    if (!(log_theta > T(-1e29))) return T(0);
    const T d = log_theta - max_log;
    return d < T(-80) ? T(0) : dmath::dexp(d);
  }

  // Counting sort of the edges by measurement: deterministic order (target
  // index within each measurement).
  void build_measurement_index() {
    for (std::size_t j = 0; j <= nm_; ++j) meas_start_[j] = 0;
    for (std::size_t e = 0; e < ne_; ++e) ++meas_start_[edge_meas_[e] + 1u];  // <= MaxEdges < 65536
    for (std::size_t j = 0; j < nm_; ++j) {
      meas_start_[j + 1] = static_cast<std::uint16_t>(meas_start_[j + 1] + meas_start_[j]);
    }
    for (std::size_t j = 0; j < nm_; ++j) fill_[j] = meas_start_[j];
    for (std::size_t e = 0; e < ne_; ++e) meas_edges_[fill_[edge_meas_[e]]++] = static_cast<std::uint16_t>(e);
  }

  // Per measurement, the clutter sources with theta > 0 (gated-in), and
  // the list of "coupled" measurements whose messages can change: those
  // with a target edge or more than one clutter source. The others (e.g. a
  // point only the uniform component can explain) send constant messages.
  void build_active_lists() {
    std::size_t n = 0;
    n_coupled_ = 0;
    for (std::size_t j = 0; j < nm_; ++j) {
      act_start_[j] = static_cast<std::uint16_t>(n);
      for (std::size_t t = 0; t < nc_; ++t) {
        if (theta_c_[t][j] > T(0)) act_src_[n++] = static_cast<std::uint8_t>(t);
        phi_c_[t][j] = T(0);
        rho_c_[t][j] = T(0);
      }
      const std::size_t n_act = n - act_start_[j];
      if (meas_start_[j + 1] > meas_start_[j] || n_act > 1) coupled_[n_coupled_++] = static_cast<std::uint16_t>(j);
    }
    act_start_[nm_] = static_cast<std::uint16_t>(n);
  }

  // I_j side: phi = theta / (sum of the other sources' rho), seed 000 eqs. (99)-(100).
  // all = false: coupled measurements only (inside the loop); true: every one.
  void measurement_side(bool all) {
    const std::size_t count = all ? nm_ : n_coupled_;
    for (std::size_t q = 0; q < count; ++q) measurement_messages(all ? q : coupled_[q]);
  }

  // One measurement's messages. Each leave-one-out sum is prefix + suffix
  // (the same additions in the same order as a separate prefix, suffix and
  // message pass), fused into a forward pass (rho and its prefix sums) and
  // a backward pass (suffix sums and messages): fewer passes over the list.
  // eta_c_[0][j] stays 1 (E^c of the uniform is off), so the uniform's rho
  // is theta * 1 = theta exactly, as before.
  void measurement_messages(std::size_t j) {
    const std::size_t e_begin = meas_start_[j], e_end = meas_start_[j + 1];
    const std::size_t a_begin = act_start_[j], a_end = act_start_[j + 1];
    std::size_t L = 0;
    prefix_[0] = T(0);
    for (std::size_t k = e_begin; k < e_end; ++k, ++L) {
      const std::size_t e = meas_edges_[k];
      rho_[L] = theta_e_[e] * eta_e_[e];
      prefix_[L + 1] = prefix_[L] + rho_[L];
    }
    for (std::size_t a = a_begin; a < a_end; ++a, ++L) {
      const std::size_t t = act_src_[a];
      rho_[L] = theta_c_[t][j] * eta_c_[t][j];
      prefix_[L + 1] = prefix_[L] + rho_[L];
    }
    S_[j] = prefix_[L];
    T suffix = T(0);
    for (std::size_t a = a_end; a-- > a_begin;) {
      --L;
      const std::size_t t = act_src_[a];
      phi_c_[t][j] = safe_div(theta_c_[t][j], prefix_[L] + suffix);
      rho_c_[t][j] = rho_[L];
      suffix += rho_[L];
    }
    for (std::size_t k = e_end; k-- > e_begin;) {
      --L;
      const std::size_t e = meas_edges_[k];
      phi_e_[e] = safe_div(theta_e_[e], prefix_[L] + suffix);
      suffix += rho_[L];
    }
  }

  // E^t_i side (seed 000 eq. (101)) and E^c_tau side (seed 000 eq. (102)), damped;
  // returns max |d eta|.
  T target_and_clutter_side(T damping) {
    T delta = T(0);
    for (std::size_t i = 0; i < nt_; ++i) {
      // Leave-one-out sums over [theta^t_i0 (= phi^t_i0), phi of the edges]
      // as in measurement_messages(): a forward pass of prefix sums, then
      // the edges backwards with the suffix sum (the missed entry's own
      // leave-one-out sum is never used). delta is a max: order-free.
      const std::size_t e_begin = edge_begin_[i], e_end = edge_end_[i];
      prefix_[0] = T(0);
      prefix_[1] = prefix_[0] + theta_t0_[i];
      std::size_t L = 1;
      for (std::size_t e = e_begin; e < e_end; ++e, ++L) prefix_[L + 1] = prefix_[L] + phi_e_[e];
      T suffix = T(0);
      for (std::size_t e = e_end; e-- > e_begin;) {
        --L;
        const T fresh = safe_div(T(1), prefix_[L] + suffix);
        suffix += phi_e_[e];
        const T updated = damping * eta_e_[e] + (T(1) - damping) * fresh;
        const T d = updated > eta_e_[e] ? updated - eta_e_[e] : eta_e_[e] - updated;
        delta = d > delta ? d : delta;
        eta_e_[e] = updated;
      }
    }
    for (std::size_t t = 1; t < nc_; ++t) {
      // (seed 000 eq. (102)): eta_tau,j = 1 / (1 + theta0 / prod_{j' != j} (1 + phi_j')).
      // The leave-one-out products come from prefix and suffix products
      // saturated at kBig (factors are >= 1, so saturation is monotone and
      // theta0 / kBig is negligible); this replaces a sum of logs
      // (same purpose: no overflow) without a transcendental per pair.
      // Gated-out pairs (theta = 0, phi = 0) contribute a factor 1 and their
      // eta is never used, so they are skipped (sparsity, docs/algorithms/mfbp.md
      // §Departures from the paper).
      if (!(theta_c0_[t] > T(0))) continue;  // E^c off: eta stays 1
      std::size_t n = 0;
      cprefix_[0] = T(1);
      for (std::size_t j = 0; j < nm_; ++j) {
        if (!(theta_c_[t][j] > T(0))) continue;
        cj_[n] = static_cast<std::uint16_t>(j);
        cfac_[n] = T(1) + phi_c_[t][j];
        cprefix_[n + 1] = saturate(cprefix_[n] * cfac_[n]);
        ++n;
      }
      T suffix = T(1);
      for (std::size_t a = n; a-- > 0;) {
        const std::size_t j = cj_[a];
        const T loo = saturate(cprefix_[a] * suffix);
        suffix = saturate(suffix * cfac_[a]);
        const T fresh = T(1) / (T(1) + theta_c0_[t] / loo);
        const T updated = damping * eta_c_[t][j] + (T(1) - damping) * fresh;
        const T d = updated > eta_c_[t][j] ? updated - eta_c_[t][j] : eta_c_[t][j] - updated;
        delta = d > delta ? d : delta;
        eta_c_[t][j] = updated;
      }
    }
    return delta;
  }

  void compute_beliefs() {
    for (std::size_t i = 0; i < nt_; ++i) {
      T lam = T(0);
      for (std::size_t e = edge_begin_[i]; e < edge_end_[i]; ++e) lam += phi_e_[e];
      const T phi_total = theta_t0_[i] + lam;
      lambda_[i] = lam;
      belief_t0_[i] = safe_div(theta_t0_[i], phi_total);
      for (std::size_t e = edge_begin_[i]; e < edge_end_[i]; ++e) {
        belief_e_[e] = safe_div(phi_e_[e], phi_total);
      }
    }
    for (std::size_t t = 0; t < nc_; ++t) {
      T prod = T(1);
      for (std::size_t j = 0; j < nm_; ++j) {
        rho_c_[t][j] = safe_div(rho_c_[t][j], S_[j]);  // now the belief a_hat^c
        if (t > 0 && theta_c_[t][j] > T(0)) prod = saturate(prod * (T(1) + phi_c_[t][j]));
      }
      // a_tau0 = theta0 / (prod(1 + phi) + theta0)  (0 for the uniform)
      belief_c0_[t] = t == 0 ? T(0) : theta_c0_[t] / (prod + theta_c0_[t]);
    }
  }

  static constexpr std::size_t kMaxList = MaxTargets + MaxSources + 1;

  std::size_t nm_ = 0, nc_ = 0, nt_ = 0, ne_ = 0;
  // targets
  std::array<T, MaxTargets> theta_t0_{};
  std::array<std::uint16_t, MaxTargets> edge_begin_{}, edge_end_{};
  std::array<T, MaxTargets> belief_t0_{}, lambda_{};
  // edges
  std::array<std::uint16_t, MaxEdges> edge_meas_{};
  std::array<T, MaxEdges> theta_e_{}, eta_e_{}, phi_e_{}, belief_e_{};
  // measurement index
  std::array<std::uint16_t, MaxMeas + 1> meas_start_{};
  std::array<std::uint16_t, MaxMeas> fill_{};
  std::array<std::uint16_t, MaxEdges> meas_edges_{};
  std::array<T, MaxMeas> max_log_{}, S_{}, cfac_{};
  std::array<T, MaxMeas + 1> cprefix_{};
  std::array<std::uint16_t, MaxMeas> cj_{};
  // clutter
  std::array<T, MaxSources> theta_c0_{}, belief_c0_{};
  std::array<std::array<T, MaxMeas>, MaxSources> theta_c_{}, eta_c_{}, phi_c_{};
  std::array<std::array<T, MaxMeas>, MaxSources> rho_c_{};  ///< rho^c, then the belief a_hat^c
  // active clutter sources per measurement, coupled measurements
  std::array<std::uint16_t, MaxMeas + 1> act_start_{};
  std::array<std::uint8_t, MaxMeas * MaxSources> act_src_{};
  std::array<std::uint16_t, MaxMeas> coupled_{};
  std::size_t n_coupled_ = 0;
  // scratch
  std::array<T, kMaxList + MaxEdges> rho_{};
  std::array<T, kMaxList + MaxEdges + 1> prefix_{};
};

}  // namespace mptrack::assoc
