#pragma once
// Benchmarks split into shards (BenchOptions::shard) are joined here: each
// shard's results.json is read back, and the shards of one benchmark (same
// foveate version and settings, each job once) become one result, written
// like any other.
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "foveate/bench/bench.hpp"
#include "foveate/bench/tune.hpp"

namespace foveate::bench {

/// A benchmark's results as results.json holds them (bench_json); images
/// (samples, heat maps) are not in the file and stay empty. Throws
/// foveate::Error naming `where` for a file that is not such results.
BenchResult read_bench_results(const nlohmann::json& j, const std::string& where);

/// One result from the shards of one benchmark, `names[i]` naming shard i
/// in errors: every shard must come from the same foveate version with the
/// same settings and a shard count, and each index 0..N-1 must appear
/// exactly once. Native's figures are the first shard's; each run keeps the
/// speedup measured against its own shard's native. Runs keep the order of
/// one unsharded run.
BenchResult merge_shards(const std::vector<BenchResult>& shards,
                         const std::vector<std::string>& names);

/// The settings that shards must share (bench_json's "settings").
nlohmann::json bench_settings_json(const BenchResult& b);

/// A shard's results file: its output folder (the results.json or tune.json
/// in it) or the file itself. Throws foveate::Error for a folder with neither.
std::string shard_results_file(const std::string& shard);

/// Shards joined from their files: a benchmark's or a tune run's, whichever
/// the shards are.
struct MergedShards {
  std::optional<BenchResult> bench;
  std::optional<TuneResult> tune;
};
/// Reads each shard (a folder or file, shard_results_file) and joins them
/// (merge_shards or merge_tune_shards); refuses a benchmark's shards mixed
/// with a tune run's, naming the files, and an empty list (field "shards").
MergedShards merge_shard_files(const std::vector<std::string>& shards);

}  // namespace foveate::bench
