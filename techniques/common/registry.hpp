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

std::vector<std::pair<std::string, double>> layered_defaults(const TechniqueConfig& c);
std::vector<std::pair<std::string, double>> logpolar_defaults(const TechniqueConfig& c);
std::vector<std::pair<std::string, double>> checkerboard_defaults(const TechniqueConfig& c);
std::vector<std::pair<std::string, double>> lodmask_defaults(const TechniqueConfig& c);
std::vector<std::pair<std::string, double>> inset_defaults(const TechniqueConfig& c);
/// The layer plan a `layered` technique uses (nullptr for other techniques).
const LayerPlan* layered_plan(const Technique& t);

/// Parameter values a technique would use for `config`, without GL.
std::vector<std::pair<std::string, double>> derive_parameters(const std::string& name,
                                                              const TechniqueConfig& config);

}  // namespace foveate::tech
