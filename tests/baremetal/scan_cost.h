// Instructions per scan of the MF-BP filter on the Cortex-M7 under QEMU
// (see scan_cost.cpp): printed by the golden runner after the goldens.
#pragma once

namespace mptrack::baremetal {

/// Runs MfbpTracker<float, DefaultCaps> (online filter, window 1) on the
/// embedded seed000-s2 scans 1..5 and prints SysTick-derived instruction
/// counts per step(). Returns false if the input could not be parsed or a
/// step failed.
bool report_mfbp_scan_cost(const char* s2_golden_text);

}  // namespace mptrack::baremetal
