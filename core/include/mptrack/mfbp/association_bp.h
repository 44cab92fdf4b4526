// MF-BP's loopy BP is the shared one of assoc/association_bp.h (seed 000
// eqs. (99)-(102)); this name keeps MF-BP's code and tests unchanged.
#pragma once

#include "mptrack/assoc/association_bp.h"

namespace mptrack::mfbp {

using assoc::AssociationBp;

}  // namespace mptrack::mfbp
