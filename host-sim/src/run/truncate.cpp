// Scenario clipping; see truncate.h.
#include "run/truncate.h"

#include <algorithm>
#include <vector>

namespace mptrack::sim {

namespace {

/// Drops the items born after `last` and ends the others at `last` at the latest.
template <class T>
void clip(std::vector<T>& items, std::uint32_t last, std::uint32_t T::*birth, std::uint32_t T::*death) {
  std::vector<T> keep;
  for (T x : items) {
    if (x.*birth > last) continue;
    x.*death = std::min(x.*death, last);
    keep.push_back(x);
  }
  items = keep;
}

}  // namespace

void truncate_scans(scenario::ScenarioSpec& s, std::uint32_t scans) {
  if (scans == 0 || scans >= s.num_scans) return;
  s.num_scans = scans;
  s.eval_last_scan = std::min(s.eval_last_scan, scans);
  if (s.eval_first_scan > scans) s.eval_first_scan = 1;
  clip(s.targets, scans, &scenario::TargetSpec::birth_scan, &scenario::TargetSpec::death_scan);
  clip(s.clutter, scans, &scenario::ClutterSpec::birth_scan, &scenario::ClutterSpec::death_scan);
}

void truncate_frames(adc::AdcScenario& s, std::uint32_t frames) {
  if (frames == 0 || frames >= s.num_frames) return;
  s.num_frames = frames;
  clip(s.drones, frames, &adc::DroneSpec::birth_frame, &adc::DroneSpec::death_frame);
  clip(s.clutter_patches, frames, &adc::ClutterPatchSpec::birth_frame, &adc::ClutterPatchSpec::death_frame);
  clip(s.chaff_clouds, frames, &adc::ChaffCloudSpec::birth_frame, &adc::ChaffCloudSpec::death_frame);
  clip(s.jammers, frames, &adc::JammerSpec::birth_frame, &adc::JammerSpec::death_frame);
  clip(s.phases, frames, &adc::EvalPhase::first_frame, &adc::EvalPhase::last_frame);
}

}  // namespace mptrack::sim
