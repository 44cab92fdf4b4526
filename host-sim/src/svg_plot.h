// plot.svg: left, the x/y picture of run 0 (region, truth trajectories,
// confirmed tracks, true clutter components dashed, estimated components as
// 2-sigma ellipses every 10 scans); right, OSPA over time (mean over runs)
// with the evaluation interval shaded. Plain SVG 1.1, no dependencies.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "mptrack/scenario/generator.h"
#include "tracker_adapter.h"

namespace mptrack::sim {

void write_plot_svg(const std::string& path, const scenario::ScenarioSpec& spec,
                    const std::vector<scenario::SimScan>& scans, const std::vector<EstimateOut>& estimates,
                    const std::vector<double>& ospa_per_scan, const std::string& title, double order_p = 2.0,
                    double cutoff_m = 631.0);

/// One line of the comparison plot: a tracker's mean OSPA per scan [m].
struct OspaSeries {
  std::string name;
  std::vector<double> ospa_per_scan;  ///< index scan-1
};

/// ospa.svg of `mptrack-sim compare`: OSPA over scans, one coloured line per
/// tracker with a legend, the evaluation interval shaded.
void write_ospa_comparison_svg(const std::string& path, const std::string& title,
                               const std::vector<OspaSeries>& series, std::uint32_t eval_first_scan,
                               std::uint32_t eval_last_scan, double order_p, double cutoff_m);

}  // namespace mptrack::sim
