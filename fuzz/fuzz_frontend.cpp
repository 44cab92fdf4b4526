// libFuzzer harness: the MIMO front end on arbitrary ADC cubes and CFAR
// settings (docs/reliability.md). A tiny radar (1 Tx x 2 Rx, 16 samples,
// 4 chirps) keeps one execution in the tens of microseconds. The input's
// bytes are tiled over the cube, so short inputs fill it; modes give
// all-zero and saturated int16 cubes and raw float cubes (NaN/Inf).
#include <cstddef>
#include <cstdint>

#include "fuzz_common.h"
#include "mptrack/frontend/front_end.h"

namespace {
namespace fe = mptrack::frontend;

struct FuzzRadarCaps {
  static constexpr std::size_t kNumTx = 1;
  static constexpr std::size_t kNumRx = 2;
  static constexpr std::size_t kNumSamples = 16;
  static constexpr std::size_t kRangeFftSize = 16;
  static constexpr std::size_t kNumRangeBins = 8;
  static constexpr std::size_t kNumChirps = 4;
  static constexpr std::size_t kNumAngleBins = 4;
  static constexpr std::size_t kMaxDetections = 8;
};

fe::FrontEnd<FuzzRadarCaps> g_fe;
fe::RadarCubeInt16<FuzzRadarCaps> g_cube16;
fe::RadarCube<FuzzRadarCaps> g_cubef;
mptrack::Scan<float, 6> g_scan;  // smaller than kMaxDetections: the scan caps too

fe::WindowType window_from(std::uint8_t b) { return static_cast<fe::WindowType>(b % 4u); }
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  mptrack::fuzz::FuzzReader in(data, size);
  fe::FrontEndParams p;
  p.chirp_duration_s = 0.25e-6;  // L = 8 samples: L + 8 bins - 1 <= 16
  p.max_range_m = 40.0;
  p.max_detections = 8;
  const std::uint8_t c0 = in.u8();
  const std::uint8_t c1 = in.u8();
  p.cfar.type = static_cast<fe::CfarType>(c0 % 4u);
  p.cfar.edge = static_cast<fe::CfarEdge>((c0 >> 2) % 3u);
  p.cfar.guard_cells = (c0 >> 4) & 1u;
  p.cfar.training_cells = 1u + ((c0 >> 5) & 1u);
  p.cfar.pfa = (c1 & 1u) != 0 ? 0.3 : 1e-3;
  p.remove_dc = (c1 & 2u) != 0;
  p.range_window = window_from(static_cast<std::uint8_t>(c1 >> 2));
  p.doppler_window = window_from(static_cast<std::uint8_t>(c1 >> 4));
  p.angle_window = window_from(static_cast<std::uint8_t>(c1 >> 6));
  const mptrack::Status si = g_fe.init(p);
  if (si != mptrack::Status::kOk) return 0;  // e.g. a window type the params reject

