// Turns the benchmark runs into <out>/results.json, <out>/latency.svg and
// the summary table printed by `./run bench`.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace mptrack::bench {

/// What the writer needs of one benchmark run (aggregates are skipped).
struct RunRecord {
  std::string name;                       ///< e.g. "fft/ours/256", "grid/gmphd/float/T8/M128/C2"
  double time_ns = 0.0;                   ///< real (or manual) time per iteration [ns]
  double cpu_ns = 0.0;                    ///< CPU time of this thread per iteration [ns]
  double iterations = 0.0;
  std::map<std::string, double> counters;
  bool error = false;
};

struct MachineInfo {
  int num_cpus = 0;
  double mhz_per_cpu = 0.0;
  std::string build_type;
  std::string compiler;
  std::string timestamp_utc;
};

/// Writes <dir>/results.json and <dir>/latency.svg; prints the table to stdout.
/// Returns false if a file could not be written.
bool write_results(const std::string& dir, const std::vector<RunRecord>& runs, const MachineInfo& machine);

}  // namespace mptrack::bench
