// Clutter-component birth by grid seeding (our choice: the paper leaves
// component birth open; docs/algorithms/mfbp.md §Birth and §Departures).
//
// Measurements explained by the uniform clutter (or, on a new scan,
// unexplained by the tracks) and outside the gate of every live component
// are pooled over up to K stored scans and counted on a range-azimuth grid
// (at most kMaxClutterGridCells cells: the cells are coarsened until the
// region fits). Connected cells whose count exceeds clutter_seed_factor
// times the uniform expectation (and 2 points per pooled scan) seed a new
// Normal-Wishart component (the prior of eq. (50)) with a CNR inverse gamma
// (eq. (62)) and a Dirichlet weight (eq. (69)) from the points they hold.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "mptrack/mfbp/clutter_birth.h"
#include "mptrack/mfbp/clutter_slot.h"
#include "mptrack/mfbp/mfbp_caps.h"
#include "mptrack/mfbp/mfbp_params.h"
#include "mptrack/mfbp/model_constants.h"
#include "mptrack/mfbp/track_spawn.h"
#include "mptrack/mfbp/window_store.h"
#include "mptrack/model/mahalanobis.h"
#include "mptrack/profile.h"
#include "mptrack/track_report.h"

namespace mptrack::mfbp {

template <class T, class Caps>
class ClutterSpawner {
 public:
  static constexpr std::size_t kMaxMeas = Caps::kMaxMeasurements;
  static constexpr std::size_t kMaxComp = Caps::kMaxClutterComponents;
  static constexpr std::size_t kMaxWindow = Caps::kMaxWindow;
  static constexpr std::size_t kStore = Caps::kMaxWindow;
  static constexpr std::size_t kGridCells = kMaxClutterGridCells<Caps>;
  /// The seed threshold counts at least this many scans (the paper's K = 7).
  static constexpr std::size_t kMinSeedScans = 7;
  using Store = WindowStore<T, Caps>;

  void spawn(std::size_t n, const Store& store, ClutterTable<T, Caps>& cl,
             const TrackSpawner<T, Caps>& births, const MfbpParams<T>& p, const ModelConstants<T>& mc,
             std::uint32_t& next_id, TrackerCounters& counters) {
    MPTRACK_PROFILE_STAGE(g_mfbp, MfbpStage::kBirth);
    const std::size_t pool_first = (store.n_hist() + n > kMaxWindow) ? store.n_hist() + n - kMaxWindow : 0;
    const std::size_t pool_end = store.n_hist() + n;
    const std::size_t n_pool = pool_end - pool_first;
    Grid g{p.clutter_cell_range_m, p.clutter_cell_az_rad, 0};
    if (!reset_grid(g, p)) return;
    mark_pooled(pool_first, pool_end, store, cl, births, p);
    T uniform_total = T(0);
    for (std::size_t si = pool_first; si < pool_end; ++si) {
      const ScanSlot<T, Caps>& s = store.at(si);
      for (std::size_t j = 0; j < s.count; ++j) {
        if (pooled_[si][j] == 0) continue;
        uniform_total += T(1);
        grid_.add(cell_index(s.r[j], s.az[j], g, p));
      }
    }
    const T lambda0 = uniform_total / static_cast<T>(n_pool);
    const T mu_cell = static_cast<T>(n_pool) * lambda0 * g.cell_r * g.cell_a / mc.volume;
    T thr = p.clutter_seed_factor * mu_cell;
    // 2 points per pooled scan, counted as if at least 7 scans (the paper's
    // K) were pooled: with only a few scans pooled (start of an online run)
    // two nearby points - e.g. two targets - would seed a component, and two
    // neighbouring clouds would merge into one seed (our choice).
    const std::size_t n_eff = n_pool > kMinSeedScans ? n_pool : kMinSeedScans;
    const T thr2 = T(2) * static_cast<T>(n_eff);
    if (thr < thr2) thr = thr2;
    const std::size_t threshold = static_cast<std::size_t>(thr) + 1u;  // count >= ceil-ish
    const std::size_t groups = grid_.label_seeds(threshold > 1u ? threshold - 1u : 1u);
    for (std::size_t label = 1; label <= groups; ++label) {
      Seed seed = gather_seed(label, pool_first, pool_end, store, g, p);
      if (!(seed.st.n > thr2 - T(0.5))) continue;
      const std::size_t slot = free_slot(cl);
      if (slot == kMaxComp) {
        ++counters.clutter_cap_hits;
        break;
      }
      start_component(cl.comps[slot], seed, n_pool, p, mc, next_id);
      ++counters.clutter_born;
    }
  }

 private:
  struct Grid {
    T cell_r;        ///< cell size in range [m]
    T cell_a;        ///< cell size in azimuth [rad]
    std::size_t na;  ///< cells per azimuth row
  };
  struct Seed {
    NwStats<T> st{};
    AmplitudeStats<T> as{};
  };

  /// Sets the grid to the params' cells, coarsened until they fit.
  bool reset_grid(Grid& g, const MfbpParams<T>& p) {
    const T span_r = p.region.range_max_m - p.region.range_min_m;
    const T span_a = p.region.azimuth_max_rad - p.region.azimuth_min_rad;
    for (int attempt = 0; attempt < 16; ++attempt) {
      const std::size_t nr = static_cast<std::size_t>(span_r / g.cell_r) + 1u;
      g.na = static_cast<std::size_t>(span_a / g.cell_a) + 1u;
      if (grid_.reset(nr, g.na)) return true;
      g.cell_r *= T(2);
      g.cell_a *= T(2);
    }
    return false;
  }

