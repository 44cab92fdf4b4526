// Recorded detections as JSON: the same content as the CSV of
// detections_csv.h, for recorders that already speak JSON.
//
//   {"schema": "mptrack-detections/1",
//    "scans": [{"time_s": 12.5,
//               "detections": [{"range_m": 10234.1, "azimuth_rad": 0.716,
//                               "amplitude": 2.31, "doppler_mps": -3.2}]},
//              {"time_s": 13.75, "detections": []}]}
//
// Each detection gives azimuth_rad or azimuth_deg; doppler_mps is optional
// and, if given, must be given for every detection. Scans in time order
// (times must not decrease; equal times merge into one scan, as in the CSV).
// Every field is checked with the CSV's rules; an error names the file and
// the JSON path: "FILE: scans[3].detections[1].amplitude: must be > 0".
#pragma once

#include <string>
#include <vector>

#include "mptrack/scenario/generator.h"

namespace mptrack::sim {

inline constexpr const char* kDetectionsJsonSchema = "mptrack-detections/1";

/// The scans of a detections JSON file (as read_detections_csv: scan k
/// 1-based, measurements in file order, origin unknown, no truth).
std::vector<scenario::SimScan> read_detections_json(const std::string& path);

/// Writes `scans` in the format above (radians; numbers round-trip exactly).
void write_detections_json(const std::string& path, const std::vector<scenario::SimScan>& scans);

/// read_detections_json for a path ending in ".json", else read_detections_csv.
std::vector<scenario::SimScan> read_detections_file(const std::string& path);

}  // namespace mptrack::sim
