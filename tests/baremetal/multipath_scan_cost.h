// Instructions per scan of the multipath MF-BP tracker on the Cortex-M7
// under QEMU (see multipath_scan_cost.cpp): printed by the golden runner.
#pragma once

namespace mptrack::baremetal {

/// Runs MultipathMfbpTracker<float, ...> (lag 3, the harness's Params) on
/// the embedded seed002-othr run 0 of the four Table IV cells
/// (tests/support/othr_scan_file.h) and prints, per cell, instructions per
/// step() p50 / p99 / max, the tracker's size and a hash of its outputs.
/// Returns false if the input could not be read or a step failed.
bool report_multipath_scan_cost(const unsigned char* begin, const unsigned char* end);

}  // namespace mptrack::baremetal
