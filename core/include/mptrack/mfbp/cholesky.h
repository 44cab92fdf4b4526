// Forwarding header: the Cholesky routines live in model/cholesky.h.
#pragma once

#include "mptrack/model/cholesky.h"

namespace mptrack::mfbp {
using model::cholesky;
using model::cholesky_solve;
using model::cholesky_whiten;
}  // namespace mptrack::mfbp
