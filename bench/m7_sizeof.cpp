// sizeof of every top-level core object as the Cortex-M7 compiler lays it
// out (32-bit pointers and size_t), for bench/footprint.sh.
//
// Compiled to an object file only, never linked: each array below is a
// .bss symbol whose size (arm-none-eabi-nm -S) is the sizeof of one object,
// so even objects too large to place in the image side by side are sized.
#include "mptrack/caps.h"
#include "mptrack/cbmember/cbmember_filter.h"
#include "mptrack/frontend/front_end.h"
#include "mptrack/gnn/gnn_tracker.h"
#include "mptrack/measurement.h"
#include "mptrack/mfbp/mfbp_tracker.h"
#include "mptrack/multipath/multipath_tracker.h"
#include "mptrack/phd/phd_filter.h"

#define MPTRACK_SIZEOF(name, ...) extern "C" { alignas(8) char mptrack_sizeof__##name[sizeof(__VA_ARGS__)]; }

namespace m = mptrack;
namespace fe = mptrack::frontend;

MPTRACK_SIZEOF(MfbpTracker_float_DefaultCaps, m::MfbpTracker<float, m::DefaultCaps>)
MPTRACK_SIZEOF(MfbpTracker_float_SmallBoardCaps, m::MfbpTracker<float, m::SmallBoardCaps>)
MPTRACK_SIZEOF(MfbpTracker_float_LargeCaps, m::MfbpTracker<float, m::LargeCaps>)
MPTRACK_SIZEOF(GmPhdFilter_float_DefaultCaps, m::GmPhdFilter<float, m::DefaultCaps>)
MPTRACK_SIZEOF(GmPhdFilter_float_SmallBoardCaps, m::GmPhdFilter<float, m::SmallBoardCaps>)
MPTRACK_SIZEOF(GmCphdFilter_float_DefaultCaps, m::GmCphdFilter<float, m::DefaultCaps>)
MPTRACK_SIZEOF(GmCphdFilter_float_SmallBoardCaps, m::GmCphdFilter<float, m::SmallBoardCaps>)
MPTRACK_SIZEOF(CbMemberFilter_float_DefaultCaps, m::CbMemberFilter<float, m::DefaultCaps>)
MPTRACK_SIZEOF(CbMemberFilter_float_SmallBoardCaps, m::CbMemberFilter<float, m::SmallBoardCaps>)
MPTRACK_SIZEOF(GnnTracker_float_DefaultCaps, m::GnnTracker<float, m::DefaultCaps>)
MPTRACK_SIZEOF(GnnTracker_float_SmallBoardCaps, m::GnnTracker<float, m::SmallBoardCaps>)
MPTRACK_SIZEOF(MultipathMfbpTracker_float_DefaultCaps, m::MultipathMfbpTracker<float, m::DefaultCaps>)
MPTRACK_SIZEOF(MultipathMfbpTracker_float_SmallBoardCaps, m::MultipathMfbpTracker<float, m::SmallBoardCaps>)
MPTRACK_SIZEOF(FrontEnd_Seed004RadarCaps, fe::FrontEnd<fe::Seed004RadarCaps>)
MPTRACK_SIZEOF(FrontEnd_LargeRadarCaps, fe::FrontEnd<fe::LargeRadarCaps>)
MPTRACK_SIZEOF(RadarCubeInt16_Seed004RadarCaps, fe::RadarCubeInt16<fe::Seed004RadarCaps>)
MPTRACK_SIZEOF(Scan_float_DefaultCaps, m::Scan<float, m::DefaultCaps::kMaxMeasurements>)
MPTRACK_SIZEOF(Scan_float_SmallBoardCaps, m::Scan<float, m::SmallBoardCaps::kMaxMeasurements>)
