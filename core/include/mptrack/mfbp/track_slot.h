// One MF-BP track and the fixed table of them.
//
// A track holds its prior at the scan before the window (the filtered
// beliefs there, or its birth state) and, per window scan, every belief the
// sweeps of seed 000 Algorithm 1 produce: the kinematic state (eq. (35),
// forward and smoothed), the SNR inverse gamma (eq. (43)), the visibility
// (eq. (64)), the association beliefs of eqs. (99)-(102) on its gated
// measurements, and the manoeuvre statistics (docs/algorithms/mfbp.md
// §Departures). When the window slides (docs/algorithms/mfbp.md §Window
// schedule) the slot shifts itself: the last finalised filtered beliefs
// become the prior and the later scans move to the front.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "mptrack/mfbp/amplitude_model.h"
#include "mptrack/mfbp/cubature.h"
#include "mptrack/mfbp/amplitude_stats.h"
#include "mptrack/model/inverse_gamma.h"
#include "mptrack/mfbp/mfbp_caps.h"
#include "mptrack/mfbp/target_filter.h"

namespace mptrack::mfbp {

template <class T, class Caps>
struct TrackSlot {
  static constexpr std::size_t kMaxWindow = Caps::kMaxWindow;
  using Vec2 = mfbp::Vec2<T>;
  using Vec4 = mfbp::Vec4<T>;
  using Mat4 = mfbp::Mat4<T>;
  using IG = model::InverseGamma<T>;
  using AmpStats = AmplitudeStats<T>;

  bool alive = false;
  bool confirmed = false;
  bool from_birth = false;     ///< state at `first` is the birth state (no update there)
  std::uint32_t id = 0;
  std::size_t first = 0;       ///< first window scan of the track
  std::uint32_t low_run = 0;   ///< finalised consecutive scans with b_s < delete_threshold
  std::uint32_t age = 0;       ///< finalised scans since birth
  /// Scored measurements with the predictive density (young track inside
  /// weaker clutter, weaker_clutter.h) on some scan while tentative: it is
  /// confirmed at confirm_threshold_in_clutter (docs/algorithms/mfbp.md §Birth).
  bool predictive_evidence = false;
  /// Online filter: its predicted measurement lay in the gate of a Gaussian
  /// clutter component, of any power, on some scan while tentative
  /// (filter_score_in_any_component): it is held to confirm_threshold_in_clutter.
  bool predicted_in_component = false;
  /// Online filter: sum of ln(xi(1)/xi(0)) over the scans the track took
  /// part in while it had to reach confirm_threshold_in_clutter
  /// (filter_score_confirms, track_management.h) [nats].
  T score = T(0);
  // prior: filtered at the scan before the window (or birth state)
  Vec4 x0 = Vec4::Zero();
  Mat4 P0 = Mat4::Identity();
  IG ig0{};
  T vis0 = T(0.5);
  Vec2 bias0 = Vec2::Zero();    ///< faded whitened innovation before the window
  T vis_emitted = T(1);         ///< b_s(1) at the last finalised scan reported on
  std::uint64_t t0_us = 0;
  // per window scan
  std::array<Vec4, kMaxWindow> xf{}, xs{};
  std::array<PackedCov4<T>, kMaxWindow> Pf{}, Ps{};  // symmetric, packed
  std::array<IG, kMaxWindow> igf{}, igs{};
  std::array<AmpStats, kMaxWindow> amp{};
  std::array<T, kMaxWindow> xi1{}, xi0{}, visf{}, vis{}, extr{}, missed{};
  std::array<std::uint8_t, kMaxWindow> n_edges{};
  /// First edge of scan k in that scan's pool (ScanSlot::edge_meas / edge_w).
  std::array<std::uint16_t, kMaxWindow> edge_begin{};
  std::array<std::int32_t, kMaxWindow> best{};
  std::array<Vec2, kMaxWindow> biasf{};  ///< faded whitened innovation after the update at k
  std::array<T, kMaxWindow> qk{};    ///< process noise used to predict into k [(m/s^2)^2]
  std::array<std::uint16_t, kMaxWindow> mate{};  ///< nearest unresolved track + 1 (0: none)

  /// Does the track take part in the association of window scan k? (Not
  /// on its birth scan: the birth state already holds that measurement.)
  bool participates(std::size_t k) const {
    return alive && k >= first && !(from_birth && k == first);
  }

  /// "No information" association on scan k: missed for sure, no edges,
  /// flat visibility messages (docs/algorithms/mfbp.md §Window schedule).
  void forget_association(std::size_t k) {
    missed[k] = T(1);
    n_edges[k] = 0;
    best[k] = -1;
    xi1[k] = T(1);
    xi0[k] = T(1);
    amp[k] = AmpStats{};
  }

