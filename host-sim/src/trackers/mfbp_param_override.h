// `--mfbp-param NAME=VALUE` (host-sim/README.md): sets the MfbpParams fields
// a user tunes most, by name, for the measurement-level and the raw-ADC MF-BP
// trackers. Units and defaults are in core/include/mptrack/mfbp/mfbp_params.h;
// the tracker's init() still validates the result.
#pragma once

#include <string>
#include <vector>

#include "mptrack/mfbp/mfbp_params.h"

namespace mptrack::sim {

/// Applies one "name=value"; returns "" or an error naming the field.
std::string apply_mfbp_param(MfbpParams<double>& p, const std::string& kv);

/// Applies every override in order; returns the first error or "".
std::string apply_mfbp_params(MfbpParams<double>& p, const std::vector<std::string>& overrides);

}  // namespace mptrack::sim
