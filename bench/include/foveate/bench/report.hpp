#pragma once
// A benchmark's results as files: JSON (schema in docs/bench-json.md), CSV,
// a Markdown table and a single-file HTML report that opens offline.
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "foveate/bench/bench.hpp"

namespace foveate::bench {

/// The results as results.json holds them.
nlohmann::json bench_json(const BenchResult& result);
std::string bench_csv(const BenchResult& result);
std::string bench_markdown(const BenchResult& result);
/// The HTML report: tables, charts with ticks and units, the techniques'
/// layers over their frames, crops, error heat maps and full frames.
std::string bench_html(const BenchResult& result);
/// Writes results.json, results.csv, results.md and report.html into `dir`
/// (created with its parents), each file atomically.
void write_bench_report(const BenchResult& result, const std::string& dir);

}  // namespace foveate::bench
