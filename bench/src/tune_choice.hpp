#pragma once
// How foveate tune ranks a technique's settings (tune_choice.cpp): shared by
// its search (which times the best ones again) and its choice.
#include <map>
#include <string>
#include <vector>

#include "foveate/bench/tune.hpp"

namespace foveate::bench {

// A setting of a technique judged on every scene it was run on: whether it
// is within the bound on each, the geometric mean of its speedups, its worst
// distance below native.
struct RankedSetting {
  std::map<std::string, double> params;
  bool within = false;
  double speed = 0.0;
  double worst = 0.0;
};

// The technique's settings judged on every scene it ran on, best first: those
// within the bound on every scene by speed, then the others by how close
// they come.
std::vector<RankedSetting> rank_settings(const TuneResult& r, const std::string& technique);

}  // namespace foveate::bench
