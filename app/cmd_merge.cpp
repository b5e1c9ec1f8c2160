// foveate merge: the shards of a benchmark (bench --shard K/N, or tune's)
// joined into one results.json, results.csv, results.md and report.html.
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_util.hpp"
#include "commands.hpp"
#include "foveate/bench/merge.hpp"
#include "foveate/bench/report.hpp"
#include "foveate/bench/tune.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/json_read.hpp"
#include "output_dir.hpp"

namespace foveate::app {

namespace {

struct MergeArgs {
  std::vector<std::string> shards;
  std::string out;
  bool overwrite = false;
};

// A shard given as its --out folder or its results.json.
std::string results_path(const std::string& shard) {
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

void run_merge(const MergeArgs& a) {
  std::vector<nlohmann::json> files;
  std::vector<std::string> names;
  for (const std::string& s : a.shards) {
    const std::string path = results_path(s);
    files.push_back(read_json_file(path, "shard results"));
    names.push_back(path);
  }
  const bool tune = files.front().value("schema", "") == bench::kTuneSchema;
  for (size_t i = 1; i < files.size(); ++i) {
    if ((files[i].value("schema", "") == bench::kTuneSchema) != tune) {
      throw Error(names[i] + ": a " + (tune ? "benchmark" : "tune run") + "'s results, but " +
                  names[0] + " is a " + (tune ? "tune run" : "benchmark") + "'s");
    }
  }
  const OutputDirLock out_lock(a.out, "--out", a.overwrite);
  if (tune) {
    std::vector<bench::TuneResult> shards;
    for (size_t i = 0; i < files.size(); ++i)
      shards.push_back(bench::read_tune_results(files[i], names[i]));
    const bench::TuneResult merged = bench::merge_tune_shards(shards, names);
    bench::write_tune_report(merged, a.out);
    std::cout << bench::tune_markdown(merged);
  } else {
    std::vector<bench::BenchResult> shards;
    for (size_t i = 0; i < files.size(); ++i)
      shards.push_back(bench::read_bench_results(files[i], names[i]));
    const bench::BenchResult merged = bench::merge_shards(shards, names);
    bench::write_bench_report(merged, a.out);
    std::cout << bench::bench_markdown(merged);
  }
  if (!quiet()) {
    std::cerr << "merged " << files.size() << " shards into "
              << (std::filesystem::path(a.out) / "report.html").string() << "\n";
  }
}

}  // namespace

void register_merge(CLI::App& app);
const CommandRegistrar kMerge(32, register_merge);

void register_merge(CLI::App& app) {
  auto a = std::make_shared<MergeArgs>();
  CLI::App* sub = app.add_subcommand(
      "merge",
      "Join the shards of a benchmark or tune run (--shard K/N) into one result and report; "
      "refuses shards of other foveate versions or settings, and missing or repeated shards");
  sub->add_option("shards", a->shards, "Each shard's --out folder (or its results.json)")
      ->required();
  sub->add_option("--out", a->out, "Output folder of the merged results and report")->required();
  add_overwrite_flag(sub, a->overwrite);
  sub->callback([a] { run_merge(*a); });
}

}  // namespace foveate::app
