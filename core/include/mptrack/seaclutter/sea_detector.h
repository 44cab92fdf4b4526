// The sea-clutter detection chain of one CPI (seed 003 Sec. III-A;
// docs/algorithms/sea_clutter.md §Detection chain):
//   1. range-Doppler power map (RangeDopplerMap: taper, FFT, |X|^2, fftshift);
//   2. CFAR along range, one line per Doppler bin (frontend::Cfar, CA with the
//      paper's permissive P_FA = 0.28 by default);
//   3. DBSCAN of the detections into plots (GridDbscan);
//   4. amplitude-weighted centroid per plot (seed 003 Sec. III-A step 4);
//   5. one 8-bit patch per plot (PatchExtractor).
// Plots become Measurements (range, range rate, amplitude) for a tracker;
// plot j's patch is patch(j) (SeaPlot::patch_index == j).
// Allocation-free; fixed caps (SeaClutterCaps). Over kMaxPlots clusters: the
// kMaxPlots with the largest peak power are kept and process() returns
// kPartial (also when a cluster outgrew the flood-fill stack).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "mptrack/frontend/cfar.h"
#include "mptrack/measurement.h"
#include "mptrack/seaclutter/grid_dbscan.h"
#include "mptrack/seaclutter/patch_extractor.h"
#include "mptrack/seaclutter/range_doppler_map.h"
#include "mptrack/seaclutter/sea_caps.h"
#include "mptrack/seaclutter/sea_detector_params.h"
#include "mptrack/seaclutter/sea_plot.h"
#include "mptrack/static_vector.h"

namespace mptrack::seaclutter {

template <class Caps = SeaClutterCaps>
class SeaDetector {
 public:
  static constexpr std::size_t kRange = Caps::kRangeBins;
  static constexpr std::size_t kDoppler = Caps::kDopplerBins;
  using Patch = typename PatchExtractor<Caps>::Patch;

  Status init(const SeaDetectorParams& p) {
    initialized_ = false;
    MPTRACK_TRY(p.validate());
    params_ = p;
    MPTRACK_TRY(map_.init(p.doppler_window));
    MPTRACK_TRY(cfar_.init(p.cfar));
    if (cfar_.min_line_length() > kRange) return Status::kInvalidArgument;
    MPTRACK_TRY(patches_.init(p.patch_floor_db, p.patch_span_db));
    dbscan_.configure(p.eps_range_bins, p.eps_doppler_bins, p.min_points);
    doppler_bin_hz_ = static_cast<float>(p.prf_hz / static_cast<double>(kDoppler));
    half_wavelength_m_ = static_cast<float>(299792458.0 / p.carrier_hz / 2.0);
    initialized_ = true;
    return Status::kOk;
  }

  /// Runs the chain on one CPI: planar samples [range][pulse]. kOk, kPartial
  /// (plots dropped at the cap), kInvalidInput (non-finite sample: no plots).
  Status process(const float* re, const float* im) {
    if (!initialized_) return Status::kNotInitialized;
    plots_.clear();
    detections_ = 0;
    clusters_ = 0;
    MPTRACK_TRY(map_.compute(re, im));
    detect();
    dbscan_.find_core_cells();
    const bool full = cluster();
    for (std::size_t j = 0; j < plots_.size(); ++j) finish_plot(j);
    return (full || dbscan_.overflowed()) ? Status::kPartial : Status::kOk;
  }

  /// The plots as a scan for a tracker (has_doppler: doppler_mps = range
  /// rate). Measurement j is plot j, whose patch is patch(j).
  template <class T, std::size_t N>
  Status to_scan(std::uint64_t time_us, Scan<T, N>& scan) const {
    scan.time_us = time_us;
    scan.has_doppler = true;
    scan.measurements.clear();
    for (std::size_t j = 0; j < plots_.size(); ++j) {
      Measurement<T> m;
      m.range_m = static_cast<T>(plots_[j].range_m);
      m.azimuth_rad = T(0);
      m.amplitude = static_cast<T>(plots_[j].amplitude);
      m.doppler_mps = static_cast<T>(plots_[j].range_rate_mps);
      if (scan.measurements.push_back(m) != Status::kOk) return Status::kPartial;
    }
    return Status::kOk;
  }

