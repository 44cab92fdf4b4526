// Cortex-M7 image of the seed 003 patch classifier alone (issue 13): its
// flash and RAM from the linked image (arm-none-eabi-size / nm, the
// classifier's own symbols listed by docs/algorithms/nemp.md §Cost) and its
// instructions per detection under qemu-system-arm -icount shift=0, by the
// SysTick method of scan_cost.cpp (docs/targets.md §"Instructions per
// scan": 1 instruction per ns of virtual time, one 25 MHz tick per 40 ns).
//
// The network runs with the trained weights (classify/generated/, the set
// the tracker deploys) on the three reference patches of the golden case;
// the cost does not depend on the values beyond a few branches (ReLU,
// max-pool, the exp's range reduction), which is why three patches are
// timed. Ends with "classifier cost: PASS" if every call returned kOk.
#include <cstddef>
#include <cstdint>
#include <new>

#include "../unit/classify_reference_data.h"
#include "mptrack/classify/sea_classifier.h"
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

// The classifier's RAM (two ping-pong buffers), constructed in raw .bss
// storage: a plain `SeaClassifier g;` is constant-initialised with the
// weights' non-zero defaults (input_scale 1, train_target_fraction 0.5), so
// GCC puts the whole 30 KiB object in .data and its initial image in flash.
alignas(cl::SeaClassifier) unsigned char g_classifier_storage[sizeof(cl::SeaClassifier)];
float g_patch[cl::kPatchSize];    // .bss: the caller's input patch, not the classifier's

void print_insns(const char* what, std::size_t patch, std::uint32_t ticks) {
  sh_write(what);
  sh_write(" patch ");
  sh_write_uint(patch);
  sh_write(": ");
  sh_write_uint(static_cast<std::uint64_t>(ticks) * kInsnPerTick);
  sh_write(" instructions (SysTick resolution: 40)\n");
}

}  // namespace

extern "C" int app_main() {
  mptrack::baremetal::systick_start();
  const std::uint32_t cal = mptrack::baremetal::icount_calibration_ticks();
  sh_write("icount calibration: 2000000-instruction loop = ");
  sh_write_uint(cal);
  sh_write(" SysTick ticks (40 expected under -icount shift=0)\n");

  cl::SeaClassifier& g_classifier = *::new (static_cast<void*>(g_classifier_storage)) cl::SeaClassifier();
  bool ok = cl::kHaveTrainedWeights && g_classifier.init(cl::trained_weights()) == Status::kOk;
  for (std::size_t p = 0; ok && p < mptrack::test::classify_ref::kNumPatches; ++p) {
    for (std::size_t i = 0; i < cl::kPatchSize; ++i) {
      g_patch[i] = static_cast<float>(mptrack::test::classify_ref::kPatches[p][i]);
    }
    cl::Features f{};
    const std::uint32_t s0 = systick_now();
    ok = g_classifier.features(g_patch, f) == Status::kOk;
    const std::uint32_t feat = ticks_since(s0);
    const std::uint32_t s1 = systick_now();
    volatile float w = g_classifier.target_probability(f, 0.5f);
    const std::uint32_t mlp = ticks_since(s1);
    (void)w;
    print_insns("classifier features() (CNN g_M)", p, feat);
    print_insns("classifier target_probability() (MLP g_c, one NEMP round)", p, mlp);
  }
  sh_write(ok ? "classifier cost: PASS\n" : "classifier cost: FAIL (no trained weights, init or features)\n");
  mptrack::baremetal::sh_exit(ok);
}
