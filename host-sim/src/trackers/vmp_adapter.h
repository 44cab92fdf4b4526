// Adapter of seed 004's VMP tracker (raw frames; vmp_adapter.cpp).
#pragma once

#include <memory>

#include "tracker_adapter.h"

namespace mptrack::sim {

/// `--tracker vmp`: consumes FrameInput::kRawFrame; init() refuses a
/// measurement-level scenario with a message.
std::unique_ptr<TrackerAdapter> make_vmp_adapter();

}  // namespace mptrack::sim
