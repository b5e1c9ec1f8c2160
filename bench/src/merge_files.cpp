// Shards as the files their jobs wrote (merge.hpp): read back, told apart
// (a benchmark's or a tune run's) and joined, for `foveate merge` and
// foveate.merge() alike.
#include <filesystem>
#include <nlohmann/json.hpp>

#include "foveate/bench/merge.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/json_read.hpp"

namespace foveate::bench {

std::string shard_results_file(const std::string& shard) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(shard, ec)) {
    for (const char* name : {"results.json", "tune.json"}) {
      const fs::path p = fs::path(shard) / name;
      if (fs::exists(p, ec)) return p.string();
    }
    throw Error(shard + ": a folder without results.json or tune.json (a bench or tune --out)");
  }
  return shard;
}

MergedShards merge_shard_files(const std::vector<std::string>& shards) {
  if (shards.empty()) throw OptionError("shards", "no shards given");
  std::vector<nlohmann::json> files;
  std::vector<std::string> names;
  for (const std::string& s : shards) {
    const std::string path = shard_results_file(s);
    files.push_back(read_json_file(path, "shard results"));
    names.push_back(path);
  }
  const bool tune = files.front().value("schema", "") == kTuneSchema;
  for (size_t i = 1; i < files.size(); ++i) {
    if ((files[i].value("schema", "") == kTuneSchema) != tune) {
      throw Error(names[i] + ": a " + (tune ? "benchmark" : "tune run") + "'s results, but " +
                  names[0] + " is a " + (tune ? "tune run" : "benchmark") + "'s");
    }
  }
  MergedShards out;
  if (tune) {
    std::vector<TuneResult> read;
    for (size_t i = 0; i < files.size(); ++i) read.push_back(read_tune_results(files[i], names[i]));
    out.tune = merge_tune_shards(read, names);
  } else {
    std::vector<BenchResult> read;
    for (size_t i = 0; i < files.size(); ++i)
      read.push_back(read_bench_results(files[i], names[i]));
    out.bench = merge_shards(read, names);
  }
  return out;
}

}  // namespace foveate::bench
