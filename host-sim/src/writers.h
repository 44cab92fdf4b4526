// CSV and summary.json writers (columns documented in host-sim/README.md).
#pragma once

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "eval/aggregator.h"
#include "eval/scan_evaluator.h"
#include "mptrack/scenario/generator.h"
#include "tracker_adapter.h"

namespace mptrack::sim {

inline constexpr const char* kTruthCsvHeader = "run,scan,target_id,x,y,vx,vy,snr,eval";
inline constexpr const char* kMeasurementsCsvHeader = "run,scan,range,azimuth,amplitude,origin";
inline constexpr const char* kTracksCsvHeader = "run,scan,track_id,x,y,vx,vy,existence,snr,confirmed,eval";
inline constexpr const char* kMetricsCsvHeader =
    "run,scan,ospa,gospa,truths,confirmed,false_tracks,car_correct,car_total,car_id_correct,latency_us,eval";

/// "target:<id>" or "clutter:<id>".
std::string origin_label(const scenario::Origin& o);

/// The four per-run CSV files of an output directory.
class CsvWriters {
 public:
  explicit CsvWriters(const std::string& dir);  ///< creates dir, writes the header rows; throws on I/O errors
  void write_run(std::uint32_t run, const scenario::ScenarioSpec& spec, const std::vector<scenario::SimScan>& scans,
                 const std::vector<EstimateOut>& by_scan, const std::vector<ScanMetrics>& metrics,
                 const std::vector<double>& latency_us);

 private:
  std::ofstream truth_, measurements_, tracks_, metrics_;
};

nlohmann::ordered_json summary_to_json(const Summary& s);
/// Per-object RMSE block of summary.json and compare.json: p50, p90, max,
/// objects, never_matched and the sorted values (the empirical CDF).
nlohmann::ordered_json object_rmse_json(const Summary& s);
/// Adds the track scores (track_scoring.h) of `s` to its summary.json object.
void add_track_scores_json(const Summary& s, nlohmann::ordered_json& j);
/// Per target id over runs (summary.json and compare.json "by_target"):
/// ttl_scans (confirmation delay of the runs it was tracked in),
/// never_tracked (runs) and coverage_from_birth5.
nlohmann::ordered_json track_scores_by_target_json(const TrackScoreTotals& t);
void write_summary_json(const Summary& s, const std::string& path);

}  // namespace mptrack::sim