  const fe::FrontEndCounters before = g_fe.counters();  // init() keeps the counters
  const std::uint8_t mode = in.u8();
  const std::size_t n = g_cube16.iq.size();
  const std::size_t avail = in.remaining();
  mptrack::Status s;
  if ((mode & 1u) == 0) {  // int16 cube
    for (std::size_t i = 0; i < n; ++i) {
      std::int16_t v = 0;
      switch ((mode >> 1) % 4u) {
        case 0:  // tiled bytes
          if (avail >= 2) {
            const std::size_t k = (2 * i) % (avail - 1);
            v = static_cast<std::int16_t>(data[size - avail + k] | (data[size - avail + k + 1] << 8));
          }
          break;
        case 1: v = 0; break;  // all zero
        case 2:  // saturated: full-scale square wave
          v = ((i / 2) & 1u) != 0 ? std::int16_t{32767} : std::int16_t{-32768};
          break;
        default:  // saturated where the bytes say so
          v = (avail > 0 && (data[size - avail + i % avail] & 1u) != 0) ? std::int16_t{32767}
                                                                          : std::int16_t{-32768};
          break;
      }
      g_cube16.iq[i] = v;
    }
    s = g_fe.process(g_cube16, g_scan);
  } else {  // float cube from raw bits (NaN, Inf, huge)
    for (std::size_t i = 0; i < n; ++i) {
      float f = 0.0f;
      if (avail >= 4) {
        const std::size_t k = (4 * i) % (avail - 3);
        // Little-endian on every host, so a corpus file means the same cube
        // on big-endian targets too (tests/unit/regression_fuzz_test.cpp).
        const std::uint8_t* b = data + (size - avail) + k;
        const std::uint32_t bits = static_cast<std::uint32_t>(b[0]) | (static_cast<std::uint32_t>(b[1]) << 8) |
                                   (static_cast<std::uint32_t>(b[2]) << 16) | (static_cast<std::uint32_t>(b[3]) << 24);
        std::memcpy(&f, &bits, 4);
        // Half of the float cubes fold huge finite values into range, so
        // that frames both beyond max_abs_sample (refused, F2) and just
        // inside it (F3: amplitudes at the noise floor) are explored.
        if ((mode & 2u) != 0 && mptrack::is_finite(f) && (f > 1e6f || f < -1e6f)) f *= 1e-32f;
      }
      g_cubef.iq[i] = f;
    }
    s = g_fe.process(g_cubef, g_scan);
  }
  // kPartial: saturated int16 frame or a detection dropped for a
  // non-finite amplitude (F3); kInvalidInput: NaN/Inf, beyond the sample
  // ceiling (F2) or all zero.
  FUZZ_CHECK(s == mptrack::Status::kOk || s == mptrack::Status::kCapacityExceeded ||
             s == mptrack::Status::kInvalidInput || s == mptrack::Status::kPartial);
  if (s == mptrack::Status::kInvalidInput) FUZZ_CHECK(g_scan.measurements.empty());
  FUZZ_CHECK(g_scan.measurements.size() <= 6);
  for (const auto& m : g_scan.measurements) {
    if (!(mptrack::is_finite(m.amplitude) && m.amplitude >= 0.0f)) {
      std::fprintf(stderr, "measurement r=%g az=%g amp=%g dop=%g\n", static_cast<double>(m.range_m),
                   static_cast<double>(m.azimuth_rad), static_cast<double>(m.amplitude),
                   static_cast<double>(m.doppler_mps));
    }
    FUZZ_CHECK(mptrack::is_finite(m.range_m) && m.range_m >= 0.0f);
    FUZZ_CHECK(mptrack::is_finite(m.azimuth_rad));
    FUZZ_CHECK(mptrack::is_finite(m.amplitude) && m.amplitude >= 0.0f);
    FUZZ_CHECK(mptrack::is_finite(m.doppler_mps));
  }
  const auto& c = g_fe.counters();
  FUZZ_CHECK(c.frames + c.frames_rejected == before.frames + before.frames_rejected + 1);
  // the status tells which frame-level check fired, and the counter agrees
  const bool all_zero = c.frames_all_zero != before.frames_all_zero;
  const bool over = c.frames_over_ceiling != before.frames_over_ceiling;
  const bool saturated = c.frames_saturated != before.frames_saturated;
  const bool nonfinite = c.detections_nonfinite != before.detections_nonfinite;
  if (all_zero || over) FUZZ_CHECK(s == mptrack::Status::kInvalidInput);
  if (s == mptrack::Status::kPartial) FUZZ_CHECK(saturated || nonfinite);
  if (saturated || nonfinite) {
    FUZZ_CHECK(s == mptrack::Status::kPartial || s == mptrack::Status::kCapacityExceeded);
  }
  if ((mode & 1u) == 0 && (mode >> 1) % 4u == 1) FUZZ_CHECK(all_zero);
  FUZZ_CHECK(c.detections - before.detections == g_scan.measurements.size());
  return 0;
}
