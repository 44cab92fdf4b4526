// Paired Monte Carlo differences: trackers that ran on the same scenes (the
// run loop hands every tracker of one run the same SimScan objects) are
// compared run by run, so the scene-to-scene spread cancels and the standard
// error is that of the per-run differences (docs/algorithms/metrics.md
// §Paired differences).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace mptrack::sim {

struct PairedDifference {
  double mean = 0.0;            ///< mean over runs of a[r] - b[r]
  double standard_error = 0.0;  ///< sample standard deviation of the differences / sqrt(runs); 0 for one run
  std::size_t runs = 0;         ///< pairs compared; 0 when the inputs differ in length or are empty
  std::size_t a_lower = 0;      ///< runs with a[r] < b[r]
};

/// a - b, paired by run index.
PairedDifference paired_difference(const std::vector<double>& a, const std::vector<double>& b);

/// "-2.52 +- 1.46 (lower in 40 of 100)": mean +- standard error (runs with a lower), `digits` after the point;
/// "n/a" when nothing was compared.
std::string paired_difference_text(const PairedDifference& d, int digits);

}  // namespace mptrack::sim