  std::size_t num_plots() const { return plots_.size(); }
  const SeaPlot& plot(std::size_t j) const { return plots_[j]; }
  const Patch& patch(std::size_t j) const { return patch_[j]; }
  const RangeDopplerMap<Caps>& map() const { return map_; }
  std::size_t detections() const { return detections_; }  ///< CFAR hits of the last CPI
  std::size_t clusters() const { return clusters_; }      ///< clusters before the plot cap
  double cfar_alpha() const { return cfar_.alpha(); }
  const SeaDetectorParams& params() const { return params_; }

 private:
  void detect() {
    dbscan_.clear();
    for (std::size_t d = 0; d < kDoppler; ++d) {
      for (std::size_t m = 0; m < kRange; ++m) line_[m] = map_.power(m, d);
      for (std::size_t m = 0; m < kRange; ++m) {
        if (cfar_.test(line_.data(), kRange, m).detected) {
          dbscan_.mark_detection(m, d);
          ++detections_;
        }
      }
    }
  }

  /// Clusters into plots_; true if some were dropped at the cap.
  bool cluster() {
    std::size_t cursor = 0;
    ClusterSums s;
    bool dropped = false;
    auto power = [this](std::size_t m, std::size_t d) { return map_.power(m, d); };
    while (dbscan_.next_cluster(&cursor, power, s)) {
      ++clusters_;
      SeaPlot p;
      p.range_bin = s.range_sum / s.weight;
      p.doppler_bin = s.doppler_sum / s.weight;
      p.peak_power = s.peak_power;
      p.peak_range = s.peak_range;
      p.peak_doppler = s.peak_doppler;
      p.cells = static_cast<std::uint16_t>(s.cells > 65535u ? 65535u : s.cells);
      if (!plots_.full()) {
        (void)plots_.push_back(p);
        continue;
      }
      dropped = true;
      std::size_t weakest = 0;  // replace the weakest kept plot if this one is stronger
      for (std::size_t j = 1; j < plots_.size(); ++j) {
        if (plots_[j].peak_power < plots_[weakest].peak_power) weakest = j;
      }
      if (p.peak_power > plots_[weakest].peak_power) plots_[weakest] = p;
    }
    return dropped;
  }

  void finish_plot(std::size_t j) {
    SeaPlot& p = plots_[j];
    p.range_m = p.range_bin * static_cast<float>(params_.range_bin_m);
    p.doppler_hz = (p.doppler_bin - static_cast<float>(kDoppler / 2)) * doppler_bin_hz_;
    p.range_rate_mps = -p.doppler_hz * half_wavelength_m_;
    for (std::size_t m = 0; m < kRange; ++m) line_[m] = map_.power(m, p.peak_doppler);
    const frontend::CfarResult c = cfar_.test(line_.data(), kRange, p.peak_range);
    p.amplitude = c.noise > 0.0f ? std::sqrt(p.peak_power / c.noise) : 0.0f;
    const auto centre = static_cast<std::size_t>(p.range_bin + 0.5f);
    const std::size_t start = PatchExtractor<Caps>::start_row(centre < kRange ? centre : kRange - 1);
    p.patch_range_start = static_cast<std::uint16_t>(start);
    p.patch_index = static_cast<std::uint16_t>(j);
    patches_.extract(map_, start, patch_[j]);
  }

  SeaDetectorParams params_{};
  RangeDopplerMap<Caps> map_;
  frontend::Cfar cfar_;
  GridDbscan<Caps> dbscan_;
  PatchExtractor<Caps> patches_;
  StaticVector<SeaPlot, Caps::kMaxPlots> plots_;
  std::array<Patch, Caps::kMaxPlots> patch_{};
  std::array<float, kRange> line_{};
  float doppler_bin_hz_ = 1.0f;
  float half_wavelength_m_ = 0.0f;
  std::size_t detections_ = 0;
  std::size_t clusters_ = 0;
  bool initialized_ = false;
};

}  // namespace mptrack::seaclutter
