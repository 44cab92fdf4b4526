// Per-stage cycle profile, compiled in only with MPTRACK_PROFILE=1.
//
// Why a compile-time switch: the issue (issue 6, "Targets") asks for a
// per-stage profile from the board's cycle counter that costs nothing when
// disabled. With MPTRACK_PROFILE=0 (the default) the two macros below
// expand to nothing, so the core objects are the same bytes as without
// them (bench/README.md records the proof: mptrack_core_static's object
// file compared with the macro lines stripped).
//
// Core knows no clock (it depends on nothing in the repo): the caller
// binds a plain function pointer std::uint32_t (*)() returning a
// free-running 32-bit tick count (platform/ binds DWT CYCCNT on Cortex-M,
// PMCCNTR on Cortex-A, steady_clock nanoseconds on hosts). Deltas are
// taken modulo 2^32, so a stage must be shorter than one wrap (8.6 s at
// 500 MHz; 4.3 s in nanoseconds).
//
// Accounting is exclusive: a stage scope opened while another is active
// pauses the outer one, so the stages of a step add up to the step's time
// and sequential scopes in one block act as marks ("from here on, stage
// S"). A step scope (one per step()/process() call) closes the step:
// the per-stage totals of that step become last(), and min/max/total over
// steps are updated. Several calls of the same stage in one step add up.
//
// One profile per component kind (g_frontend, g_mfbp, g_vmp) in static storage:
// every instance of that component (any Scalar, any Caps) reports into it,
// which is what a profiling run of one pipeline wants; not thread-safe.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#ifndef MPTRACK_PROFILE
#define MPTRACK_PROFILE 0
#endif

namespace mptrack::profile {

/// Free-running tick source (cycles or nanoseconds), bound by the caller.
using ClockFn = std::uint32_t (*)();

/// Front-end stages (FrontEnd::process).
enum class FrontEndStage : std::uint8_t {
  kRange = 0,  ///< frame check + range matched filter
  kDoppler,    ///< Doppler FFTs
  kAngle,      ///< angle FFTs and power map
  kCfar,       ///< local maxima + CA/OS-CFAR tests + peak list
  kPeaks,      ///< peak interpolation and measurement output
  kCount
};

/// MF-BP stages (MfbpTracker::step and flush). The smoother predicts inside
/// every forward sweep, so prediction is part of kMfUpdate (the
/// mean-field sweeps: Dirichlet, visibility, clutter and target chains).
enum class MfbpStage : std::uint8_t {
  kInput = 0,  ///< scan validation and storage in the window
  kMfUpdate,   ///< MF sweeps: prediction + updates of every chain
  kEvidence,   ///< local evidence and gating of one window scan
  kBp,         ///< loopy BP association and storage of its beliefs
  kBirth,      ///< track and clutter-component birth (incl. late birth)
  kOutput,     ///< confirmation, output, deletion/merging, window shift
  kCount
};

/// VMP stages (VmpTracker::step; docs/algorithms/vmp.md §Per-frame schedule).
enum class VmpStage : std::uint8_t {
  kInput = 0,       ///< whitened spectrum of the frame and prediction of every track
  kAmplitudeExistence,  ///< Gram matrix, q(alpha) and the q(xi) sweeps (every call)
  kDataMessage,     ///< residuals r~_k and the Gauss-Newton data messages
  kChain,           ///< window smoother passes and Gamma updates
  kBirth,           ///< residual map, candidate refinement and tests
  kOutput,          ///< pruning and the report
  kCount
};

constexpr const char* stage_name(FrontEndStage s) {
  constexpr const char* kNames[] = {"range", "doppler", "angle", "cfar", "peaks"};
  return kNames[static_cast<std::size_t>(s)];
}
constexpr const char* stage_name(MfbpStage s) {
  constexpr const char* kNames[] = {"input", "mf_update", "evidence", "bp", "birth", "output"};
  return kNames[static_cast<std::size_t>(s)];
}

constexpr const char* stage_name(VmpStage s) {
  constexpr const char* kNames[] = {"input", "amplitude_existence", "data_message", "chain", "birth", "output"};
  return kNames[static_cast<std::size_t>(s)];
}

template <std::size_t kStages>
class ScopedStage;

/// Per-stage tick statistics over steps. Fixed arrays only (no heap).
template <std::size_t kStages>
class StageProfile {
 public:
  static constexpr std::size_t kNumStages = kStages;

  /// Binds the tick source (nullptr: every delta reads 0).
  void set_clock(ClockFn fn) { clock_ = fn; }
  ClockFn clock() const { return clock_; }
  /// Forgets every statistic (keeps the clock).
  void reset() {
    step_ = {};
    last_ = {};
    min_ = {};
    max_ = {};
    total_ = {};
    steps_ = 0;
    depth_ = 0;
    active_ = nullptr;
  }

