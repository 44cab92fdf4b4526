// The belief column of the classifier's training data (seed 003 Sec.
// III-D: stage 2 trains the MLP on [CNN features, tracker belief], the
// beliefs "from MP runs on the training sequences"). A tracker with the sea
// configuration of its adapter (sea_setup.h) runs over a scene and records,
// per plot, its extrinsic P(target-originated) when its scan is finalised
// (mfbp::NempState::finalised_belief):
//   kMfbp  plain MF-BP (the classifier's reliability 0: the association is
//          MF-BP's), at the window NEMP runs with;
//   kNemp  NEMP with its sea settings and the committed network: the belief
//          the MLP is fed when NEMP runs (docs/algorithms/sea_clutter.md
//          §Training explains why that is the one to train on).
#pragma once

#include "mptrack/sea/sea_dataset.h"

namespace mptrack::sim {

enum class BeliefSource { kMfbp, kNemp };

/// False without the trained classifier header (the NEMP state needs a
/// ready classifier even when it ignores it); the dataset then keeps 0.5.
bool sea_beliefs_available();

/// Per scan and plot of `scene`, the tracker's P(target-originated). kNemp
/// needs the scene's patches (ScenePlots::patches).
sea::SceneBeliefs scene_beliefs(BeliefSource source, const sea::SeaScenario& scenario, const sea::ScenePlots& scene);

}  // namespace mptrack::sim
