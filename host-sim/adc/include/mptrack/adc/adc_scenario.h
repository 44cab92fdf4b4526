// AdcScenario: a raw-ADC MIMO radar scenario as data (seed 004 Secs. II and V;
// docs/algorithms/scenarios.md §Seed 004). Same spirit as scenario::ScenarioSpec: the JSON
// files in host-sim/scenarios/ (schema "mptrack-adc-scenario/1") load to exactly these
// values, angles in degrees, powers in the units named in each field.
//
// Geometry (seed 004 eq. (1)): radar at the origin, array along +x, boresight +y;
// bearing theta = atan2(x, y) measured from +y towards +x. Frame n
// (1-based) is at time (n - 1) * frame_period_s.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace mptrack::adc {

inline constexpr double kBoltzmann_J_per_K = 1.380649e-23;  ///< k_b (SI 2019, exact)
/// N_T N_R = 3 x 3 virtual channels (docs/algorithms/frontend.md §Frame input and checks).
inline constexpr std::size_t kNumVirtual = 9;

/// Noise variance convention (docs/algorithms/scenarios.md §Seed 004).
enum class NoiseModel : std::uint8_t {
  kModelA,   ///< "model_a": N0 = k_b T0, per-sample variance k_b T0 f_s (recommended)
  kLiteral,  ///< "literal": per-sample variance k_b T0 BW, whatever f_s is (paper text)
};

/// Waveform, array and receiver (seed 004 Sec. V-A). The ADC samples at
/// sample_rate_hz directly (the 32 MHz decimated path of docs/algorithms/frontend.md
/// §Departures from the paper).
struct RadarSpec {
  double carrier_hz = 10e9;                ///< f_c [Hz]
  double bandwidth_hz = 20e6;              ///< chirp sweep [Hz]
  double chirp_duration_s = 3.6e-6;        ///< T_Tx [s]
  double sample_rate_hz = 32e6;            ///< f_s [Hz]
  double element_spacing_wavelengths = 0.5;  ///< virtual ULA spacing [lambda]
  double tx_amplitude = 0.53;              ///< A in rho(r) = A G lambda / ((4 pi)^1.5 r^2) [V/m]
  double antenna_gain = 1.0;               ///< G [-]
  double noise_temperature_k = 290.0;      ///< T0 [K]
  NoiseModel noise_model = NoiseModel::kModelA;
};

/// One leg of a drone's velocity schedule (docs/algorithms/scenarios.md §Seed 004): over `steps`
/// frame steps the velocity moves linearly from its current value to
/// velocity_mps (equal values = constant velocity).
struct MotionLeg {
  std::uint32_t steps = 1;                 ///< frame steps, >= 1
  std::array<double, 2> velocity_mps{};    ///< velocity at the end of the leg (vx, vy) [m/s]
};

/// A point target (seed 004 Sec. V-A): Swerling RCS drawn per frame.
struct DroneSpec {
  std::uint32_t id = 1;                    ///< >= 1, unique
  std::array<double, 2> start_m{};         ///< position at birth_frame (x, y) [m]
  std::array<double, 2> velocity_mps{};    ///< velocity at birth_frame (vx, vy) [m/s]
  std::uint32_t birth_frame = 1;           ///< first frame it exists (inclusive)
  std::uint32_t death_frame = 1;           ///< last frame it exists (inclusive)
  double mean_rcs_m2 = 0.05;               ///< E[sigma_RCS] [m^2]
  int swerling = 3;                        ///< 1 (exponential RCS) or 3 (Gamma shape 2)
  std::vector<MotionLeg> legs;             ///< after the last leg: constant velocity
};

/// Distributed ground clutter: `scatterers` points placed uniformly in a
/// range x bearing cell once per run (static), each with a Swerling-1
/// (complex Gaussian) amplitude redrawn per frame (wind-blown vegetation).
struct ClutterPatchSpec {
  std::uint32_t id = 1;
  double range_min_m = 0.0, range_max_m = 0.0;         ///< [m]
  double bearing_min_deg = 0.0, bearing_max_deg = 0.0; ///< [deg]
  std::uint32_t scatterers = 1;
  double mean_rcs_m2 = 0.01;               ///< mean RCS per scatterer [m^2]
  std::uint32_t birth_frame = 1, death_frame = 1;
};

/// Chaff-like cloud: `scatterers` dipole clusters with Gaussian offsets
/// (drawn once per run) around a centre drifting with the wind; the cloud
/// blooms, its std growing linearly from sigma0_m at birth.
struct ChaffCloudSpec {
  std::uint32_t id = 1;
  std::array<double, 2> centre_m{};        ///< centre at birth (x, y) [m]
  std::array<double, 2> drift_mps{};       ///< centre velocity [m/s]
  double sigma0_m = 1.0;                   ///< cloud std per axis at birth [m]
  double growth_mps = 0.0;                 ///< std growth rate [m/s]
  std::uint32_t scatterers = 1;
  double mean_rcs_m2 = 0.01;               ///< mean RCS per scatterer [m^2]
  std::uint32_t birth_frame = 1, death_frame = 1;
};

