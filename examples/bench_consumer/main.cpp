// A program outside the foveate tree that runs a benchmark through the
// installed package: it registers a technique of its own (native_copy.hpp),
// measures it beside every built-in technique the scene can run, and writes
// the report. Run: ./bench_consumer [out-folder]
#include <cstdio>
#include <string>

#include "foveate/bench/bench.hpp"
#include "foveate/bench/report.hpp"
#include "foveate/core/error.hpp"
#include "native_copy.hpp"

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "bench-consumer-out";
  try {
    example::register_native_copy();
    foveate::bench::BenchOptions options;  // every registered technique the scene can run
    options.session.scene = "cheap";
    options.session.size = {96, 54};
    options.frames = 2;
    options.warmup = 1;
    options.command = "bench_consumer";
    foveate::bench::BenchCallbacks callbacks;
    callbacks.session.notice = [](const foveate::bench::Notice& n) {
      if (n.kind != foveate::bench::NoticeKind::Detail)
        std::fprintf(stderr, "bench_consumer: %s\n", n.text.render().c_str());
    };
    const foveate::bench::BenchResult result = foveate::bench::run_bench(options, callbacks);
    foveate::bench::write_bench_report(result, out);
    std::printf("%s", foveate::bench::bench_markdown(result).c_str());
    for (const foveate::bench::TechniqueResult& r : result.results) {
      if (r.technique == example::kNativeCopy) {
        std::printf("report: %s/report.html\n", out.c_str());
        return 0;
      }
    }
    std::fprintf(stderr, "bench_consumer: %s was not measured\n", example::kNativeCopy);
    return 1;
  } catch (const foveate::Error& e) {
    std::fprintf(stderr, "bench_consumer: error: %s\n", e.what());
    return 1;
  }
}
