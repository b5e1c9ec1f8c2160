// foveate merge: the shards of a benchmark (bench --shard K/N, or tune's)
// joined into one results.json, results.csv, results.md and report.html.
// foveate report: benchmarks read back (runs, scenes, shards) shown on one
// page with their charts as SVG files beside it.
#include <filesystem>
#include <iostream>
#include <map>
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

void run_merge(const MergeArgs& a) {
  const bench::MergedShards merged = bench::merge_shard_files(a.shards);
  const OutputDirLock out_lock(a.out, "--out", a.overwrite);
  if (merged.tune) {
    bench::write_tune_report(*merged.tune, a.out);
    std::cout << bench::tune_markdown(*merged.tune);
  } else {
    bench::write_bench_report(*merged.bench, a.out);
    std::cout << bench::bench_markdown(*merged.bench);
  }
  if (!quiet()) {
    std::cerr << "merged " << a.shards.size() << " shards into "
              << (std::filesystem::path(a.out) / "report.html").string() << "\n";
  }
}

struct ReportArgs {
  std::vector<std::string> results;
  std::string out;
  bool overwrite = false;
};

// The benchmarks given, with the shards of one benchmark merged into one (in
// the place of its first shard), and the name of each.
struct Benchmarks {
  std::vector<bench::BenchResult> results;
  std::vector<std::string> names;
};

Benchmarks read_benchmarks(const std::vector<std::string>& given) {
  Benchmarks all;
  std::map<std::string, size_t> shard_group;  // settings -> index in `groups`
  std::vector<std::vector<bench::BenchResult>> groups;
  std::vector<std::vector<std::string>> group_names;
  for (const std::string& g : given) {
    const std::string path = bench::shard_results_file(g);
    const nlohmann::json j = read_json_file(path, "benchmark results");
    if (j.value("schema", "") == bench::kTuneSchema) {
      throw Error(path +
                  ": a tune run's results; report combines benchmarks (bench --out), "
                  "and a tune run has its own report.html");
    }
    bench::BenchResult r = bench::read_bench_results(j, path);
    if (r.options.shard.count <= 1) {
      groups.push_back({std::move(r)});
      group_names.push_back({path});
      continue;
    }
    // A shard: with the others of its benchmark (the same settings).
    const auto [it, fresh] = shard_group.try_emplace(r.settings_key, groups.size());
    if (fresh) groups.emplace_back(), group_names.emplace_back();
    groups[it->second].push_back(std::move(r));
    group_names[it->second].push_back(path);
  }
  for (size_t i = 0; i < groups.size(); ++i) {
    if (groups[i].front().options.shard.count > 1) {
      all.results.push_back(bench::merge_shards(groups[i], group_names[i]));
      const size_t others = groups[i].size() - 1;
      all.names.push_back(group_names[i].front() + " and " + std::to_string(others) +
                          (others == 1 ? " other shard" : " other shards"));
    } else {
      all.results.push_back(std::move(groups[i].front()));
      all.names.push_back(group_names[i].front());
    }
  }
  return all;
}

void run_report(const ReportArgs& a) {
  const Benchmarks b = read_benchmarks(a.results);
  const std::string html = b.results.size() == 1 ? bench::bench_html(b.results.front())
                                                 : bench::combined_html(b.results, b.names);
  const OutputDirLock out_lock(a.out, "--out", a.overwrite);
  bench::write_html_report(html, a.out);
  if (!quiet()) {
    std::cerr << "wrote " << (std::filesystem::path(a.out) / "report.html").string() << " ("
              << b.results.size() << (b.results.size() == 1 ? " benchmark, " : " benchmarks, ")
              << bench::report_figures(html).size() << " charts as SVG beside it)\n";
  }
}

}  // namespace

void register_merge(CLI::App& app);
void register_report(CLI::App& app);
const CommandRegistrar kMerge(32, register_merge);
const CommandRegistrar kReport(33, register_report);

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

void register_report(CLI::App& app) {
  auto a = std::make_shared<ReportArgs>();
  CLI::App* sub = app.add_subcommand(
      "report",
      "One HTML page from several benchmarks (runs, scenes; the shards of one benchmark are "
      "merged): every run in one table and chart, then each benchmark's sections; each chart "
      "also as an SVG file beside the page");
  sub->add_option("results", a->results, "Each benchmark's --out folder (or its results.json)")
      ->required();
  sub->add_option("--out", a->out, "Output folder of report.html and its charts")->required();
  add_overwrite_flag(sub, a->overwrite);
  sub->callback([a] { run_report(*a); });
}

}  // namespace foveate::app
