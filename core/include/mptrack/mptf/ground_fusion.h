// Fusion of path tracks in ground coordinates (docs/algorithms/mptf.md
// §Fusion). Every confirmed slant track is carried to the ground under every
// path (model/othr_slant_state.h): one candidate per (track, path), of which
// only the track's true path is right. A fused track holds at most one slant
// track per path; per scan:
//   1. refresh: members whose slant track is gone (or no longer invertible)
//      leave; the fused state is the information sum of the members'
//      candidates; a member farther than the gate from it leaves;
//   2. join: free candidates join the fused track (on a path it lacks) they
//      are closest to, within the gate, closest pairs first;
//   3. new: among free candidates, the (track, path) seed whom the most other
//      tracks support on distinct paths within the gate starts a fused track
//      with them, if they are at least fuse_min_paths; repeated until none
//      (optionally deferred while another path reading is as well supported).
// Distances are Mahalanobis in ground range, range rate and bearing
// (g, g_dot, theta) over the sum of the two covariances.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include <Eigen/Core>

#include "mptrack/model/cholesky.h"
#include "mptrack/model/mahalanobis.h"
#include "mptrack/model/othr_measurement.h"
#include "mptrack/model/spd_guard_scaled.h"
#include "mptrack/mptf/slant_track.h"
#include "mptrack/static_vector.h"
#include "mptrack/track_report.h"

namespace mptrack::mptf {

/// One confirmed slant track seen from the ground under every path.
template <class T, std::size_t MaxPaths>
struct Candidate {
  std::uint32_t track_id = 0;
  std::int32_t measurement_index = -1;
  std::array<model::OthrState<T>, MaxPaths> x{};
  std::array<Mat4<T>, MaxPaths> P{};
  std::array<bool, MaxPaths> ok{};  ///< the inversion under this path succeeded
  bool used = false;                ///< belongs to a fused track this scan
};

template <class T, std::size_t MaxPaths>
struct FusedTrack {
  std::uint32_t id = 0;
  std::array<std::uint32_t, MaxPaths> member{};  ///< slant track id per path, 0 = none
  model::OthrState<T> x = model::OthrState<T>::Zero();
  Mat4<T> P = Mat4<T>::Zero();
  std::int32_t measurement_index = -1;
  std::uint32_t members() const {
    // A branch, not n += (m != 0 ? 1u : 0u): GCC 12's NEON vectoriser
    // (armhf, -O3) summed that as -3 for 3 members (mptf_tracker_test).
    std::uint32_t n = 0;
    for (std::uint32_t m : member) {
      if (m != 0) ++n;
    }
    return n;
  }
};

/// Mahalanobis distance^2 of two ground states in (g, g_dot, theta) over
/// Pa + Pb; a huge value when that covariance is not SPD. The ground range
/// rate comes from the measured slant range rate (1 m/s noise against a
/// +-524 m/s clutter spread), so it separates chance coincidences of
/// clutter tracks that position alone would fuse (docs/algorithms/mptf.md §Fusion).
template <class T>
T ground_distance2(const model::OthrState<T>& a, const Mat4<T>& Pa, const model::OthrState<T>& b, const Mat4<T>& Pb) {
  constexpr int kAxis[3] = {0, 1, 2};  // g, g_dot, theta
  Mat3<T> C;
  Eigen::Matrix<T, 3, 1> e;
  for (int r = 0; r < 3; ++r) {
    e(r) = a(kAxis[r]) - b(kAxis[r]);
    for (int c = 0; c < 3; ++c) C(r, c) = Pa(kAxis[r], kAxis[c]) + Pb(kAxis[r], kAxis[c]);
  }
  T d2 = T(1e30);
  static_cast<void>(model::mahalanobis_n<T, 3>(e, C, d2));
  return d2;
}

/// (x, P) <- the information sum of (x, P) and (xb, Pb), written in gain
/// form x += K (xb - x), P -= K P with K = P (P + Pb)^-1, and the inverse
/// taken on the correlation matrix of P + Pb (its variances span 1e1 ..
/// 1e-10 in these units). False (nothing changed) if P + Pb is not SPD.
template <class T>
bool information_fuse(model::OthrState<T>& x, Mat4<T>& P, const model::OthrState<T>& xb, const Mat4<T>& Pb) {
  const Mat4<T> Ssum = P + Pb;
  Eigen::Matrix<T, 4, 1> d;
  for (int r = 0; r < 4; ++r) {
    if (!(Ssum(r, r) > T(0))) return false;
    d(r) = T(1) / std::sqrt(Ssum(r, r));
  }
  const Mat4<T> C = d.asDiagonal() * Ssum * d.asDiagonal();
  Mat4<T> L;
  if (!model::cholesky<T, 4>(C, L)) return false;
  const Mat4<T> B = d.asDiagonal() * P;                       // D P
  const Mat4<T> KT = d.asDiagonal() * model::cholesky_solve<T, 4, 4>(L, B);  // (P + Pb)^-1 P
  const Mat4<T> K = KT.transpose();
  x += K * (xb - x);
  const Mat4<T> Pn = P - K * P;
  P = T(0.5) * (Pn + Pn.transpose());
  return true;
}

}  // namespace mptrack::mptf
