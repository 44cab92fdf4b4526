// Fixed-work driver for callgrind instruction counts (bench/callgrind.sh).
//
//   mptrack-bench-scan <tracker> <scans>
//     tracker: mfbp-filter | mfbp | gmphd | gmcphd | gnn   (float, DefaultCaps)
// Generates seed 000 S2 (run 0, seed 0) up front, then steps the tracker
// through the first <scans> scans inside run_scans(), the function whose
// inclusive instruction count callgrind reports (--toggle-collect), so
// scenario generation is not counted. Deterministic: same binary, same
// count on any machine.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>

#include "mptrack/gnn/gnn_tracker.h"
#include "mptrack/mfbp/mfbp_tracker.h"
#include "mptrack/phd/phd_filter.h"
#include "workload.h"

namespace {

using namespace mptrack;

template <class Tracker>
__attribute__((noinline)) int run_scans(Tracker& tr,
                                        const std::vector<std::unique_ptr<typename Tracker::ScanType>>& scans) {
  int not_ok = 0;
  for (const auto& s : scans) {
    if (tr.step(*s) != Status::kOk) ++not_ok;
  }
  if (tr.flush() != Status::kOk) ++not_ok;
  return not_ok;
}

template <class Tracker>
int drive(const typename Tracker::Params& p, const scenario::ScenarioSpec& spec, std::uint32_t n) {
  auto scans = bench::generate_scans<float, DefaultCaps::kMaxMeasurements>(spec, 0, 1, n);
  auto tr = std::make_unique<Tracker>();
  if (tr->init(p) != Status::kOk) return 2;
  const int not_ok = run_scans(*tr, scans);
  std::printf("scans %zu, steps not kOk %d, outputs at end %zu\n", scans.size(), not_ok, tr->outputs().size());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s mfbp-filter|mfbp|gmphd|gmcphd|gnn <scans>\n", argv[0]);
    return 2;
  }
  const std::string kind = argv[1];
  const auto n = static_cast<std::uint32_t>(std::strtoul(argv[2], nullptr, 10));
  const scenario::ScenarioSpec spec = bench::seed000_s2();
  if (kind == "mfbp-filter") return drive<MfbpTracker<float>>(bench::mfbp_params_for<float>(spec, 1), spec, n);
  if (kind == "mfbp") return drive<MfbpTracker<float>>(bench::mfbp_params_for<float>(spec, 7), spec, n);
  if (kind == "gmphd") return drive<phd::GmPhdFilter<float>>(bench::phd_params_for<float>(spec), spec, n);
  if (kind == "gmcphd") return drive<phd::GmCphdFilter<float>>(bench::phd_params_for<float>(spec), spec, n);
  if (kind == "gnn") return drive<GnnTracker<float>>(bench::gnn_params_for<float>(spec), spec, n);
  std::fprintf(stderr, "unknown tracker %s\n", kind.c_str());
  return 2;
}
