// The consumer's C++ part: GnnTracker<float, DefaultCaps> (explicitly
// instantiated in libmptrack_core_static) next to the C part (c_side.c).
#include <cstdio>

#include "mptrack/caps.h"
#include "mptrack/gnn/gnn_tracker.h"

extern "C" int consumer_c_side(void);

namespace {
mptrack::GnnTracker<float, mptrack::DefaultCaps> g_tracker;  // .bss
mptrack::GnnTracker<float, mptrack::DefaultCaps>::ScanType g_scan;
}  // namespace

int main() {
  mptrack::GnnParams<float> p;
  p.report_tentative = true;
  if (g_tracker.init(p) != mptrack::Status::kOk) return 1;
  mptrack::Measurement<float> m;
  m.range_m = 100.0f;
  m.azimuth_rad = 0.25f;
  m.amplitude = 5.0f;
  g_scan.time_us = 1000000u;
  if (g_scan.measurements.push_back(m) != mptrack::Status::kOk) return 1;
  if (g_tracker.step(g_scan) != mptrack::Status::kOk) return 1;
  const int cpp_tracks = static_cast<int>(g_tracker.outputs()[0].tracks.size());
  const int c_tracks = consumer_c_side();
  std::printf("consumer: C++ GNN %d track(s), C API GNN %d track(s)\n", cpp_tracks, c_tracks);
  return cpp_tracks == 1 && c_tracks == 1 ? 0 : 1;
}
