#pragma once
// What the joins of shards (a benchmark's, a tune run's) share.
#include <set>
#include <string>

#include "foveate/core/error.hpp"

namespace foveate::bench::detail {

/// Throws unless every shard index 0..count-1 was given, naming the first
/// shard's file (`first_name`) and the missing jobs as --shard K/N counts
/// them (from 1).
inline void check_every_shard(const std::set<int>& seen, int count, const std::string& first_name) {
  if (static_cast<int>(seen.size()) == count) return;
  std::string missing;
  int n = 0;
  for (int k = 0; k < count; ++k) {
    if (seen.count(k)) continue;
    missing += (missing.empty() ? "" : ", ") + std::to_string(k + 1);
    ++n;
  }
  throw Error(first_name + ": one of " + std::to_string(count) + " shards, and shard" +
              (n > 1 ? "s " : " ") + missing + " of " + std::to_string(count) +
              (n > 1 ? " are" : " is") +
              " not given: every shard's results are needed to join them");
}

}  // namespace foveate::bench::detail
