// Bare-metal golden runner (Cortex-M7 under qemu-system-arm; Hexagon under
// qemu-hexagon with hexagon_rt.cpp in place of semihost.cpp): every case of tests/golden/cases/golden_cases.def
// runs on the target and its values are compared, line by line and bit for
// bit, with the golden file embedded in the image (golden_data.cpp, generated
// by CMake with .incbin). Output and exit status go through semihosting, so
// `qemu-system-arm -M mps2-an500 ... -kernel mptrack_m7_goldens.elf` prints
// one line per golden file and exits 0 only if every value matched.
//
// No heap, no stdio: lines are formatted by the shared format_line() into a
// stack buffer, numbers printed by hand.
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "golden_cases.h"
#include "semihost.h"
#if defined(__arm__)
#include "multipath_scan_cost.h"
#include "scan_cost.h"
#endif

namespace mptrack::test {
#define MPTRACK_GOLDEN_CASE(name, source) extern "C" const char mptrack_golden_##name[];
#include "golden_cases.def"
#undef MPTRACK_GOLDEN_CASE
#if defined(__arm__)
extern "C" const char mptrack_golden_scenario_s2_scans1to5[];  // input of the scan-cost report
extern "C" const unsigned char mptrack_seed002_scans[];             // input of the multipath one
extern "C" const unsigned char mptrack_seed002_scans_end[];
#endif
}  // namespace mptrack::test

namespace {

using mptrack::baremetal::sh_write;
using mptrack::baremetal::sh_write_uint;
using mptrack::test::GoldenSink;

struct Case {
  const char* name;
  void (*run)(GoldenSink&);
  const char* golden;  // the committed file's text, NUL-terminated
};

constexpr Case kCases[] = {
#define MPTRACK_GOLDEN_CASE(name, source) \
  {#name, &mptrack::test::golden_case_##name, mptrack::test::mptrack_golden_##name},
#include "golden_cases.def"
#undef MPTRACK_GOLDEN_CASE
};

/// Compares each recorded line with the next line of the embedded file.
class EmbeddedSink final : public GoldenSink {
 public:
  EmbeddedSink(const char* name, const char* golden) : name_(name), next_(golden) {}

  std::uint32_t compared() const { return compared_; }
  std::uint32_t differ() const { return differ_; }
  /// Lines of the file no recorded value reached (the case stopped early).
  std::uint32_t unread() const {
    std::uint32_t n = 0;
    for (const char* p = next_; *p != '\0'; ++p) n += (*p == '\n') ? 1u : 0u;
    return n;
  }

 private:
  void add_f32(const char* label, float v) override { add_line(label, 'f', mptrack::test::bits_of(v)); }
  void add_f64(const char* label, double v) override { add_line(label, 'd', mptrack::test::bits_of(v)); }
  void add_i64(const char* label, std::int64_t v) override {
    add_line(label, 'i', static_cast<std::uint64_t>(v));
  }
  void on_failure(const char* what) override {
    sh_write("golden ");
    sh_write(name_);
    sh_write(": case precondition failed: ");
    sh_write(what);
    sh_write("\n");
  }

  void add_line(const char* label, char kind, std::uint64_t bits) {
    char got[mptrack::test::Label::kCapacity + 32];
    const std::size_t n = mptrack::test::format_line(got, sizeof got, label, kind, bits);
    const char* end = std::strchr(next_, '\n');
    const std::size_t want_n = end != nullptr ? static_cast<std::size_t>(end - next_) : std::strlen(next_);
    const bool same = want_n == n && std::memcmp(next_, got, n) == 0;
    ++compared_;
    if (!same) {
      if (differ_ < 5) {
        sh_write("golden ");
        sh_write(name_);
        sh_write(" line ");
        sh_write_uint(compared_);
        sh_write(": got '");
        sh_write(got);
        sh_write("'\n");
      }
      ++differ_;
    }
    next_ = end != nullptr ? end + 1 : next_ + want_n;
  }

  const char* name_;
  const char* next_;
  std::uint32_t compared_ = 0;
  std::uint32_t differ_ = 0;
};

}  // namespace

extern "C" int app_main() {
  std::uint64_t total = 0;
  std::uint32_t bad_files = 0;
  for (const Case& c : kCases) {
    EmbeddedSink sink(c.name, c.golden);
    c.run(sink);
    const std::uint32_t unread = sink.unread();
    const bool ok = sink.differ() == 0 && unread == 0 && sink.failures() == 0 && sink.compared() > 0;
    total += sink.compared();
    bad_files += ok ? 0u : 1u;
    sh_write(ok ? "PASS " : "FAIL ");
    sh_write(c.name);
    sh_write(": ");
    sh_write_uint(sink.compared());
    sh_write(" values compared, ");
    sh_write_uint(sink.differ());
    sh_write(" differ, ");
    sh_write_uint(unread);
    sh_write(" golden lines not reached\n");
  }
  sh_write(bad_files == 0 ? "goldens: PASS, " : "goldens: FAIL, ");
  sh_write_uint(total);
  sh_write(" golden values compared bit for bit in ");
  sh_write_uint(sizeof kCases / sizeof kCases[0]);
  sh_write(" files\n");
#if defined(__arm__)
  // Instructions per scan (Cortex-M7 SysTick, meaningful under -icount
  // shift=0; scan_cost.cpp).
  if (!mptrack::baremetal::report_mfbp_scan_cost(mptrack::test::mptrack_golden_scenario_s2_scans1to5)) {
    sh_write("scan cost: FAIL (input or step)\n");
  }
  if (!mptrack::baremetal::report_multipath_scan_cost(mptrack::test::mptrack_seed002_scans,
                                                      mptrack::test::mptrack_seed002_scans_end)) {
    sh_write("multipath scan cost: FAIL (input or step)\n");
  }
#endif
  mptrack::baremetal::sh_exit(bad_files == 0);
}