  static std::size_t cell_index(T r, T az, const Grid& g, const MfbpParams<T>& p) {
    const std::size_t ir = static_cast<std::size_t>((r - p.region.range_min_m) / g.cell_r);
    const std::size_t ia = static_cast<std::size_t>((az - p.region.azimuth_min_rad) / g.cell_a);
    return ir * g.na + ia;
  }

  static std::size_t free_slot(const ClutterTable<T, Caps>& cl) {
    for (std::size_t c = 0; c < kMaxComp; ++c) {
      if (!cl.comps[c].alive) return c;
    }
    return kMaxComp;
  }

  /// Marks in pooled_ the measurements pooled for clutter seeding: explained
  /// by uniform clutter (or, on new scans, unexplained by tracks) and outside
  /// the gate of every live component.
  void mark_pooled(std::size_t first, std::size_t end, const Store& store, const ClutterTable<T, Caps>& cl,
                   const TrackSpawner<T, Caps>& births, const MfbpParams<T>& p) {
    const std::size_t k_ref = store.n_win() > 0 ? store.n_win() - 1 : 0;
    for (std::size_t si = first; si < end; ++si) {
      const ScanSlot<T, Caps>& s = store.at(si);
      for (std::size_t j = 0; j < s.count; ++j) {
        pooled_[si][j] = (s.has_beliefs ? !(s.uniform_share[j] < T(0.5)) : births.unexplained(store, si, j)) ? 1u : 0u;
      }
    }
    for (const auto& cs : cl.comps) {
      if (!cs.alive) continue;
      const NormalWishart<T>& nw = cs.nws[k_ref];
      const model::Mahalanobis2<T> gate(nw.expected_covariance());
      if (!gate.valid()) continue;
      for (std::size_t si = first; si < end; ++si) {
        const ScanSlot<T, Caps>& s = store.at(si);
        for (std::size_t j = 0; j < s.count; ++j) {
          if (pooled_[si][j] == 0) continue;
          const T er = s.r[j] - nw.mu(0);
          const T ea = model::wrap_angle(s.az[j] - nw.mu(1));
          if (gate.distance2(er, ea) < p.clutter_gate_chi2) pooled_[si][j] = 0;
        }
      }
    }
  }

  /// Spatial and amplitude statistics of the pooled points in seed group label.
  Seed gather_seed(std::size_t label, std::size_t first, std::size_t end, const Store& store,
                   const Grid& g, const MfbpParams<T>& p) const {
    Seed seed;
    bool have_ref = false;
    for (std::size_t si = first; si < end; ++si) {
      const ScanSlot<T, Caps>& s = store.at(si);
      for (std::size_t j = 0; j < s.count; ++j) {
        if (pooled_[si][j] == 0) continue;
        if (grid_.label(cell_index(s.r[j], s.az[j], g, p)) != label) continue;
        if (!have_ref) {
          seed.st.ref = Vec2<T>(s.r[j], s.az[j]);
          have_ref = true;
        }
        seed.st.add(Vec2<T>(s.r[j], s.az[j]), T(1));
        seed.as.w += T(1);
        seed.as.s += s.amp[j] * s.amp[j] - p.amplitude.threshold * p.amplitude.threshold;
      }
    }
    return seed;
  }

  static void start_component(CompSlot<T, Caps>& cs, const Seed& seed, std::size_t n_pool,
                              const MfbpParams<T>& p, const ModelConstants<T>& mc, std::uint32_t& next_id) {
    const T N = seed.st.n;
    const Vec2<T> off = seed.st.sum / N;
    Mat2<T> S = seed.st.sum_sq / N - off * off.transpose();
    // Floor the spread at the measurement noise so a tight seed stays SPD.
    S(0, 0) += mc.R(0, 0);
    S(1, 1) += mc.R(1, 1);
    const T per_scan = N / static_cast<T>(n_pool);
    cs = CompSlot<T, Caps>{};
    cs.alive = true;
    cs.id = next_id++;
    cs.nw0.mu = seed.st.ref + off;
    cs.nw0.mu(1) = model::wrap_angle(cs.nw0.mu(1));
    cs.nw0.c = per_scan;
    cs.nw0.nu = per_scan + T(3);
    cs.nw0.w_inv = cs.nw0.nu * S;  // W = S^-1 / nu  =>  W^-1 = nu S
    cs.ig0.a = p.ig_birth_shape;
    T mean_excess = seed.as.s / seed.as.w;
    if (!(mean_excess > T(1e-3))) mean_excess = T(1e-3);
    cs.ig0.b = p.ig_birth_scale_factor * mean_excess;
    cs.alpha0 = per_scan;
    cs.fill_window_with_prior();  // until the next MF sweep
  }

  SeedGrid<kGridCells> grid_{};
  std::array<std::array<std::uint8_t, kMaxMeas>, kStore> pooled_{};  ///< seeding scratch
};

}  // namespace mptrack::mfbp
