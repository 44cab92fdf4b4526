// MF-BP duplicate suppression (core/include/mptrack/mfbp/track_management.h,
// suppress_duplicates; docs/algorithms/mfbp.md §Confirmation and reporting):
// one behaviour per case, distances worked out by hand.
#include <doctest/doctest.h>

#include <memory>

#include "mptrack/caps.h"
#include "mptrack/mfbp/track_management.h"

using namespace mptrack;
using namespace mptrack::mfbp;

namespace {

using Table = TrackTable<double, DefaultCaps>;

/// Track `id` in slot i, present from window scan 0, smoothed state
/// (px, 0, 0, 0) with covariance I on every window scan.
void put(Table& t, std::size_t i, std::uint32_t id, double px, bool confirmed) {
  t[i].start(id, 0, 0.5);
  t[i].confirmed = confirmed;
  for (std::size_t k = 0; k < DefaultCaps::kMaxWindow; ++k) {
    t[i].xs[k] = Vec4<double>(px, 0.0, 0.0, 0.0);
    t[i].Ps[k].set(Mat4<double>::Identity());
  }
}

MfbpParams<double> params(double chi2) {
  MfbpParams<double> p;
  p.duplicate_chi2 = chi2;
  return p;
}

}  // namespace

TEST_CASE("mfbp duplicates: within the distance the younger of two confirmed tracks is deleted") {
  // e = (1.9, 0, 0, 0), C = 2 I: d^2 = 1.9^2 / 2 = 1.805 < 2.
  auto t = std::make_unique<Table>();
  put(*t, 0, 7, 100.0, true);
  put(*t, 1, 3, 101.9, true);
  TrackerCounters c;
  suppress_duplicates(*t, 3, params(2.0), c);
  CHECK((*t)[1].alive);   // id 3: the older
  CHECK_FALSE((*t)[0].alive);
  CHECK(c.tracks_deleted == 1);
}

TEST_CASE("mfbp duplicates: a pair just beyond the distance is kept") {
  // e = (2.1, 0, 0, 0), C = 2 I: d^2 = 2.205 >= 2.
  auto t = std::make_unique<Table>();
  put(*t, 0, 1, 100.0, true);
  put(*t, 1, 2, 102.1, true);
  TrackerCounters c;
  suppress_duplicates(*t, 3, params(2.0), c);
  CHECK((*t)[0].alive);
  CHECK((*t)[1].alive);
  CHECK(c.tracks_deleted == 0);
}

TEST_CASE("mfbp duplicates: a confirmed track is kept over an older tentative one") {
  auto t = std::make_unique<Table>();
  put(*t, 0, 1, 100.0, false);
  put(*t, 1, 2, 100.5, true);
  TrackerCounters c;
  suppress_duplicates(*t, 3, params(2.0), c);
  CHECK_FALSE((*t)[0].alive);
  CHECK((*t)[1].alive);
}

TEST_CASE("mfbp duplicates: two tentative tracks and the default 0 are left alone") {
  auto t = std::make_unique<Table>();
  put(*t, 0, 1, 100.0, false);
  put(*t, 1, 2, 100.0, false);
  TrackerCounters c;
  suppress_duplicates(*t, 3, params(2.0), c);
  CHECK((*t)[0].alive);
  CHECK((*t)[1].alive);
  (*t)[1].confirmed = true;
  suppress_duplicates(*t, 3, MfbpParams<double>{}, c);  // duplicate_chi2 = 0: off
  CHECK((*t)[0].alive);
  CHECK(c.tracks_deleted == 0);
}

TEST_CASE("mfbp duplicates: velocity counts, so a crossing pair at one position is kept") {
  // Same position, vx differ by 2.1 m/s: e = (0, 2.1, 0, 0), C = 2 I, d^2 = 2.205 >= 2
  // (state [px, vx, py, vy]).
  auto t = std::make_unique<Table>();
  put(*t, 0, 1, 100.0, true);
  put(*t, 1, 2, 100.0, true);
  for (std::size_t k = 0; k < DefaultCaps::kMaxWindow; ++k) (*t)[1].xs[k](1) = 2.1;
  TrackerCounters c;
  suppress_duplicates(*t, 3, params(2.0), c);
  CHECK((*t)[0].alive);
  CHECK((*t)[1].alive);
}
