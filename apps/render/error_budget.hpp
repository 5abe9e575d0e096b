#pragma once
// --error-budget E: the controls a render may coarsen when a relative image error of E is
// acceptable, each from an estimate of what it leaves out, and why, in words.
//  - radiosity: shooting stops when the unshot energy is below E of the emitted (energy 1 - E,
//    between 0.5 and the default 0.999): the unshot energy bounds the light still missing;
//  - specular: rays stop at the depth where the largest mirror or glass weight w leaves w^depth
//    below E (never deeper than the default 5).
//  - media: left out when the thickest one's optical depth tau along its longest chord gives
//    1 - e^-tau below half the budget; the rest of the budget goes to the other controls.
// The hemicube resolution has no such estimate and stays.
#include <string>
#include <vector>

#include "apps/common/scene/scene_description.hpp"
#include "apps/render/plan.hpp"
#include "apps/render/render_accuracy.hpp"

namespace gcsim::render {

struct BudgetChoice {
  RenderControls controls;
  std::vector<std::string> reasons;  // one line per control considered
};

// Throws std::invalid_argument unless 0 < budget < 1.
BudgetChoice controls_for_budget(const scene::SceneDescription& description, const Plan& plan, double budget);

}  // namespace gcsim::render
