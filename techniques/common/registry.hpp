#pragma once
// Each technique's folder provides its registry entry and its pure parameter
// derivation (no GL), gathered here.
#include "foveate/core/planner.hpp"
#include "foveate/techniques/technique.hpp"

namespace foveate::tech {

TechniqueInfo native_info();
TechniqueInfo layered_info();
TechniqueInfo logpolar_info();
TechniqueInfo checkerboard_info();
TechniqueInfo lodmask_info();
TechniqueInfo inset_info();

/// The layer plan a `layered` technique uses (nullptr for other techniques).
const LayerPlan* layered_plan(const Technique& t);

}  // namespace foveate::tech
