// Explicit instantiations of core components for the shipped scalar types.
//
// Compiling them here (with -fno-exceptions -fno-rtti, EIGEN_NO_MALLOC) is
// what lets the no-heap check run `nm` on real code: any operator new,
// malloc or __cxa_throw reachable from core shows up as an undefined symbol
// of this library.
#include "mptrack/caps.h"
#include "mptrack/measurement.h"
#include "mptrack/static_vector.h"
#include "mptrack/status.h"
#include "mptrack/validate.h"

namespace mptrack {

template class StaticVector<Measurement<float>, DefaultCaps::kMaxMeasurements>;
template class StaticVector<Measurement<double>, DefaultCaps::kMaxMeasurements>;

static_assert(caps_are_valid<DefaultCaps>());
static_assert(caps_are_valid<SmallBoardCaps>());
static_assert(caps_are_valid<LargeCaps>());

}  // namespace mptrack
