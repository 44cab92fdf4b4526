// plot.svg: left, the x/y picture of run 0 (region, truth trajectories,
// confirmed tracks, true clutter components dashed, estimated components as
// 2-sigma ellipses every 10 scans); right, OSPA over time (mean over runs)
// with the evaluation interval shaded. Plain SVG 1.1, no dependencies.
#pragma once

#include <string>
#include <vector>

#include "mptrack/scenario/generator.h"
#include "tracker_adapter.h"

namespace mptrack::sim {

void write_plot_svg(const std::string& path, const scenario::ScenarioSpec& spec,
                    const std::vector<scenario::SimScan>& scans, const std::vector<EstimateOut>& estimates,
                    const std::vector<double>& ospa_per_scan, const std::string& title);

}  // namespace mptrack::sim
