#pragma once
// A benchmark's results as files: JSON (schema in docs/bench-json.md), CSV,
// a Markdown table and a single-file HTML report that opens offline.
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <utility>
#include <vector>

#include "foveate/bench/bench.hpp"

namespace foveate::bench {

/// The results as results.json holds them.
nlohmann::json bench_json(const BenchResult& result);
std::string bench_csv(const BenchResult& result);
std::string bench_markdown(const BenchResult& result);
/// The HTML report: tables, charts with ticks and units, the techniques'
/// layers over their frames, crops, error heat maps and full frames.
std::string bench_html(const BenchResult& result);
/// One page from several benchmarks (runs, scenes, merged shards): every run
/// of every benchmark in one table and chart, then each benchmark's sections
/// as bench_html shows them; `names[i]` names results[i] (its file).
std::string combined_html(const std::vector<BenchResult>& results,
                          const std::vector<std::string>& names);
/// The charts of a page from bench_html or combined_html as SVG files of
/// their own: (file name, its text), named by each chart's id.
std::vector<std::pair<std::string, std::string>> report_figures(const std::string& html);
/// Writes `html` as report.html into `dir` and each of its charts beside it
/// (report_figures), each file atomically.
void write_html_report(const std::string& html, const std::string& dir);
/// Writes results.json, results.csv, results.md and report.html with its
/// charts into `dir` (created with its parents), each file atomically.
void write_bench_report(const BenchResult& result, const std::string& dir);

}  // namespace foveate::bench
