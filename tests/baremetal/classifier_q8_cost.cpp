// Cortex-M7 image of the int8 CNN g_M of the seed 003 patch classifier
// alone (sea_features_q8.h, docs/algorithms/nemp.md §int8 inference): flash
// and RAM from the linked image (arm-none-eabi-size / nm) and instructions
// per detection under qemu-system-arm -icount shift=0, by the SysTick method
// of classifier_cost.cpp (the float network's image). The trained int8 set
// on the three reference patches of the golden case, read as the detector's
// uint8 codes (no float copy of the patch). Ends with "classifier q8 cost:
// PASS" if every call returned kOk.
#include <cstddef>
#include <cstdint>
#include <new>

#include "../unit/classify_reference_data.h"
#include "mptrack/classify/sea_features_q8.h"
#include "mptrack/classify/trained_weights.h"
#include "semihost.h"
#include "systick_icount.h"

namespace {

namespace cl = mptrack::classify;
using mptrack::Status;
using mptrack::baremetal::sh_write;
using mptrack::baremetal::sh_write_uint;
using mptrack::baremetal::kInsnPerTick;
using mptrack::baremetal::systick_now;
using mptrack::baremetal::ticks_since;

// Raw .bss storage, as in classifier_cost.cpp (no initial image in flash).
alignas(cl::SeaFeaturesQ8) unsigned char g_features_storage[sizeof(cl::SeaFeaturesQ8)];

}  // namespace

extern "C" int app_main() {
  mptrack::baremetal::systick_start();
  const std::uint32_t cal = mptrack::baremetal::icount_calibration_ticks();
  sh_write("icount calibration: 2000000-instruction loop = ");
  sh_write_uint(cal);
  sh_write(" SysTick ticks (40 expected under -icount shift=0)\n");

  cl::SeaFeaturesQ8& q = *::new (static_cast<void*>(g_features_storage)) cl::SeaFeaturesQ8();
  bool ok = cl::kHaveTrainedQ8Weights && q.init(cl::trained_q8_weights()) == Status::kOk;
  for (std::size_t p = 0; ok && p < mptrack::test::classify_ref::kNumPatches; ++p) {
    cl::Features f{};
    const std::uint32_t s0 = systick_now();
    ok = q.features(mptrack::test::classify_ref::kPatches[p], f) == Status::kOk;
    const std::uint32_t ticks = ticks_since(s0);
    sh_write("int8 features() (CNN g_M) patch ");
    sh_write_uint(p);
    sh_write(": ");
    sh_write_uint(static_cast<std::uint64_t>(ticks) * kInsnPerTick);
    sh_write(" instructions (SysTick resolution: 40)\n");
  }
  sh_write(ok ? "classifier q8 cost: PASS\n" : "classifier q8 cost: FAIL (no int8 weights, init or features)\n");
  mptrack::baremetal::sh_exit(ok);
}
