// Must NOT compile: a caps type with zero targets is rejected by
// caps_are_valid() with a readable static_assert (test failtest_bad_caps).
#include "mptrack/caps.h"

struct ZeroTargetCaps {
  static constexpr std::size_t kMaxTargets = 0;
  static constexpr std::size_t kMaxMeasurements = 16;
  static constexpr std::size_t kMaxClutterComponents = 2;
  static constexpr std::size_t kMaxWindow = 1;
};

static_assert(mptrack::caps_are_valid<ZeroTargetCaps>());

int main() { return 0; }
