// One path track of multipath track fusion: a Kalman filter on the
// slant-coordinate CV state s = [r km, r_dot km/s, zeta rad, zeta_dot rad/s]
// (model/othr_slant_state.h) with the M/N track logic of seed 002 Sec. IV
// (docs/algorithms/mptf.md §Path trackers).
//
// In slant coordinates the measurement y = [r, r_dot, zeta] is a selection
// of the state (H = [I_3 0]), so the filter is linear and exact; the
// nonlinearity of seed 002 eq. (57) only enters when a track is carried to
// the ground (fusion, with the Jacobian of model/othr_measurement.h).
#pragma once

#include <cstdint>

#include <Eigen/Core>

#include "mptrack/model/othr_measurement.h"
#include "mptrack/model/othr_slant_state.h"

namespace mptrack::mptf {

template <class T>
using Mat4 = Eigen::Matrix<T, 4, 4>;
template <class T>
using Mat3 = Eigen::Matrix<T, 3, 3>;

/// Stage of the M/N logic (confirm_m1/n1 then confirm_m2/n2).
enum class TrackStage : std::uint8_t { kStage1, kStage2, kConfirmed };

template <class T>
struct SlantTrack {
  std::uint32_t id = 0;  ///< stable, never reused within a run
  model::OthrSlantState<T> s = model::OthrSlantState<T>::Zero();
  Mat4<T> P = Mat4<T>::Zero();
  TrackStage stage = TrackStage::kStage1;
  std::uint32_t age_scans = 0;     ///< scans since birth (0 at the birth scan)
  std::uint32_t stage_hits = 0;    ///< hits in the current stage (the birth detection counts in stage 1)
  std::uint32_t misses = 0;        ///< consecutive scans with an empty gate
  bool hit = false;                ///< something fell in the gate this scan
  std::int32_t measurement_index = -1;  ///< scan index of the most probable gated detection, -1 = none

  bool finite() const {
    for (int r = 0; r < 4; ++r) {
      if (!(s(r) - s(r) == T(0)) || !(P(r, r) - P(r, r) == T(0))) return false;
    }
    return true;
  }
};

/// What the M/N logic decides after a scan.
enum class Verdict : std::uint8_t { kKeep, kConfirm, kDelete };

/// The M/N logic after the scan that set t.hit (age_scans already advanced
/// for a scan after the birth one). Stage 1 spans ages [0, n1), stage 2
/// ages [n1, n1 + n2); a stage fails as soon as its m hits are out of reach
/// (docs/algorithms/mptf.md §Track logic). Confirmed tracks are deleted
/// after delete_misses consecutive empty gates.
template <class T>
Verdict track_logic(SlantTrack<T>& t, std::uint32_t m1, std::uint32_t n1, std::uint32_t m2, std::uint32_t n2,
                    std::uint32_t delete_misses) {
  t.misses = t.hit ? 0u : t.misses + 1u;
  if (t.stage == TrackStage::kConfirmed) return t.misses >= delete_misses ? Verdict::kDelete : Verdict::kKeep;
  if (t.hit) ++t.stage_hits;
  if (t.stage == TrackStage::kStage1) {
    const std::uint32_t left = n1 - 1u - t.age_scans;  // stage-1 scans still to come
    if (t.stage_hits + left < m1) return Verdict::kDelete;
    if (left > 0u) return Verdict::kKeep;
    if (n2 == 0u) return Verdict::kConfirm;
    t.stage = TrackStage::kStage2;
    t.stage_hits = 0;
    return Verdict::kKeep;
  }
  if (t.stage_hits >= m2) return Verdict::kConfirm;
  const std::uint32_t left = n1 + n2 - 1u - t.age_scans;
  return t.stage_hits + left < m2 ? Verdict::kDelete : Verdict::kKeep;
}

}  // namespace mptrack::mptf
