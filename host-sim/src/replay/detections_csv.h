// Recorded detections as CSV: what `mptrack-sim replay` reads and
// `mptrack-sim --write-detections` writes (host-sim/README.md, "Replaying
// recorded detections").
//
//   time_s,range_m,azimuth_deg,amplitude[,doppler_mps]     (header required)
//   12.5,10234.1,41.02,2.31                                (one detection)
//   13.75,,,                                               (a scan without detections)
//
// Rows with the same time_s form one scan; times must not decrease. The
// azimuth column is azimuth_rad or azimuth_deg (the header says which).
// amplitude is the normalised envelope sqrt(power / N0) (> 0). Every field
// is checked; a malformed row is an error naming file, line and column.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "mptrack/scenario/generator.h"

namespace mptrack::sim {

/// The scans of a detections file: scan k (1-based) at its time, with its
/// measurements in file order (origin unknown: clutter id 0), no truth.
/// Throws std::runtime_error "FILE:LINE: column N (NAME): why".
std::vector<scenario::SimScan> read_detections_csv(const std::string& path);

/// Header of write_detections_csv (radians; Doppler column when a scan has Doppler).
std::string detections_csv_header(bool doppler);

/// Writes `scans` in the format above with every number round-tripping
/// exactly (%.17g; times in whole microseconds), so replaying the file
/// feeds a tracker the same bits. Throws on I/O errors.
void write_detections_csv(const std::string& path, const std::vector<scenario::SimScan>& scans);

}  // namespace mptrack::sim
