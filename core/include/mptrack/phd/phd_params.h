// Parameters of GM-PHD / GM-CPHD: the shared Gaussian-mixture RFS parameter
// block (rfs/rfs_params.h) under the PHD filters' names.
#pragma once

#include "mptrack/rfs/rfs_params.h"

namespace mptrack::phd {
using rfs::ClutterMode;
using rfs::FilterParams;
using rfs::MeasurementSpace;
}  // namespace mptrack::phd
