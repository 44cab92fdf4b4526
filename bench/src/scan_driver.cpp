// Fixed-work driver for callgrind instruction counts (bench/callgrind.sh).
//
//   mptrack-bench-scan <tracker> <scans>
//     tracker: mfbp-filter | mfbp | mfbp-s1 | gmphd | gmcphd | gnn   (float, DefaultCaps)
//   mptrack-bench-scan profile <scans> <results.json>
//     (a -DMPTRACK_PROFILE=ON build only) per-stage profile: MF-BP online
//     filter and window-7 smoother on the first <scans> scans of S2, and
//     the seed 004 front end on its first <scans> frames; p50/p99/max per
//     stage printed and merged into <results.json> under "stage_profile".
//   mptrack-bench-scan merge-json <file.json> <key> <value.json>
//     sets <key> of the object in <file.json> (created if missing) to the
//     JSON in <value.json>; ./run bench uses it for footprint.json.
// Generates seed 000 S2 (run 0, seed 0) up front, then steps the tracker
// through the first <scans> scans inside run_scans(), the function whose
// inclusive instruction count callgrind reports (--toggle-collect), so
// scenario generation is not counted. Deterministic: same binary, same
// count on any machine.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "mptrack/adc/adc_scenario.h"
#include "mptrack/adc/frontend_config.h"
#include "mptrack/adc/synthesizer.h"
#include "mptrack/frontend/front_end.h"
#include "mptrack/platform/stage_report.h"

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

using nlohmann::ordered_json;

bool read_json(const std::string& path, ordered_json& j) {
  std::ifstream f(path);
  if (!f) return false;
  j = ordered_json::parse(f, nullptr, false);
  return !j.is_discarded();
}

bool merge_json(const std::string& path, const std::string& key, const ordered_json& value) {
  ordered_json j = ordered_json::object();
  if (!read_json(path, j) || !j.is_object()) j = ordered_json::object();
  j[key] = value;
  std::ofstream f(path);
  f << j.dump(2) << "\n";
  return static_cast<bool>(f);
}

#if MPTRACK_PROFILE
template <class Rec>
ordered_json table_json(const Rec& rec) {
  ordered_json t = ordered_json::object();
  for (const platform::StageSummary& r : rec.summary()) {
    t[r.name] = {{"p50_us", r.p50_us}, {"p99_us", r.p99_us}, {"max_us", r.max_us}, {"mean_us", r.mean_us}};
  }
  return t;
}

template <class Tracker>
ordered_json profile_tracker(const typename Tracker::Params& p, const scenario::ScenarioSpec& spec,
                             std::uint32_t n, const char* title) {
  auto scans = bench::generate_scans<float, DefaultCaps::kMaxMeasurements>(spec, 0, 1, n);
  auto tr = std::make_unique<Tracker>();
  if (tr->init(p) != Status::kOk) return {};
  profile::g_mfbp.reset();
  platform::StageRecorder<profile::MfbpStage, profile::MfbpProfile::kNumStages> rec(profile::g_mfbp,
                                                                                    platform::profile_tick_us());
  for (const auto& s : scans) {
    (void)tr->step(*s);
    rec.poll();
  }
  rec.print(title);
  ordered_json j = table_json(rec);
  j["steps"] = rec.steps();
  return j;
}

ordered_json profile_frontend(std::uint32_t frames) {
  adc::AdcScenario sc;
  if (!adc::builtin_adc_scenario("seed004-drones", sc)) return {};
  using Caps = frontend::Seed004RadarCaps;
  auto fe = std::make_unique<frontend::FrontEnd<Caps>>();
  auto cube = std::make_unique<frontend::RadarCube<Caps>>();
  auto scan = std::make_unique<Scan<float, Caps::kMaxDetections>>();
  adc::FrameSynthesizer synth;
  std::vector<adc::DroneTruth> truth;
  if (synth.init(sc, 4, 0) != Status::kOk || fe->init(adc::frontend_params_for(sc)) != Status::kOk) return {};
  profile::g_frontend.reset();
  platform::StageRecorder<profile::FrontEndStage, profile::FrontEndProfile::kNumStages> rec(
      profile::g_frontend, platform::profile_tick_us());
  for (std::uint32_t k = 1; k <= frames && k <= sc.num_frames; ++k) {
    if (synth.synthesize(k, *cube, truth) != Status::kOk) break;
    (void)fe->process(*cube, *scan);
    rec.poll();
  }
  rec.print("front end (seed 004 cube)");
  ordered_json j = table_json(rec);
  j["frames"] = rec.steps();
  return j;
}
#endif

int profile_main(std::uint32_t n, const std::string& results) {
#if MPTRACK_PROFILE
  if (!platform::bind_profile_clocks()) return 2;
  const scenario::ScenarioSpec spec = bench::seed000_s2();
  ordered_json j = ordered_json::object();
  j["unit"] = "us (steady_clock on this host; cycles on DWT/PMU targets)";
  j["switch"] = "cmake -DMPTRACK_PROFILE=ON (core/include/mptrack/profile.h)";
  j["mfbp_filter_s2"] =
      profile_tracker<MfbpTracker<float>>(bench::mfbp_params_for<float>(spec, 1), spec, n, "MF-BP online filter, S2");
  j["mfbp_window7_s2"] =
      profile_tracker<MfbpTracker<float>>(bench::mfbp_params_for<float>(spec, 7), spec, n, "MF-BP window 7, S2");
  j["frontend_seed004"] = profile_frontend(n);
  if (!results.empty() && !merge_json(results, "stage_profile", j)) return 1;
  return 0;
#else
  (void)n;
  (void)results;
  std::fprintf(stderr, "profile: this binary was built without -DMPTRACK_PROFILE=ON\n");
  return 2;
#endif
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 5 && std::strcmp(argv[1], "merge-json") == 0) {
    ordered_json v;
    if (!read_json(argv[4], v)) {
      std::fprintf(stderr, "merge-json: cannot parse %s\n", argv[4]);
      return 2;
    }
    return merge_json(argv[2], argv[3], v) ? 0 : 1;
  }
  if ((argc == 3 || argc == 4) && std::strcmp(argv[1], "profile") == 0) {
    return profile_main(static_cast<std::uint32_t>(std::strtoul(argv[2], nullptr, 10)), argc == 4 ? argv[3] : "");
  }
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s mfbp-filter|mfbp|mfbp-s1|gmphd|gmcphd|gnn <scans>\n", argv[0]);
    return 2;
  }
  const std::string kind = argv[1];
  const auto n = static_cast<std::uint32_t>(std::strtoul(argv[2], nullptr, 10));
  const scenario::ScenarioSpec spec = bench::seed000_s2();
  if (kind == "mfbp-filter") return drive<MfbpTracker<float>>(bench::mfbp_params_for<float>(spec, 1), spec, n);
  if (kind == "mfbp") return drive<MfbpTracker<float>>(bench::mfbp_params_for<float>(spec, 7), spec, n);
  if (kind == "mfbp-s1") {
    return drive<MfbpTracker<float>>(bench::mfbp_params_for<float>(spec, 7, every_scan_smoother_params<float>()), spec, n);
  }
  if (kind == "gmphd") return drive<GmPhdFilter<float>>(bench::phd_params_for<float>(spec), spec, n);
  if (kind == "gmcphd") return drive<GmCphdFilter<float>>(bench::phd_params_for<float>(spec), spec, n);
  if (kind == "gnn") return drive<GnnTracker<float>>(bench::gnn_params_for<float>(spec), spec, n);
  std::fprintf(stderr, "unknown tracker %s\n", kind.c_str());
  return 2;
}
