#pragma once
// A small SVG line chart writer (no dependencies), used for the planner sweep
// and the benchmark report.
#include <string>
#include <vector>

namespace foveate::app {

struct Series {
  std::string name;
  std::string color;
  std::vector<double> x;
  std::vector<double> y;
  bool dashed = false;
};

struct ChartOptions {
  std::string title;
  std::string x_label;
  std::string y_label;
  bool log_y = false;
  int width = 720;
  int height = 440;
};

std::string svg_line_chart(const std::vector<Series>& series, const ChartOptions& options);

}  // namespace foveate::app
