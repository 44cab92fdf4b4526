// Clipping a scenario to its first N scans (measurement level) or frames
// (raw ADC): lifetimes, the evaluation interval and phases are clipped, what
// is born later is dropped.
#pragma once

#include <cstdint>

#include "mptrack/adc/adc_scenario.h"
#include "mptrack/scenario/scenario_spec.h"

namespace mptrack::sim {

/// Keeps the first `scans` scans (eval interval and lifetimes clipped); 0 = all.
void truncate_scans(scenario::ScenarioSpec& s, std::uint32_t scans);

/// Keeps the first `frames` frames (lifetimes and phases clipped); 0 = all.
void truncate_frames(adc::AdcScenario& s, std::uint32_t frames);

}  // namespace mptrack::sim
