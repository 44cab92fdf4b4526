// Fixed-lag smoothing of the multipath tracker's output
// (docs/algorithms/multipath.md §Fixed-lag smoother). Seed 002 smooths
// the whole batch (its Module 1, RTS over q(x), and Module 2, forward-
// backward over q(s)); online, the tracker records what its filter knew of
// each track at each of the last L + 1 scans and reports scan k - L at
// step k, smoothed with everything seen up to scan k:
//  - q(s) by the backward pass of the two-state chain (seed 002 eq. (38)):
//      gamma_t(1) = q_t(1) [ p(1|1) gamma_t+1 / qp_t+1 + (1 - p(1|1)) (1 - gamma_t+1) / (1 - qp_t+1) ]
//      gamma_t(0) = q_t(0) [ p(1|0) gamma_t+1 / qp_t+1 + (1 - p(1|0)) (1 - gamma_t+1) / (1 - qp_t+1) ]
//    with qp_t+1 the predicted p(s = 1) of scan t + 1 and gamma the smoothed
//    q(s = 1): a target missed on every path for one scan keeps its track
//    (its later detections raise gamma), a track that dies drops its tail;
//  - q(x) by Rauch-Tung-Striebel over the CWNA motion (model/cwna_motion.h):
//      G = P_t F^T Pp_t+1^-1,  x^s_t = x_t + G (x^s_t+1 - xp_t+1),
//      P^s_t = P_t + G (P^s_t+1 - Pp_t+1) G^T.
// A track deleted at scan d has entries up to d - 1: its chain ends there.
// Memory: (kMaxLag + 1) x kMaxTracks entries, members only.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include <Eigen/Core>

#include "mptrack/model/cholesky.h"
#include "mptrack/model/othr_measurement.h"
#include "mptrack/multipath/path_track.h"
#include "mptrack/static_vector.h"
#include "mptrack/status.h"

namespace mptrack::multipath {

/// What the filter knew of one track at one scan.
template <class T>
struct LagEntry {
  std::uint32_t id = 0;
  model::OthrState<T> x = model::OthrState<T>::Zero();       ///< filtered mean
  Mat4<T> P = Mat4<T>::Zero();                                ///< filtered covariance
  model::OthrState<T> x_pred = model::OthrState<T>::Zero();  ///< prediction of this scan
  Mat4<T> P_pred = Mat4<T>::Zero();
  T q = T(0);        ///< filtered q(s = 1)
  T q_pred = T(0);   ///< predicted p(s = 1) of this scan
  T dt_s = T(0);     ///< time from the previous scan [s]
  bool confirmed = false;               ///< reached the counting threshold at or before this scan
  std::int32_t measurement_index = -1;  ///< scan index of its most likely detection
  /// Retrodicted (multipath/retrodiction.h): a track born later, carried
  /// back; its state is taken as it is (no RTS or chain step through it).
  bool retro = false;
};

/// A detection of a held-back scan that no track took and no birth used.
template <class T>
struct Leftover {
  model::OthrMeas<T> y = model::OthrMeas<T>::Zero();  ///< [km, km/s, rad]
  std::uint16_t scan_index = 0;  ///< its index in the scan
  bool taken = false;            ///< claimed by a retrodicted track
};

/// The smoothed view of one entry of the oldest scan.
template <class T>
struct SmoothedEntry {
  std::uint32_t id = 0;
  model::OthrState<T> x = model::OthrState<T>::Zero();
  Mat4<T> P = Mat4<T>::Zero();
  T q = T(0);                   ///< smoothed q(s = 1)
  bool confirmed = false;       ///< the track has reached the counting threshold by the newest scan
  T max_later_q = T(0);         ///< largest filtered q(s = 1) of its newer scans (0 if none)
  std::int32_t measurement_index = -1;
};

/// The meta-state transition of the tracker's params (seed 002 eq. (38)).
template <class T>
struct LagModel {
  T p_stay = T(0.85);      ///< p(s = 1 | s = 1)
  T p_become = T(0.15);    ///< p(s = 1 | s = 0)
};

template <class T, std::size_t MaxTracks, std::size_t MaxLag, std::size_t MaxMeasurements = 1>
class FixedLagSmoother {
  static_assert(MaxLag >= 1, "a fixed-lag smoother needs a lag of at least one scan");

 public:
  struct Slot {
    std::uint64_t time_us = 0;
    std::uint32_t scan_index = 0;
    StaticVector<LagEntry<T>, MaxTracks> entries;
    StaticVector<Leftover<T>, MaxMeasurements> leftovers;  ///< for retrodiction, in slant-range order
    model::OthrMeas<T> r_var = model::OthrMeas<T>::Ones();  ///< the scan's noise variances [km^2, (km/s)^2, rad^2]
    bool has_doppler = false;
  };

  /// Forgets every scan.
  void reset() { head_ = count_ = 0; }
  std::size_t pending() const { return count_; }
  /// Starts recording a scan; the caller pops first when pending() > lag.
  /// False (nothing changed) if kMaxLag + 1 scans are pending.
  bool open_scan(std::uint64_t time_us, std::uint32_t scan_index) {
    if (count_ == kSlots) return false;
    Slot& s = slot(count_);
    s.time_us = time_us;
    s.scan_index = scan_index;
    s.entries.clear();
    s.leftovers.clear();
    ++count_;
    return true;
  }
  /// Records a track at the newest scan; false if the scan holds MaxTracks.
  bool record(const LagEntry<T>& e) { return newest().entries.push_back(e) == Status::kOk; }

