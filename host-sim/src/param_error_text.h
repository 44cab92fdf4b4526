// The harness's wording of a refused parameter (validate.h ParamError):
//   "mfbp.window_length = 100: must be <= 7 (Caps::kMaxWindow)"
// Core validate() records field, value and bounds without heap; the text
// is composed here, on the host.
#pragma once

#include <string>

#include "mptrack/validate.h"

namespace mptrack::sim {

/// "<prefix>.<field> = <value>: must be <bounds> (<limit>)"; prefix "" gives
/// the bare field. A plain condition (no figures) reads
/// "<field>: must satisfy <rule as written in validate()>".
std::string describe_param_error(const std::string& prefix, const ParamError& e);

/// The bounds alone: "must be in (0, 3600]", "must be <= 7 (Caps::kMaxWindow)".
std::string describe_bounds(const CheckResult& r);

/// %g of x, "nan", "inf" or "-inf".
std::string format_number(double x);

}  // namespace mptrack::sim
