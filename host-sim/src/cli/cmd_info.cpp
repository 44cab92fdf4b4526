// `mptrack-sim info`: caps presets, trackers, tracker footprints, scenarios.
#include <cstdio>

#include "cli/commands.h"
#include "mptrack/caps.h"
#include "mptrack/measurement.h"
#include "mptrack/scenario/builtin.h"
#include "tracker_registry.h"

namespace mptrack::sim {

namespace {

template <class Caps>
void print_caps(const char* name) {
  using ScanF = Scan<float, Caps::kMaxMeasurements>;
  std::printf("  %-11s targets %4zu  measurements %5zu  clutter comps %2zu  window %zu  sizeof(Scan<float>) %7zu B\n",
              name, Caps::kMaxTargets, Caps::kMaxMeasurements, Caps::kMaxClutterComponents,
              Caps::kMaxWindow, sizeof(ScanF));
}

int run_info() {
  std::printf("mptrack %s\n", "0.1.0");
  std::printf("caps presets:\n");
  print_caps<SmallBoardCaps>("SmallBoard");
  print_caps<DefaultCaps>("Default");
  print_caps<LargeCaps>("Large");
  std::printf("trackers:\n");
  for (const auto& t : tracker_list()) {
    std::printf("  %-12s %s\n", t.name.c_str(), t.description.c_str());
  }
  std::printf("tracker footprint (sizeof, DefaultCaps):\n");
  for (const auto& f : tracker_footprints()) {
    std::printf("  %-40s float %9zu B  double %9zu B\n", f.name.c_str(), f.bytes_float, f.bytes_double);
  }
  std::printf("scenarios:");
  for (const auto& n : scenario::builtin_scenario_names()) std::printf(" %s", n.c_str());
  std::printf("\n");
  return 0;
}

}  // namespace

Subcommand add_info_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("info", "print build configuration, caps presets, trackers and scenarios");
  return Subcommand{cmd, [](const RunOptions&) { return run_info(); }};
}

}  // namespace mptrack::sim
