// The fused ground tracks of multipath track fusion and the three steps
// per scan of ground_fusion.h (refresh, join, new): docs/algorithms/mptf.md
// §Fusion. Sized by compile-time caps: MaxFused fused tracks, MaxPaths
// members each; candidates are passed in by the tracker.
#pragma once

#include <cstddef>
#include <cstdint>

#include "mptrack/model/spd_guard_scaled.h"
#include "mptrack/mptf/ground_fusion.h"
#include "mptrack/static_vector.h"
#include "mptrack/track_report.h"

namespace mptrack::mptf {

template <class T, std::size_t MaxFused, std::size_t MaxPaths>
class FusionTable {
 public:
  using Cand = Candidate<T, MaxPaths>;
  using Fused = FusedTrack<T, MaxPaths>;

  struct Config {
    std::size_t num_paths = 1;
    T gate_chi2 = T(11.34);
    std::uint32_t min_paths = 2;
    T min_variance = T(1e-14);
    bool defer_ambiguous = false;
  };

  void clear() { fused_.clear(); }
  const StaticVector<Fused, MaxFused>& tracks() const { return fused_; }

  /// One scan. cand[0..n) are in increasing track_id (binary search).
  /// Fused tracks refused at MaxFused count in c.track_cap_hits.
  void update(Cand* cand, std::size_t n, const Config& cfg, TrackerCounters& c, std::uint32_t& next_id) {
    for (std::size_t k = 0; k < n; ++k) cand[k].used = false;
    refresh(cand, n, cfg);
    join(cand, n, cfg);
    while (start_new(cand, n, cfg, c, next_id)) {
    }
  }

 private:
  static constexpr std::size_t kNone = ~std::size_t(0);

  static std::ptrdiff_t find(const Cand* cand, std::size_t n, std::uint32_t id) {
    std::size_t lo = 0, hi = n;
    while (lo < hi) {
      const std::size_t mid = lo + (hi - lo) / 2;
      if (cand[mid].track_id < id) {
        lo = mid + 1;
      } else {
        hi = mid;
      }
    }
    return lo < n && cand[lo].track_id == id ? static_cast<std::ptrdiff_t>(lo) : -1;
  }

  // The information sum of f's members (in path order); false if it has none.
  bool fuse(Fused& f, Cand* cand, std::size_t n, const Config& cfg) {
    bool first = true;
    f.measurement_index = -1;
    for (std::size_t p = 0; p < cfg.num_paths; ++p) {
      if (f.member[p] == 0) continue;
      const Cand& m = cand[find(cand, n, f.member[p])];
      if (first) {
        f.x = m.x[p];
        f.P = m.P[p];
        f.measurement_index = m.measurement_index;
        first = false;
      } else if (!information_fuse(f.x, f.P, m.x[p], m.P[p])) {
        f.member[p] = 0;  // not SPD together: the member leaves
      }
    }
    if (!first) static_cast<void>(model::keep_spd_scaled(f.P, cfg.min_variance));
    return !first;
  }

  void refresh(Cand* cand, std::size_t n, const Config& cfg) {
    std::size_t w = 0;
    for (std::size_t i = 0; i < fused_.size(); ++i) {
      Fused f = fused_[i];
      for (std::size_t p = 0; p < cfg.num_paths; ++p) {
        if (f.member[p] == 0) continue;
        const std::ptrdiff_t k = find(cand, n, f.member[p]);
        if (k < 0 || !cand[k].ok[p] || cand[k].used) f.member[p] = 0;
        if (f.member[p] != 0) cand[k].used = true;
      }
      if (fuse(f, cand, n, cfg) && f.members() > 1) {
        // A member inconsistent with the fused state leaves (it may start or join another).
        bool left = false;
        for (std::size_t p = 0; p < cfg.num_paths; ++p) {
          if (f.member[p] == 0) continue;
          const std::ptrdiff_t k = find(cand, n, f.member[p]);
          if (ground_distance2(cand[k].x[p], cand[k].P[p], f.x, f.P) > cfg.gate_chi2) {
            cand[k].used = false;
            f.member[p] = 0;
            left = true;
          }
        }
        if (left) static_cast<void>(fuse(f, cand, n, cfg));
      }
      if (f.members() == 0) continue;  // no path track left: the fused track ends
      fused_[w++] = f;
    }
    static_cast<void>(fused_.resize(w));  // shrinking cannot fail
  }

