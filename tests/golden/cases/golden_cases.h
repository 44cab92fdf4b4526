// Declarations of every golden case listed in golden_cases.def.
#pragma once

#include "golden_sink.h"

namespace mptrack::test {
#define MPTRACK_GOLDEN_CASE(name, source) void golden_case_##name(GoldenSink& g);
#include "golden_cases.def"
#undef MPTRACK_GOLDEN_CASE
}  // namespace mptrack::test
