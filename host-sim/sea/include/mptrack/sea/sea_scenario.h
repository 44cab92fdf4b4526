// Seed 003 sea-clutter scenes (docs/algorithms/sea_clutter.md §Scene model):
// a staring pulse-Doppler radar looking at compound-Gaussian (K-distributed)
// sea clutter with a Gaussian Doppler spectrum whose centre and width vary
// over range and time, thermal noise, and injected moving targets at a given
// signal-to-clutter ratio (seed 003 Sec. IV, eq. (3)).
//
// Built-in sea states stand in for the paper's two data sets:
// seed003-sea-a (trained on, the CSIR role) and two held out in the IPIX role:
// seed003-sea-b (spikier texture, wider and faster-drifting spectrum) and
// seed003-sea-c (sea-b's clutter with small floating targets whose Doppler
// lies inside the clutter band, as IPIX's target does).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace mptrack::sea {

/// Everything that defines a scene family; one scene = one seed.
struct SeaScenario {
  std::string name;
  std::string description;
  // Radar (seed 003 Sec. IV: X band, staring, 1 kHz PRF, 96 range bins, 15 scans of 10 s).
  double carrier_hz = 9.4e9;        ///< f_c [Hz]; lambda = c / f_c
  double prf_hz = 1000.0;           ///< pulse repetition frequency [Hz]
  std::uint32_t range_bins = 96;    ///< M range cells
  double range_bin_m = 15.0;        ///< range cell size [m]; bin m is centred at m * range_bin_m
  std::uint32_t pulses = 512;       ///< pulses per CPI (one CPI per scan) = Doppler bins
  std::uint32_t num_scans = 15;     ///< scans per scene
  double scan_period_s = 10.0;      ///< time between CPI starts [s]
  // Clutter: x = sqrt(P_c tau) s + n (compound Gaussian), tau ~ Gamma(nu, 1/nu).
  double cnr_db = 30.0;             ///< mean clutter-to-noise power per pulse and cell [dB]
  double k_shape = 3.0;             ///< K-distribution shape nu; 2 nu must be an integer 1..16
  double texture_corr_time_s = 20.0;   ///< texture correlation time across scans [s]
  double texture_range_corr = 0.7;     ///< texture correlation between adjacent range bins [-]
  double doppler_centre_hz = 20.0;     ///< mean clutter Doppler [Hz]
  double doppler_centre_slope_hz = 10.0;  ///< centre change from first to last range bin [Hz]
  double doppler_drift_hz = 5.0;       ///< amplitude of the slow sinusoidal centre drift [Hz]
  double doppler_drift_period_s = 150.0;  ///< period of that drift [s]
  double doppler_jitter_hz = 2.0;      ///< per (bin, scan) random centre offset, sd [Hz]
  double doppler_width_hz = 20.0;      ///< spectrum standard deviation at nominal texture [Hz]
  double doppler_width_log_sd = 0.2;   ///< width = nominal * exp(log_sd * g), g the texture's
                                       ///< first Gaussian component (varies with range and time)
  // Targets (seed 003 eq. (3)): every target lives in every scan.
  std::uint32_t num_targets = 4;
  double target_doppler_min_hz = -400.0;
  double target_doppler_max_hz = 300.0;
  double target_length_min_m = 5.0;     ///< radial length ~ U[min, max] (omega(m) of eq. (3))
  double target_length_max_m = 30.0;
  double target_amp_corr_s = 2.0;       ///< correlation time of the log RCS fluctuation a(p) [s]
  double target_amp_log_sd = 0.25;      ///< sd of ln a(p) [-]
  double scr_db = 0.0;                  ///< signal-to-clutter ratio of every target [dB]
  double edge_margin_bins = 4.0;        ///< targets stay this far from the first/last bin

  double wavelength_m() const { return 299792458.0 / carrier_hz; }
  double doppler_bin_hz() const { return prf_hz / static_cast<double>(pulses); }
  /// One Doppler bin as range rate [m/s] (f_D = 2 rdot / lambda): the plots'
  /// range-rate resolution, the trackers' and the metrics' range-rate std.
  double doppler_bin_mps() const { return doppler_bin_hz() * wavelength_m() / 2.0; }
  /// Empty string if valid, else the first offending field.
  std::string validate() const;
};

/// seed003-sea-a, seed003-sea-b, seed003-sea-c.
std::vector<std::string> builtin_sea_scenario_names();
/// The named built-in sea scenario; false if the name is unknown.
bool builtin_sea_scenario(const std::string& name, SeaScenario& out);

}  // namespace mptrack::sea
