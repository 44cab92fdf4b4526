// Coupling of unresolved tracks (mfbp/evidence.h couple_unresolved,
// unresolved_weight; docs/algorithms/mfbp.md §Departures): common means
// computed by hand. One behaviour per case.
#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <memory>

#include "mptrack/caps.h"
#include "mptrack/mfbp/evidence.h"

using namespace mptrack;
using namespace mptrack::mfbp;

namespace {

using Moments = std::array<TrackMoments<double>, 2>;

/// Two tracks at range 0 and `apart` m (azimuth 0), Sz = I each: d^2 = apart^2 / 2.
Moments two_tracks(double apart) {
  Moments m{};
  for (auto& x : m) {
    x.ok = true;
    x.Sz = Mat2<double>::Identity();
  }
  m[1].z(0) = apart;
  return m;
}

/// Couples m with unresolved_chi2 = 4 and the given taper, both tracks
/// confirmed or both tentative; returns the mate of track 0 on scan 0.
std::uint16_t couple(Moments& m, bool taper, bool confirmed = true) {
  auto table = std::make_unique<TrackTable<double, DefaultCaps>>();  // too big for a small stack
  (*table)[0].confirmed = (*table)[1].confirmed = confirmed;
  MfbpParams<double> p;
  p.unresolved_chi2 = 4.0;
  p.unresolved_taper = taper;
  couple_unresolved(m, *table, 0, p);
  return (*table)[0].mate[0];
}

}  // namespace

TEST_CASE("unresolved weight: 1 at zero distance, 1/4 halfway, 0 at the coupling edge; 1 without taper") {
  CHECK(unresolved_weight(0.0, 4.0, true) == 1.0);
  CHECK(unresolved_weight(2.0, 4.0, true) == 0.25);
  CHECK(unresolved_weight(4.0, 4.0, true) == 0.0);
  CHECK(unresolved_weight(2.0, 4.0, false) == 1.0);
}

TEST_CASE("unresolved coupling of confirmed tracks with the taper: a neighbour at d^2 = 0.5 (chi2 4) weighs 49/64 in the common mean") {
  Moments m = two_tracks(1.0);
  const std::uint16_t mate = couple(m, true);
  // (0 + 49/64 * 1) / (1 + 49/64) = 49/113; symmetric for the other track.
  CHECK(m[0].z_shared(0) == doctest::Approx(49.0 / 113.0).epsilon(1e-15));
  CHECK(m[1].z_shared(0) == doctest::Approx(1.0 - 49.0 / 113.0).epsilon(1e-15));
  CHECK(mate == 2);  // mate is the neighbour's slot + 1
}

TEST_CASE("unresolved coupling of tentative tracks is the plain average, taper or not") {
  Moments m = two_tracks(1.0);
  (void)couple(m, true, false);
  CHECK(m[0].z_shared(0) == 0.5);
}

TEST_CASE("unresolved coupling without the taper is the plain average") {
  Moments m = two_tracks(1.0);
  (void)couple(m, false);
  CHECK(m[0].z_shared(0) == 0.5);
}

TEST_CASE("unresolved coupling leaves tracks at or beyond unresolved_chi2 on their own prediction") {
  Moments m = two_tracks(3.0);  // d^2 = 4.5 > 4
  const std::uint16_t mate = couple(m, true);
  CHECK(m[0].z_shared(0) == 0.0);
  CHECK(m[1].z_shared(0) == 3.0);
  CHECK(mate == 0);
}
