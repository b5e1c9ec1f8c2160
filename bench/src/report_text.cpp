// results.csv, results.md, and the files of a report written together.
#include <filesystem>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>

#include "foveate/bench/report.hpp"
#include "foveate/core/file.hpp"
#include "report_common.hpp"

namespace foveate::bench {

namespace {

// The quality columns' titles, then the header's rule: `rule` for the
// leading columns and one right-aligned rule per quality column.
std::string quality_header(const std::string& rule) {
  std::string h;
  for (const QualityColumn& c : kQualityColumns) h += std::string(" ") + c.title + " |";
  h += "\n" + rule;
  for (size_t i = 0; i < std::size(kQualityColumns); ++i) h += "---:|";
  return h + "\n";
}

std::string passes_markdown(const BenchResult& b) {
  if (!b.options.passes) return {};
  std::ostringstream s;
  s << "\nTime per pass, ms per frame (share of the frame). Resolve = composite, reconstruction, "
       "temporal, warps, blurs, upscales and copies.\n\n| technique | passes | resolve share "
       "|\n|---|---|---:|\n";
  for (const TechniqueResult& r : b.results) {
    s << "| " << label(b, r) << " | ";
    s << pass_list(r, "") << " | " << format_fixed(100 * resolve_ms(r) / r.mean_ms, 1) << " % |\n";
  }
  return s.str();
}

// Stereo: each eye's pixels and quality.
std::string eyes_markdown(const BenchResult& b) {
  if (!b.stereo) return {};
  std::ostringstream s;
  s << "\nStereo: " << b.options.session.size.width << 'x' << b.options.session.size.height
    << " per eye, IPD " << format_fixed(b.stereo->ipd_mm, 1)
    << " mm. Times above are per stereo frame (both eyes), pixels both eyes' and quality over "
       "both eyes' frames; per eye:\n\n| technique | eye | JOD | shaded px | pixel ratio |"
    << quality_header("|---|---|---:|---:|---:|");
  for (const TechniqueResult& r : b.results) {
    for (Eye e : kEyes) {
      if (r.eyes.size() != 2) continue;
      const TechniqueResult::Eye& eye = r.eyes[static_cast<size_t>(e)];
      const double jod = eye.metrics && eye.metrics->fvvdp ? eye.metrics->fvvdp->jod : std::nan("");
      s << "| " << label(b, r) << " | " << eye_name(e) << " | "
        << (std::isfinite(jod) ? format_fixed(jod, 3) : std::string("-")) << " | "
        << format_fixed(eye.shaded_pixels, 0) << " | " << format_fixed(eye.pixel_ratio, 3) << " |";
      for (const QualityColumn& c : kQualityColumns) {
        const double v = eye.metrics ? c.get(*eye.metrics) : std::nan("");
        s << ' ' << (std::isfinite(v) ? format_fixed(v, c.digits) : std::string("-")) << " |";
      }
      s << '\n';
    }
  }
  return s.str();
}

std::string number_or_empty(double v) {
  return std::isfinite(v) ? format_number(v) : std::string();
}

}  // namespace

std::string bench_csv(const BenchResult& b) {
  std::ostringstream s;
  s << "technique,label,sweep_value,jod,jod_below_native,mean_ms,median_ms,p90_ms,speedup,"
       "speedup_lo,speedup_hi,shaded_pixels,native_pixels,pixel_ratio,bound_share";
  for (const QualityColumn& c : kQualityColumns) s << ',' << c.csv;
  s << '\n';
  for (const TechniqueResult& r : b.results) {
    s << r.technique << ',' << '"' << label(b, r) << '"' << ',' << format_number(r.sweep_value)
      << ',' << number_or_empty(jod_of(r)) << ',' << number_or_empty(jod_below_native(b, r)) << ','
      << format_number(r.mean_ms, 3) << ',' << format_number(r.median_ms, 3) << ','
      << format_number(r.p90_ms, 3) << ',' << format_number(r.speedup, 4) << ','
      << format_number(r.speedup_lo, 4) << ',' << format_number(r.speedup_hi, 4) << ','
      << format_number(r.shaded_pixels, 1) << ',' << format_number(r.native_pixels, 0) << ','
      << format_number(r.pixel_ratio) << ',' << format_number(r.bound_share, 4);
    for (const QualityColumn& c : kQualityColumns) {
      const double v = quality_value(r, c);
      s << ',' << (std::isfinite(v) ? format_number(v) : std::string());
    }
    s << '\n';
  }
  return s.str();
}

std::string bench_markdown(const BenchResult& b) {
  std::ostringstream s;
  // FovVideoVDP first: a speedup counts at the quality it keeps.
  s << "| technique | JOD | below native | speedup (95 % CI) | mean ms | median ms | p90 ms | "
       "shaded px | pixel ratio | share of bound |"
    << quality_header("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
  const auto jod_cell = [](double v) { return std::isfinite(v) ? format_fixed(v, 3) : "-"; };
  for (const TechniqueResult& r : b.results) {
    s << "| " << label(b, r) << row_marks(b, r) << " | " << jod_cell(jod_of(r)) << " | "
      << jod_cell(jod_below_native(b, r)) << " | " << format_fixed(r.speedup, 2) << "x ("
      << format_fixed(r.speedup_lo, 2) << "-" << format_fixed(r.speedup_hi, 2) << ") | "
      << format_fixed(r.mean_ms, 2) << " | " << format_fixed(r.median_ms, 2) << " | "
      << format_fixed(r.p90_ms, 2) << " | " << format_fixed(r.shaded_pixels, 0) << " | "
      << format_fixed(r.pixel_ratio, 3) << " | " << format_fixed(100 * r.bound_share, 0) << " % |";
    for (const QualityColumn& c : kQualityColumns) s << ' ' << quality_cell(r, c) << " |";
    s << '\n';
  }
  const std::vector<std::string> notes = mark_notes(b);
  if (!notes.empty()) s << '\n';
  for (const std::string& n : notes) s << n << '\n';
  if (const auto busy = busy_machine(b.environment)) s << "\nWarning: " << *busy << ".\n";
  s << eyes_markdown(b) << passes_markdown(b);
  return s.str();
}

void write_bench_report(const BenchResult& b, const std::string& dir) {
  namespace fs = std::filesystem;
  make_output_dir(dir, "out");
  const fs::path d(dir);
  write_file_atomic((d / "results.json").string(), bench_json(b).dump(2) + "\n");
  write_file_atomic((d / "results.csv").string(), bench_csv(b));
  write_file_atomic((d / "results.md").string(), bench_markdown(b));
  write_html_report(bench_html(b), dir);
}

void write_html_report(const std::string& html, const std::string& dir) {
  namespace fs = std::filesystem;
  make_output_dir(dir, "out");
  const fs::path d(dir);
  write_file_atomic((d / "report.html").string(), html);
  for (const auto& [name, svg] : report_figures(html)) write_file_atomic((d / name).string(), svg);
}

}  // namespace foveate::bench
