// The shared parameter blocks (tracker_params.h) and every tracker's
// validate(): a refused value names its field (ParamError), the blocks keep
// one name per quantity, and each tracker checks its Caps.
#include <doctest/doctest.h>

#include <cstring>
#include <limits>

#include "mptrack/caps.h"
#include "mptrack/cbmember/cbmember_filter.h"
#include "mptrack/frontend/front_end.h"
#include "mptrack/frontend/radar_caps.h"
#include "mptrack/gnn/gnn_tracker.h"
#include "mptrack/mfbp/mfbp_tracker.h"
#include "mptrack/phd/phd_filter.h"
#include "mptrack/sbl/sbl_params.h"
#include "mptrack/seaclutter/sea_detector_params.h"
#include "mptrack/tracker_params.h"
#include "mptrack/vmp/vmp_params.h"

using mptrack::ParamError;
using mptrack::Status;

namespace {

/// The field named by a failed validate(), "" when it passed.
template <class Check>
const char* field_of(Check check) {
  ParamError where;
  return check(&where) == Status::kOk ? "" : where.field;
}

bool same(const char* a, const char* b) { return std::strcmp(a, b) == 0; }

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

TEST_CASE("PolarRegion: valid defaults of a tracker pass; each bound is named") {
  mptrack::PolarRegion<double> r{10.0, 50.0, -1.0, 1.0};
  auto v = [&r](ParamError* w) { return r.validate(w); };
  CHECK(same(field_of(v), ""));
  r.range_min_m = -1.0;  // a range is >= 0
  CHECK(same(field_of(v), "region.range_min_m"));
  r = {10.0, 5.0, -1.0, 1.0};  // max below min
  CHECK(same(field_of(v), "region.range_max_m"));
  r = {10.0, 2e7, -1.0, 1.0};  // beyond 1e7 m
  CHECK(same(field_of(v), "region.range_max_m"));
  r = {10.0, 50.0, kNaN, 1.0};
  CHECK(same(field_of(v), "region.azimuth_min_rad"));
  r = {10.0, 50.0, -1.0, 4.0};  // beyond pi
  CHECK(same(field_of(v), "region.azimuth_max_rad"));
  r = {10.0, 50.0, 1.0, 1.0};  // empty
  CHECK(same(field_of(v), "region.azimuth_max_rad"));
}

TEST_CASE("PolarRegion: volume is range span x azimuth span, contains includes the bounds") {
  const mptrack::PolarRegion<double> r{10.0, 50.0, -0.5, 1.5};
  CHECK(r.volume() == 80.0);  // 40 m x 2 rad
  CHECK(r.contains(10.0, 1.5));
  CHECK(r.contains(50.0, -0.5));
  CHECK_FALSE(r.contains(50.5, 0.0));
  CHECK_FALSE(r.contains(20.0, -0.6));
  CHECK_FALSE(r.contains(kNaN, 0.0));
}

TEST_CASE("CartesianRegion: each bound is named; volume is the area") {
  mptrack::CartesianRegion<double> r{-100.0, 100.0, 0.0, 50.0};
  auto v = [&r](ParamError* w) { return r.validate(w); };
  CHECK(same(field_of(v), ""));
  CHECK(r.volume() == 10000.0);
  CHECK(r.contains(-100.0, 50.0));
  CHECK_FALSE(r.contains(0.0, 51.0));
  r.x_min_m = -2e7;
  CHECK(same(field_of(v), "cartesian_region.x_min_m"));
  r = {-100.0, -100.0, 0.0, 50.0};
  CHECK(same(field_of(v), "cartesian_region.x_max_m"));
  r = {-100.0, 100.0, kNaN, 50.0};
  CHECK(same(field_of(v), "cartesian_region.y_min_m"));
  r = {-100.0, 100.0, 0.0, -1.0};
  CHECK(same(field_of(v), "cartesian_region.y_max_m"));
}

TEST_CASE("PolarNoise: each standard deviation is named with its range") {
  mptrack::PolarNoise<float> n{20.0f, 0.01f, 1.0f};
  auto v = [&n](ParamError* w) { return n.validate(w); };
  CHECK(same(field_of(v), ""));
  n.range_std_m = 0.0f;
  CHECK(same(field_of(v), "noise.range_std_m"));
  n = {20.0f, 2.0f, 1.0f};  // above 1 rad
  CHECK(same(field_of(v), "noise.azimuth_std_rad"));
  n = {20.0f, 0.01f, 1e-40f};  // denormal: its square is 0
  CHECK(same(field_of(v), "noise.doppler_std_mps"));
}

TEST_CASE("AmplitudeModel: Swerling I / III give n = 1 / 2; bad fields are named") {
  mptrack::AmplitudeModel<double> a{true, 0.715, 1e4, 1};
  auto v = [&a](ParamError* w) { return a.validate(w); };
  CHECK(same(field_of(v), ""));
  CHECK(a.order() == 1);
  a.swerling = 3;
  CHECK(a.order() == 2);
  CHECK(same(field_of(v), ""));
  a.swerling = 2;  // the old RFS spelling of Swerling III is refused
  CHECK(same(field_of(v), "amplitude.swerling"));
  a = {true, 0.0, 1e4, 1};
  CHECK(same(field_of(v), "amplitude.threshold"));
  a = {true, 0.715, 0.5, 1};  // ceiling below the threshold
  CHECK(same(field_of(v), "amplitude.max_amplitude"));
  ParamError where;
  CHECK(a.validate(&where) == Status::kInvalidArgument);
  CHECK(std::strstr(where.rule, "max_amplitude, threshold") != nullptr);
  CHECK(where.result.value == 0.5);  // the figures the harness prints
  CHECK(where.result.lo == doctest::Approx(0.715));
  CHECK(where.result.lo_open);
}

TEST_CASE("GNN validate: the motion noise is a variance; block fields carry the block name") {
  using Tracker = mptrack::GnnTracker<float>;
  Tracker::Params p;
  CHECK(p.accel_var_m2ps4 == 4.0f);  // (2 m/s^2)^2
  auto v = [&p](ParamError* w) { return Tracker::validate(p, w); };
  CHECK(same(field_of(v), ""));
  p.accel_var_m2ps4 = -1.0f;
  CHECK(same(field_of(v), "accel_var_m2ps4"));
  p = Tracker::Params{};
  p.region.range_max_m = 0.1f;  // below range_min_m 0.5
  CHECK(same(field_of(v), "region.range_max_m"));
  p = Tracker::Params{};
  p.max_gap_s = -1.0f;
  CHECK(same(field_of(v), "max_gap_s"));
}

TEST_CASE("MF-BP validate: caps of the instantiation are checked and named") {
  using Small = mptrack::MfbpTracker<float, mptrack::SmallBoardCaps>;  // kMaxWindow 4
  Small::Params p;
  p.window_length = 4;
  p.slide = 2;
  auto v = [&p](ParamError* w) { return Small::validate(p, w); };
  CHECK(same(field_of(v), ""));
  p.window_length = 5;
  CHECK(same(field_of(v), "window_length"));
  // The defaults (window 7) are valid params, but not for these caps.
  CHECK(Small::Params{}.validate() == Status::kOk);
  p = Small::Params{};
  CHECK(same(field_of(v), "window_length"));
  p.window_length = 4;
  p.slide = 2;
  p.birth_max_per_window = mptrack::mfbp::kMaxBirthCandidates<mptrack::SmallBoardCaps> + 1;
  CHECK(same(field_of(v), "birth_max_per_window"));
  p.birth_max_per_window = 20;
  p.clutter_mode = mptrack::ClutterMode::kKnownMap;
  p.known_clutter.num_components = mptrack::SmallBoardCaps::kMaxClutterComponents + 1;
  CHECK(same(field_of(v), "known_clutter.num_components"));
  p.known_clutter.num_components = mptrack::SmallBoardCaps::kMaxClutterComponents;
  CHECK(same(field_of(v), ""));
}

TEST_CASE("MF-BP validate: its own rules on shared blocks use the shared names") {
  using Tracker = mptrack::MfbpTracker<float>;
  Tracker::Params p;
  auto v = [&p](ParamError* w) { return Tracker::validate(p, w); };
  p.region.range_min_m = 0.0f;  // MF-BP needs a positive minimum range
  CHECK(same(field_of(v), "region.range_min_m"));
  p = Tracker::Params{};
  p.amplitude.swerling = 2;
  CHECK(same(field_of(v), "amplitude.swerling"));
  p = Tracker::Params{};
  p.accel_var_m2ps4 = 0.0f;
  CHECK(same(field_of(v), "accel_var_m2ps4"));
  p = Tracker::Params{};
  p.clutter_mode = mptrack::ClutterMode::kKnownUniform;  // not an MF-BP mode
  CHECK(same(field_of(v), "clutter_mode"));
}

TEST_CASE("RFS validate: the active measurement space picks region and noise") {
  using Filter = mptrack::GmPhdFilter<float>;
  Filter::Params p;  // Cartesian by default
  CHECK(p.accel_var_m2ps4 == 25.0f);  // (5 m/s^2)^2
  auto v = [&p](ParamError* w) { return Filter::validate(p, w); };
  CHECK(same(field_of(v), ""));
  p.region.range_min_m = -5.0f;  // the polar region is not used
  CHECK(same(field_of(v), ""));
  p.cartesian_std_m = 0.0f;
  CHECK(same(field_of(v), "cartesian_std_m"));
  p.cartesian_std_m = 10.0f;
  p.cartesian_region.y_max_m = -2000.0f;
  CHECK(same(field_of(v), "cartesian_region.y_max_m"));
  p = Filter::Params{};
  p.space = mptrack::MeasurementSpace::kPolar;
  CHECK(same(field_of(v), ""));
  p.region.range_min_m = -5.0f;
  CHECK(same(field_of(v), "region.range_min_m"));
  p.region.range_min_m = 0.0f;
  p.noise.azimuth_std_rad = 0.5f;  // cross-range std 1000 m x 0.5 = 500 m <= 1e3 x 10 m
  CHECK(same(field_of(v), ""));
  p.noise.range_std_m = 0.01f;  // 500 m > 1e3 x 0.01 m: condition number too large
  CHECK(same(field_of(v), "noise.azimuth_std_rad"));
}

TEST_CASE("RFS validate: CBMeMBer names the same fields") {
  using Filter = mptrack::CbMemberFilter<double>;
  Filter::Params p;
  p.amplitude.max_amplitude = 1e7;  // above the RFS ceiling 1e6
  ParamError where;
  CHECK(Filter::validate(p, &where) == Status::kInvalidArgument);
  CHECK(same(where.field, "amplitude.max_amplitude"));
  p = Filter::Params{};
  p.max_gap_s = -1.0;
  CHECK(Filter::validate(p, &where) == Status::kInvalidArgument);
  CHECK(same(where.field, "max_gap_s"));
}

TEST_CASE("front end validate: fields, CFAR fields and the radar caps are named") {
  using Fe = mptrack::frontend::FrontEnd<mptrack::frontend::Seed004RadarCaps>;
  mptrack::frontend::FrontEndParams p;
  auto v = [&p](ParamError* w) { return Fe::validate(p, w); };
  CHECK(same(field_of(v), ""));
  p.cfar.pfa = 0.9;
  CHECK(same(field_of(v), "cfar.pfa"));
  p = mptrack::frontend::FrontEndParams{};
  p.max_detections = mptrack::frontend::Seed004RadarCaps::kMaxDetections + 1;
  CHECK(same(field_of(v), "max_detections"));
  CHECK(p.validate() == Status::kOk);  // fine on its own, too many for these caps
  p = mptrack::frontend::FrontEndParams{};
  p.carrier_hz = -1.0;
  CHECK(same(field_of(v), "carrier_hz"));
}

TEST_CASE("carrier_hz is a radar carrier, 1 MHz to 10 THz, in every struct that holds one (F15)") {
  mptrack::frontend::FrontEndParams fe;
  mptrack::VmpParams vmp;
  mptrack::SblParams sbl;
  mptrack::seaclutter::SeaDetectorParams sea;
  auto refused = [](auto p, double f) {
    p.carrier_hz = f;
    ParamError e{};
    return p.validate(&e) == Status::kInvalidArgument && std::strcmp(e.field, "carrier_hz") == 0;
  };
  for (double f : {1e-40, 0.999e6, 1.001e13}) {
    CHECK(refused(fe, f));  // 1e-40: the fuzz_params finding, +-Inf Doppler in the detections
    CHECK(refused(vmp, f));
    CHECK(refused(sbl, f));
    CHECK(refused(sea, f));
  }
  for (double f : {1e6, 10e9, 1e13}) {
    CHECK_FALSE(refused(fe, f));
    CHECK_FALSE(refused(vmp, f));
    CHECK_FALSE(refused(sbl, f));
    CHECK_FALSE(refused(sea, f));
  }
}

TEST_CASE("front end validate: chirp_repetition_s within 1 ns .. 1 s (F15)") {
  mptrack::frontend::FrontEndParams p;
  ParamError e{};
  p.chirp_repetition_s = 1e-40;
  CHECK(p.validate(&e) == Status::kInvalidArgument);
  CHECK(std::strcmp(e.field, "chirp_repetition_s") == 0);
  p.chirp_repetition_s = 2.0;
  CHECK(p.validate(&e) == Status::kInvalidArgument);
  p.chirp_repetition_s = 1e-9;
  CHECK(p.validate() == Status::kOk);
}
