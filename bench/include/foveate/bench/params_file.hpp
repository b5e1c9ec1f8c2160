#pragma once
// A file of technique parameters (what `foveate tune` chooses; what render,
// bench and view take with --params-file):
//   {"schema": "foveate-params/1",
//    "techniques": {"layered": {"margin": 1.25, "half_rate": 0}, ...},
//    "notes": "..."}                  (optional: how the values were found)
// Every key must be a parameter the technique declares, every value in its range.
#include <map>
#include <string>

#include "foveate/bench/params.hpp"

namespace foveate::bench {

using TechniqueParams = std::map<std::string, std::map<std::string, double>>;

/// Reads and checks a parameters file; errors name the file and the entry.
ParamOverrides read_params_file(const std::string& path);
/// Writes one atomically (the file a tune run leaves).
void write_params_file(const std::string& path, const TechniqueParams& params,
                       const std::string& notes);

}  // namespace foveate::bench