  // Closest (free candidate, fused track, free path) first, until none is in the gate.
  void join(Cand* cand, std::size_t n, const Config& cfg) {
    for (;;) {
      T best = cfg.gate_chi2;
      std::size_t bk = kNone, bf = kNone, bp = kNone;
      for (std::size_t k = 0; k < n; ++k) {
        if (cand[k].used) continue;
        for (std::size_t f = 0; f < fused_.size(); ++f) {
          for (std::size_t p = 0; p < cfg.num_paths; ++p) {
            if (fused_[f].member[p] != 0 || !cand[k].ok[p]) continue;
            const T d2 = ground_distance2(cand[k].x[p], cand[k].P[p], fused_[f].x, fused_[f].P);
            if (!(d2 <= best)) continue;
            best = d2;
            bk = k;
            bf = f;
            bp = p;
          }
        }
      }
      if (bk == kNone) return;
      cand[bk].used = true;
      fused_[bf].member[bp] = cand[bk].track_id;
      static_cast<void>(fuse(fused_[bf], cand, n, cfg));
    }
  }

  // For seed (k, p): per other path q, the closest free candidate in the
  // gate (pick[q], or -1). Returns how many paths found one (the seed's included).
  std::uint32_t support(const Cand* cand, std::size_t n, std::size_t k, std::size_t p, const Config& cfg,
                        std::array<std::size_t, MaxPaths>& pick, T& total) const {
    pick.fill(kNone);
    pick[p] = k;
    std::uint32_t count = 1;
    total = T(0);
    for (std::size_t q = 0; q < cfg.num_paths; ++q) {
      if (q == p) continue;
      T best = cfg.gate_chi2;
      for (std::size_t j = 0; j < n; ++j) {
        if (j == k || cand[j].used || !cand[j].ok[q]) continue;
        bool taken = false;  // one path per slant track within a fused track
        for (std::size_t r = 0; r < q; ++r) taken = taken || pick[r] == j;
        if (taken) continue;
        const T d2 = ground_distance2(cand[j].x[q], cand[j].P[q], cand[k].x[p], cand[k].P[p]);
        if (!(d2 <= best)) continue;
        best = d2;
        pick[q] = j;
      }
      if (pick[q] != kNone) {
        ++count;
        total += best;
      }
    }
    return count;
  }

  // True if pick b reads a path track of pick a under another path (the
  // same detections, another ground point: a ghost of one of them).
  static bool conflicting(const std::array<std::size_t, MaxPaths>& a, const std::array<std::size_t, MaxPaths>& b,
                          std::size_t num_paths) {
    for (std::size_t p = 0; p < num_paths; ++p) {
      if (a[p] == kNone) continue;
      for (std::size_t q = 0; q < num_paths; ++q) {
        if (q != p && b[q] == a[p]) return true;
      }
    }
    return false;
  }

  // Step 3 once: the best-supported seed starts a fused track. With
  // defer_ambiguous, not if a seed with as much support reads one of its
  // path tracks under another path (those tracks wait for a scan where
  // more paths are confirmed; docs/algorithms/mptf.md §Fusion). False when
  // no seed is left.
  bool start_new(Cand* cand, std::size_t n, const Config& cfg, TrackerCounters& c, std::uint32_t& next_id) {
    std::uint32_t best_count = 0;
    T best_total = T(0);
    std::array<std::size_t, MaxPaths> best_pick{};
    std::array<std::size_t, MaxPaths> pick{};
    for (std::size_t k = 0; k < n; ++k) {
      if (cand[k].used) continue;
      for (std::size_t p = 0; p < cfg.num_paths; ++p) {
        if (!cand[k].ok[p]) continue;
        T total = T(0);
        const std::uint32_t count = support(cand, n, k, p, cfg, pick, total);
        if (count > best_count || (count == best_count && total < best_total)) {
          best_count = count;
          best_total = total;
          best_pick = pick;
        }
      }
    }
    if (best_count < cfg.min_paths) return false;
    bool ambiguous = false;
    for (std::size_t k = 0; k < n && cfg.defer_ambiguous && !ambiguous; ++k) {
      if (cand[k].used) continue;
      for (std::size_t p = 0; p < cfg.num_paths && !ambiguous; ++p) {
        if (!cand[k].ok[p]) continue;
        T total = T(0);
        const std::uint32_t count = support(cand, n, k, p, cfg, pick, total);
        ambiguous = count == best_count && conflicting(best_pick, pick, cfg.num_paths);
      }
    }
    if (ambiguous || fused_.size() == MaxFused) {
      if (!ambiguous) ++c.track_cap_hits;
      for (std::size_t p = 0; p < cfg.num_paths; ++p) {
        if (best_pick[p] != kNone) cand[best_pick[p]].used = true;  // out of this scan's search
      }
      return true;
    }
    Fused f;
    f.id = next_id++;
    for (std::size_t p = 0; p < cfg.num_paths; ++p) {
      if (best_pick[p] == kNone) continue;
      f.member[p] = cand[best_pick[p]].track_id;
      cand[best_pick[p]].used = true;
    }
    static_cast<void>(fuse(f, cand, n, cfg));
    static_cast<void>(fused_.push_back(f));  // size < MaxFused checked above
    return true;
  }

  StaticVector<Fused, MaxFused> fused_;
};

}  // namespace mptrack::mptf
