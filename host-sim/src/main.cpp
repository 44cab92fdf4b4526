// mptrack-sim: the host harness command-line tool.
#include <CLI/CLI.hpp>
#include <cstdio>

#include "mptrack/caps.h"
#include "mptrack/measurement.h"

namespace {

template <class Caps>
void print_caps(const char* name) {
  using ScanF = mptrack::Scan<float, Caps::kMaxMeasurements>;
  std::printf("  %-11s targets %4zu  measurements %5zu  clutter comps %2zu  window %zu  sizeof(Scan<float>) %7zu B\n",
              name, Caps::kMaxTargets, Caps::kMaxMeasurements, Caps::kMaxClutterComponents,
              Caps::kMaxWindow, sizeof(ScanF));
}

int run_info() {
  std::printf("mptrack %s\n", "0.1.0");
  std::printf("caps presets:\n");
  print_caps<mptrack::SmallBoardCaps>("SmallBoard");
  print_caps<mptrack::DefaultCaps>("Default");
  print_caps<mptrack::LargeCaps>("Large");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"mptrack-sim: host harness for the mptrack multitarget tracker"};
  app.require_subcommand(0, 1);
  auto* info = app.add_subcommand("info", "print build configuration and caps presets");
  CLI11_PARSE(app, argc, argv);
  if (info->parsed() || app.get_subcommands().empty()) return run_info();
  return 0;
}
