// The belief column of the classifier's training data (seed 003 Sec.
// III-D: stage 2 trains the MLP on [CNN features, tracker belief], the
// beliefs "from MP runs on the training sequences"): plain MF-BP with the
// sea configuration of the mfbp adapter (sea_setup.h) runs over a scene and
// records, per plot, its extrinsic P(target-originated) when its scan is
// finalised (mfbp::NempState::finalised_belief, with the classifier's
// reliability 0 so that the association is plain MF-BP's).
#pragma once

#include "mptrack/sea/sea_dataset.h"

namespace mptrack::sim {

/// False without the trained classifier header (the NEMP state needs a
/// ready classifier even when it ignores it); the dataset then keeps 0.5.
bool sea_beliefs_available();

/// Per scan and plot of `scene`, MF-BP's P(target-originated).
sea::SceneBeliefs mfbp_scene_beliefs(const sea::SeaScenario& scenario, const sea::ScenePlots& scene);

}  // namespace mptrack::sim