/// Barrage noise jammer sector: `sources` independent white complex Gaussian
/// emitters at bearings spread evenly over [bearing_min, bearing_max]
/// (one at the centre if sources == 1), spatially coherent across the
/// virtual array, independent across samples and Tx slots.
struct JammerSpec {
  double bearing_min_deg = 0.0, bearing_max_deg = 0.0;  ///< [deg]
  std::uint32_t sources = 1;
  double jnr_db = 0.0;                     ///< total jammer-to-noise ratio per ADC sample [dB]
  std::uint32_t birth_frame = 1, death_frame = 1;
};

/// Front-end configuration the scenario is meant to be processed with.
struct FrontEndSpec {
  double min_range_m = 3.0;                ///< range gate [m]
  double max_range_m = 100.0;              ///< R_max [m] (seed 004 Sec. V-A)
  double max_abs_bearing_deg = 75.0;       ///< angle span; track 2 reaches 68.6 deg
                                           ///< (docs/algorithms/scenarios.md §Seed 004)
  std::string cfar_type = "os";            ///< "ca" | "go" | "so" | "os": OS by default, because a
                                           ///< strong drone in the range training window masks a
                                           ///< weaker one under CA (seen at n = 1..5: drone 1 at
                                           ///< 14 m masks drone 2 at 33 m)
  double cfar_pfa = 1e-2;                  ///< CFAR false-alarm probability per tested cell (only
                                           ///< local maxima are tested); measured on
                                           ///< seed004-drones: ~1.4 false alarms per frame
  std::uint32_t cfar_guard_cells = 2;      ///< per side [range bins]
  std::uint32_t cfar_training_cells = 8;   ///< per side [range bins]
  std::string range_window = "rectangular";  ///< "rectangular" | "hann" | "hamming" | "blackman"
  std::string angle_window = "hamming";    ///< taper across the 9 virtual channels: -40 dB angle
                                           ///< sidelobes, else a 30 dB drone's sidelobes are detected
};

/// What the trackers are told about the detections (measurement model).
struct TrackerModelSpec {
  double sigma_range_m = 0.75;             ///< range noise std of a detection [m] (measured: 0.75)
  double sigma_bearing_deg = 1.6;          ///< bearing noise std of a detection [deg] (measured: 1.64)
};

/// The receiver's ADC (docs/algorithms/scenarios.md §ADC model). "float"
/// hands the synthesised volts to the ring as they are (no ADC: the
/// seed 004 set-up); "int16" quantises each of I and Q with a `bits`-bit
/// mid-tread quantiser clipping at +-full_scale_v, codes left-justified in
/// int16 (code / 32768 = fraction of full scale, frontend/radar_cube.h), and
/// the ring carries those int16 frames as a board's DMA would.
struct AdcModelSpec {
  std::string sample_format = "float";     ///< "float" | "int16"
  std::uint32_t bits = 12;                 ///< ADC resolution [bits], 2..16
  double full_scale_v = 1e-4;              ///< clip level of I and of Q [V]; the default puts the
                                           ///< thermal noise (std 2.5e-7 V per component, model A)
                                           ///< at 5 LSB of a 12-bit ADC, echoes clip from ~1.4 m
  double saturation_fraction = 0.01;       ///< a frame with more than this fraction of its sample
                                           ///< values at a rail is saturated, in [0, 1]
  std::string saturation_policy = "keep";  ///< "keep": a saturated frame's detections are used,
                                           ///< counted; "drop": the frame reaches no tracker
};

/// A named frame interval reported separately in summary.json (where a
/// tracker loses: start, crossing, births, low SNR).
struct EvalPhase {
  std::string name;
  std::uint32_t first_frame = 1, last_frame = 1;
};

struct AdcScenario {
  std::string name;
  std::string description;
  std::uint32_t num_frames = 100;          ///< frames 1..num_frames
  double frame_period_s = 0.1;             ///< Delta t [s] (seed 004 Sec. V-A: 10 Hz)
  double ospa_cutoff_m = 10.0;             ///< OSPA c [m] (seed 004 Sec. V-A)
  double ospa_order = 2.0;                 ///< OSPA p (seed 004 Sec. V-A)
  RadarSpec radar;
  FrontEndSpec frontend;
  TrackerModelSpec tracker_model;
  AdcModelSpec adc;
  std::vector<DroneSpec> drones;
  std::vector<ClutterPatchSpec> clutter_patches;
  std::vector<ChaffCloudSpec> chaff_clouds;
  std::vector<JammerSpec> jammers;
  std::vector<EvalPhase> phases;
};

/// Semantic checks. "" when valid, else "<field path>: <problem>", e.g.
/// "drones[1].mean_rcs_m2: expected a positive number".
std::string validate(const AdcScenario& s);

bool operator==(const AdcScenario& a, const AdcScenario& b);
inline bool operator!=(const AdcScenario& a, const AdcScenario& b) { return !(a == b); }

/// Built-in scenarios: "seed004-drones" (seed 004 Sec. V-A, clutter-free) and
/// "mimo-interference" (the same drones plus clutter patches, a chaff cloud
/// and a jammer sector). False if the name is unknown.
bool builtin_adc_scenario(const std::string& name, AdcScenario& out);
std::vector<std::string> builtin_adc_scenario_names();

}  // namespace mptrack::adc
