// Twin of bad_caps.cpp that must compile, so failtest_bad_caps fails for
// the right reason (the static_assert), not a broken harness.
#include "mptrack/caps.h"

struct OneTargetCaps {
  static constexpr std::size_t kMaxTargets = 1;
  static constexpr std::size_t kMaxMeasurements = 16;
  static constexpr std::size_t kMaxClutterComponents = 2;
  static constexpr std::size_t kMaxWindow = 1;
};

static_assert(mptrack::caps_are_valid<OneTargetCaps>());

int main() { return 0; }
