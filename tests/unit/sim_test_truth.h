// Truth states for the host-harness tests (sim_*_test.cpp): a target at
// (x, y) [m], at rest, whose detection is measurement meas (-1 = missed).
#pragma once

#include <cstdint>

#include "mptrack/scenario/generator.h"

namespace sim_test {

inline mptrack::scenario::TruthState truth_at(std::uint32_t id, double x, double y, std::int32_t meas) {
  mptrack::scenario::TruthState t;
  t.target_id = id;
  t.x.px = x;
  t.x.py = y;
  t.measurement_index = meas;
  return t;
}

}  // namespace sim_test
