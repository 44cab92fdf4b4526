// Host-side collection and report of core's per-stage profiles
// (core/include/mptrack/profile.h; built with -DMPTRACK_PROFILE=ON and
// bound with bind_profile_clocks()). Uses std::vector: for harnesses
// (mptrack-sim, mptrack-bench-scan), not for a board image.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "mptrack/platform/profile_clock.h"
#include "mptrack/profile.h"

namespace mptrack::platform {

struct StageSummary {
  std::string name;
  double p50_us = 0, p99_us = 0, max_us = 0, mean_us = 0;
  std::size_t samples = 0;
};

/// Records last() of a StageProfile after every completed step; Stage is
/// the stage enum (profile::FrontEndStage or profile::MfbpStage).
template <class Stage, std::size_t K>
class StageRecorder {
 public:
  StageRecorder(const profile::StageProfile<K>& p, double us_per_tick)
      : p_(p), us_per_tick_(us_per_tick), seen_(p.steps()) {}

  /// Call after each step()/process(): records the last step if one completed.
  void poll() {
    if (p_.steps() == seen_) return;
    seen_ = p_.steps();
    for (std::size_t s = 0; s < K; ++s) samples_[s].push_back(p_.last()[s]);
  }

  std::size_t steps() const { return samples_[0].size(); }

  std::vector<StageSummary> summary() const {
    std::vector<StageSummary> out;
    for (std::size_t s = 0; s < K; ++s) {
      StageSummary r;
      r.name = profile::stage_name(static_cast<Stage>(s));
      std::vector<std::uint32_t> v = samples_[s];
      r.samples = v.size();
      if (!v.empty()) {
        std::sort(v.begin(), v.end());
        const auto at = [&](double q) {  // nearest rank
          std::size_t i = static_cast<std::size_t>(q * static_cast<double>(v.size()));
          if (i >= v.size()) i = v.size() - 1;
          return static_cast<double>(v[i]) * us_per_tick_;
        };
        r.p50_us = at(0.50);
        r.p99_us = at(0.99);
        r.max_us = static_cast<double>(v.back()) * us_per_tick_;
        double sum = 0;
        for (std::uint32_t x : v) sum += static_cast<double>(x);
        r.mean_us = sum / static_cast<double>(v.size()) * us_per_tick_;
      }
      out.push_back(r);
    }
    return out;
  }

  void print(const char* title) const {
    std::printf("  %s per-stage profile (%zu steps, MPTRACK_PROFILE):\n", title, steps());
    for (const StageSummary& r : summary()) {
      std::printf("    %-10s p50 %9.2f  p99 %9.2f  max %9.2f  mean %9.2f us\n", r.name.c_str(), r.p50_us,
                  r.p99_us, r.max_us, r.mean_us);
    }
  }

 private:
  const profile::StageProfile<K>& p_;
  double us_per_tick_;
  std::uint64_t seen_;
  std::vector<std::uint32_t> samples_[K];
};

}  // namespace mptrack::platform

namespace mptrack::platform {

/// The front-end and MF-BP recorders together, for a harness loop: binds
/// the clocks on construction; poll() after each frame/step; print() at the
/// end. Without MPTRACK_PROFILE every call is a no-op (and print() prints
/// nothing), so harness code needs no #if.
class CoreProfileRecorders {
 public:
#if MPTRACK_PROFILE
  CoreProfileRecorders()
      : enabled_(bind_profile_clocks()),
        fe_(profile::g_frontend, profile_tick_us()),
        mfbp_(profile::g_mfbp, profile_tick_us()) {}
  void poll() {
    fe_.poll();
    mfbp_.poll();
  }
  void print() const {
    if (!enabled_) return;
    if (fe_.steps() > 0) fe_.print("front end");
    if (mfbp_.steps() > 0) mfbp_.print("MF-BP step");
  }
  const StageRecorder<profile::FrontEndStage, profile::FrontEndProfile::kNumStages>& front_end() const {
    return fe_;
  }
  const StageRecorder<profile::MfbpStage, profile::MfbpProfile::kNumStages>& mfbp() const { return mfbp_; }

 private:
  bool enabled_;
  StageRecorder<profile::FrontEndStage, profile::FrontEndProfile::kNumStages> fe_;
  StageRecorder<profile::MfbpStage, profile::MfbpProfile::kNumStages> mfbp_;
#else
  void poll() {}
  void print() const {}
#endif
};

}  // namespace mptrack::platform