  /// Ticks of each stage in the last completed step.
  const std::array<std::uint32_t, kStages>& last() const { return last_; }
  const std::array<std::uint32_t, kStages>& min() const { return min_; }
  const std::array<std::uint32_t, kStages>& max() const { return max_; }
  const std::array<std::uint64_t, kStages>& total() const { return total_; }
  std::uint64_t steps() const { return steps_; }

  std::uint32_t now() const { return clock_ != nullptr ? clock_() : 0u; }

  void begin_step() {
    if (depth_++ == 0) step_ = {};
  }
  void end_step() {
    if (depth_ == 0 || --depth_ != 0) return;
    for (std::size_t s = 0; s < kStages; ++s) {
      const std::uint32_t v = step_[s];
      last_[s] = v;
      min_[s] = (steps_ == 0 || v < min_[s]) ? v : min_[s];
      max_[s] = v > max_[s] ? v : max_[s];
      total_[s] += v;
    }
    ++steps_;
  }

 private:
  friend class ScopedStage<kStages>;
  ClockFn clock_ = nullptr;
  std::array<std::uint32_t, kStages> step_{};  // this step so far
  std::array<std::uint32_t, kStages> last_{};
  std::array<std::uint32_t, kStages> min_{};
  std::array<std::uint32_t, kStages> max_{};
  std::array<std::uint64_t, kStages> total_{};
  std::uint64_t steps_ = 0;
  std::uint32_t depth_ = 0;
  ScopedStage<kStages>* active_ = nullptr;  // innermost open stage scope
};

/// Charges the time until the end of the enclosing block to one stage,
/// pausing the stage scope it is nested in (exclusive time).
template <std::size_t kStages>
class ScopedStage {
 public:
  template <class Stage>
  ScopedStage(StageProfile<kStages>& p, Stage stage)
      : p_(p), stage_(static_cast<std::size_t>(stage)), outer_(p.active_) {
    const std::uint32_t t = p_.now();
    if (outer_ != nullptr) outer_->charge(t);
    start_ = t;
    p_.active_ = this;
  }
  ~ScopedStage() {
    const std::uint32_t t = p_.now();
    charge(t);
    p_.active_ = outer_;
    if (outer_ != nullptr) outer_->start_ = t;  // resume the outer stage
  }
  ScopedStage(const ScopedStage&) = delete;
  ScopedStage& operator=(const ScopedStage&) = delete;

 private:
  void charge(std::uint32_t t) {
    if (stage_ < kStages) p_.step_[stage_] += t - start_;  // modulo 2^32
    start_ = t;
  }
  StageProfile<kStages>& p_;
  std::size_t stage_;
  ScopedStage* outer_;
  std::uint32_t start_ = 0;
};

/// Opens a step on construction and closes it on destruction.
template <std::size_t kStages>
class ScopedStep {
 public:
  explicit ScopedStep(StageProfile<kStages>& p) : p_(p) { p_.begin_step(); }
  ~ScopedStep() { p_.end_step(); }
  ScopedStep(const ScopedStep&) = delete;
  ScopedStep& operator=(const ScopedStep&) = delete;

 private:
  StageProfile<kStages>& p_;
};

using FrontEndProfile = StageProfile<static_cast<std::size_t>(FrontEndStage::kCount)>;
using MfbpProfile = StageProfile<static_cast<std::size_t>(MfbpStage::kCount)>;
using VmpProfile = StageProfile<static_cast<std::size_t>(VmpStage::kCount)>;

#if MPTRACK_PROFILE
/// The profiles the hooks in core report into (static storage, zero-initialised).
inline FrontEndProfile g_frontend{};
inline MfbpProfile g_mfbp{};
inline VmpProfile g_vmp{};
#endif

}  // namespace mptrack::profile

#if MPTRACK_PROFILE
#define MPTRACK_PROFILE_CAT2(a, b) a##b
#define MPTRACK_PROFILE_CAT(a, b) MPTRACK_PROFILE_CAT2(a, b)
/// Step boundary: MPTRACK_PROFILE_STEP(g_mfbp);
#define MPTRACK_PROFILE_STEP(which)                                                 \
  ::mptrack::profile::ScopedStep<decltype(::mptrack::profile::which)::kNumStages>   \
      MPTRACK_PROFILE_CAT(mptrack_profile_step_, __LINE__)(::mptrack::profile::which)
/// From here to the end of the block: MPTRACK_PROFILE_STAGE(g_mfbp, MfbpStage::kBp);
#define MPTRACK_PROFILE_STAGE(which, stage)                                         \
  ::mptrack::profile::ScopedStage<decltype(::mptrack::profile::which)::kNumStages>  \
      MPTRACK_PROFILE_CAT(mptrack_profile_stage_, __LINE__)(::mptrack::profile::which, \
                                                             ::mptrack::profile::stage)
#else
#define MPTRACK_PROFILE_STEP(which)
#define MPTRACK_PROFILE_STAGE(which, stage)
#endif