  /// A new scan entering the window: no association yet, flat extrinsic
  /// visibility.
  void open_scan(std::size_t k) {
    forget_association(k);
    extr[k] = T(0.5);
  }

  /// Fresh track (the caller sets its birth state): no association on any
  /// window scan, the birth visibility as extrinsic message.
  void start(std::uint32_t track_id, std::size_t first_scan, T visibility_at_birth) {
    reset();
    alive = true;
    id = track_id;
    first = first_scan;
    from_birth = true;
    vis0 = visibility_at_birth;
    for (std::size_t k = 0; k < kMaxWindow; ++k) {
      missed[k] = T(1);
      best[k] = -1;
      xi1[k] = T(1);
      xi0[k] = T(1);
      extr[k] = visibility_at_birth;
    }
  }

  /// The window slides by fc scans (n held): if the track existed at the
  /// last finalised scan, its filtered beliefs there become the prior.
  void shift(std::size_t fc, std::size_t n, std::uint64_t t_last_us) {
    const std::size_t last = fc - 1;
    if (first <= last) {
      x0 = xf[last];
      P0 = Pf[last].get();
      ig0 = igf[last];
      vis0 = visf[last];
      bias0 = biasf[last];
      t0_us = t_last_us;
      first = 0;
      from_birth = false;
    } else {
      first -= fc;
    }
    for (std::size_t k = fc; k < n; ++k) move_scan(k, k - fc);
  }

 private:
  /// The state of a fresh slot, set in place: `*this = TrackSlot{}` builds
  /// a temporary of the slot's size (kilobytes) on the stack of step().
  /// Keep in step with the members above.
  void reset() {
    alive = false;
    confirmed = false;
    from_birth = false;
    id = 0;
    first = 0;
    low_run = 0;
    age = 0;
    predictive_evidence = false;
    predicted_in_component = false;
    score = T(0);
    x0 = Vec4::Zero();
    P0 = Mat4::Identity();
    ig0 = IG{};
    vis0 = T(0.5);
    bias0 = Vec2::Zero();
    vis_emitted = T(1);
    t0_us = 0;
    for (std::size_t k = 0; k < kMaxWindow; ++k) {
      xf[k] = Vec4::Zero();
      xs[k] = Vec4::Zero();
      Pf[k] = PackedCov4<T>{};
      Ps[k] = PackedCov4<T>{};
      igf[k] = IG{};
      igs[k] = IG{};
      amp[k] = AmpStats{};
      xi1[k] = T(0);
      xi0[k] = T(0);
      visf[k] = T(0);
      vis[k] = T(0);
      extr[k] = T(0);
      missed[k] = T(0);
      n_edges[k] = 0;
      edge_begin[k] = 0;
      best[k] = 0;
      biasf[k] = Vec2::Zero();
      qk[k] = T(0);
      mate[k] = 0;
    }
  }

  void move_scan(std::size_t k, std::size_t d) {
    xf[d] = xf[k];
    xs[d] = xs[k];
    Pf[d] = Pf[k];
    Ps[d] = Ps[k];
    igf[d] = igf[k];
    igs[d] = igs[k];
    amp[d] = amp[k];
    xi1[d] = xi1[k];
    xi0[d] = xi0[k];
    visf[d] = visf[k];
    vis[d] = vis[k];
    extr[d] = extr[k];
    missed[d] = missed[k];
    n_edges[d] = n_edges[k];
    edge_begin[d] = edge_begin[k];
    best[d] = best[k];
    mate[d] = mate[k];
    biasf[d] = biasf[k];
    qk[d] = qk[k];
  }
};

/// The kMaxTargets track slots; dead slots are reused by births.
template <class T, class Caps>
class TrackTable {
 public:
  static constexpr std::size_t kSize = Caps::kMaxTargets;
  using Slot = TrackSlot<T, Caps>;

  Slot& operator[](std::size_t i) { return slots_[i]; }
  const Slot& operator[](std::size_t i) const { return slots_[i]; }
  auto begin() { return slots_.begin(); }
  auto end() { return slots_.end(); }
  auto begin() const { return slots_.begin(); }
  auto end() const { return slots_.end(); }

  /// Index of the first dead slot, kSize if every slot is alive.
  std::size_t free_slot() const {
    for (std::size_t i = 0; i < kSize; ++i) {
      if (!slots_[i].alive) return i;
    }
    return kSize;
  }
  std::size_t live() const {
    std::size_t n = 0;
    for (const auto& t : slots_) {
      if (t.alive) ++n;  // a branch: see mptf/ground_fusion.h FusedTrack::members()
    }
    return n;
  }

 private:
  std::array<Slot, kSize> slots_{};
};

}  // namespace mptrack::mfbp