  /// Records at the pending scan of the given age; false if it holds MaxTracks.
  bool record_at(std::size_t age, const LagEntry<T>& e) { return slot(age).entries.push_back(e) == Status::kOk; }

  /// The oldest pending scan (pending() > 0).
  const Slot& oldest() const { return slot(0); }
  /// The newest pending scan (pending() > 0).
  Slot& newest() { return slot(count_ - 1); }
  /// Pending scan by age: 0 the oldest, pending() - 1 the newest.
  Slot& slot(std::size_t age) { return ring_[(head_ + age) % kSlots]; }
  const Slot& slot(std::size_t age) const { return ring_[(head_ + age) % kSlots]; }

  /// Smooths entry i of the oldest scan with every newer scan. Returns
  /// false when an innovation covariance was not SPD (the filtered state
  /// is kept from that step back).
  bool smooth(std::size_t i, const LagModel<T>& m, SmoothedEntry<T>& out) const {
    const LagEntry<T>& e0 = slot(0).entries[i];
    std::array<const LagEntry<T>*, kSlots> chain{};
    std::size_t n = 0;
    chain[n++] = &e0;
    for (std::size_t t = 1; t < count_; ++t) {
      const LagEntry<T>* next = find(slot(t), e0.id);
      if (next == nullptr) break;  // deleted: its chain ends
      chain[n++] = next;
    }
    const LagEntry<T>& last = *chain[n - 1];
    out.max_later_q = T(0);
    for (std::size_t k = 1; k < n; ++k) out.max_later_q = chain[k]->q > out.max_later_q ? chain[k]->q : out.max_later_q;
    model::OthrState<T> xs = last.x;
    Mat4<T> Ps = last.P;
    T gamma = last.q;
    bool ok = true;
    for (std::size_t k = n - 1; k-- > 0;) {
      const LagEntry<T>& cur = *chain[k];
      const LagEntry<T>& nxt = *chain[k + 1];
      if (cur.retro || nxt.retro) {  // not filtered forward: no backward step through it
        xs = cur.x;
        Ps = cur.P;
        gamma = cur.q;
        continue;
      }
      gamma = smooth_existence(cur.q, nxt.q_pred, gamma, m);
      if (ok) ok = rts_step(cur, nxt, xs, Ps);
      if (!ok) {
        xs = cur.x;
        Ps = cur.P;
      }
    }
    out.id = e0.id;
    out.x = xs;
    out.P = Ps;
    out.q = gamma;
    out.confirmed = last.confirmed;
    out.measurement_index = e0.measurement_index;
    return ok;
  }

  /// Drops the oldest scan.
  void pop() {
    head_ = (head_ + 1) % kSlots;
    --count_;
  }

 private:
  static constexpr std::size_t kSlots = MaxLag + 1;

  static const LagEntry<T>* find(const Slot& s, std::uint32_t id) {
    for (const LagEntry<T>& e : s.entries) {
      if (e.id == id) return &e;
    }
    return nullptr;
  }

  // The backward step of the two-state chain (header comment).
  static T smooth_existence(T q, T q_pred_next, T gamma_next, const LagModel<T>& m) {
    const T lo = T(1e-12);
    const T qp = q_pred_next < lo ? lo : (q_pred_next > T(1) - lo ? T(1) - lo : q_pred_next);
    const T up = gamma_next / qp;
    const T down = (T(1) - gamma_next) / (T(1) - qp);
    const T g1 = q * (m.p_stay * up + (T(1) - m.p_stay) * down);
    const T g0 = (T(1) - q) * (m.p_become * up + (T(1) - m.p_become) * down);
    const T sum = g1 + g0;
    return sum > T(0) ? g1 / sum : q;
  }

  // One RTS step from scan k + 1 (smoothed xs, Ps) back to scan k.
  static bool rts_step(const LagEntry<T>& cur, const LagEntry<T>& nxt, model::OthrState<T>& xs, Mat4<T>& Ps) {
    Mat4<T> F = Mat4<T>::Identity();
    F(0, 1) = nxt.dt_s;
    F(2, 3) = nxt.dt_s;
    Mat4<T> L;
    if (!model::cholesky<T, 4>(nxt.P_pred, L)) return false;
    const Mat4<T> FP = F * cur.P;
    const Mat4<T> Gt = model::cholesky_solve<T, 4, 4>(L, FP);  // Pp^-1 F P = G^T
    const Mat4<T> G = Gt.transpose();
    const model::OthrState<T> dx = xs - nxt.x_pred;
    xs = cur.x + G * dx;
    const Mat4<T> dP = Ps - nxt.P_pred;
    const Mat4<T> GdP = G * dP;
    Ps = cur.P + GdP * Gt;
    return true;
  }

  std::array<Slot, kSlots> ring_{};
  std::size_t head_ = 0;
  std::size_t count_ = 0;
};

}  // namespace mptrack::multipath
