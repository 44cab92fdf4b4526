// Seed 003 sea scenes as a scan source (docs/algorithms/sea_clutter.md
// §Tracking the sea scenes): per run, the pulse-level scene generator
// (host-sim/sea) and the core detection chain (seaclutter::SeaDetector) give
// every scan's plots; each plot becomes a measurement (range, azimuth 0,
// range rate as doppler_mps, amplitude), carries its 5 x 512 patch and, when
// the trained classifier exists, its 8 CNN features, computed here once per
// detection and scan so that every tracker of the run shares them.
//
// Geometry: the radar stares along +x, so a target at range r with range
// rate rdot is the Cartesian truth (px, vx, py, vy) = (r, rdot, 0, 0) and the
// harness's Cartesian metrics measure range and range-rate errors.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "mptrack/scenario/scenario_spec.h"
#include "mptrack/sea/sea_generator.h"
#include "mptrack/sea/sea_scenario.h"
#include "run/scan_source.h"

namespace mptrack::sim {

/// The measurement-level view of a sea scenario that trackers are set up
/// with and the writers read: 15 scans of 10 s, region 0..M range bins by
/// +-1 deg around boresight, range noise one range bin (seed 003 eq. (4)).
scenario::ScenarioSpec sea_spec_view(const sea::SeaScenario& s);

/// True for the built-in sea scenario names (seed003-sea-a, seed003-sea-b, seed003-sea-c).
bool is_sea_scenario(const std::string& name);

/// One range-Doppler power map kept for the plot (run 0, one scan), dB.
struct SeaMapSnapshot {
  std::uint32_t scan = 0;                ///< 1-based; 0 = none kept
  std::uint32_t range_bins = 0, doppler_bins = 0;
  std::vector<float> power_db;           ///< [range][Doppler], fftshifted, 10 log10(P)
};

/// Which CNN g_M computes the classifier features of every plot: none, the
/// float network or its int8 quantisation (docs/algorithms/nemp.md §int8
/// inference; `--classifier`).
enum class FeatureExtractor { kNone, kFloat, kInt8 };

class SeaScanSource final : public ScanSource {
 public:
  /// `features`: the classifier's CNN run on every plot (needs the trained
  /// weights of that precision; throws std::runtime_error without them).
  /// `map_scan`: the scan of run 0 whose map is kept (0 = none).
  SeaScanSource(const sea::SeaScenario& scenario, std::uint64_t seed, FeatureExtractor features,
                std::uint32_t map_scan);
  ~SeaScanSource() override;
  const scenario::ScenarioSpec& spec() const override { return spec_; }
  void begin_run(std::uint32_t run) override;
  void deliver(const ScanStep& step, FrameInput input) override;
  const std::vector<scenario::SimScan>& scans() const override { return scans_; }

  const sea::SeaScenario& sea_scenario() const { return sea_; }
  const SeaMapSnapshot& map_snapshot() const { return map_; }
  /// Mean CNN time per detection over all runs so far [us] (0 without features).
  double feature_us_per_detection() const;

 private:
  struct Chain;  // detector and classifier (large, heap)
  void fill_scan(const sea::SeaScan& in, scenario::SimScan& out);

  sea::SeaScenario sea_;
  scenario::ScenarioSpec spec_;
  std::uint64_t seed_ = 1;
  std::uint32_t map_scan_ = 0;
  std::unique_ptr<Chain> chain_;
  std::vector<scenario::SimScan> scans_;
  SeaMapSnapshot map_;
  double feature_us_ = 0.0;
  std::uint64_t feature_count_ = 0;
};

}  // namespace mptrack::sim
