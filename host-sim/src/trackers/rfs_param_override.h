// `--rfs-param NAME=VALUE` (host-sim/README.md): sets the RfsFilterParams
// fields a user tunes most, by name, for the seed 001 baselines (gmphd,
// gmcphd, cbmember and their variants), after the harness has derived the
// rest from the scenario. Units and defaults are in
// core/include/mptrack/rfs/rfs_params.h; the filter's init() still validates
// the result.
#pragma once

#include <string>
#include <vector>

#include "mptrack/rfs/rfs_params.h"

namespace mptrack::sim {

/// Applies every "name=value" in order; returns the first error (naming the
/// field) or "".
std::string apply_rfs_params(RfsFilterParams<double>& p, const std::vector<std::string>& overrides);

}  // namespace mptrack::sim
