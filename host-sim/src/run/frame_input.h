// What a tracker consumes on a raw-ADC scenario (stream/adc_source.h): the
// detections of the matched filter + CFAR front end, the detections of the
// per-frame SBL detector (seed 004's detect-then-track baseline), or the raw
// frame itself (seed 004's VMP tracker). Measurement-level sources always
// deliver detections and never a frame.
#pragma once

#include <cstdint>

#include "mptrack/frontend/radar_caps.h"
#include "mptrack/frontend/radar_cube.h"

namespace mptrack::sim {

/// The raw frame of the raw-ADC scenarios: seed 004's 3 x 3 TDM-MIMO radar,
/// the type the streaming ring carries.
using RawFrame = frontend::RadarCube<frontend::Seed004RadarCaps>;

enum class FrameInput : std::uint8_t {
  kCfarDetections,  ///< matched filter + CFAR front end (frontend/front_end.h)
  kSblDetections,   ///< per-frame SBL detector (sbl/)
  kRawFrame,        ///< the frame itself: the tracker's step_frame()
};

}  // namespace mptrack::sim
