// graph_sweep_plot: draws the search-time sweep (median and p99 query time against vertices, log-log)
// as a PNG. Input is a CSV with a header naming the columns `vertices`, `cpu_median_us` and
// `cpu_p99_us` (others are ignored): either graph_bench's own --benchmark_out_format=csv output or the
// summary in bench/graph/results/search_sweep.csv. Lines before the header and lines starting with '#'
// are skipped. When the
// input has Google Benchmark aggregate rows (names ending in _median), only those are drawn.
//
//   graph_sweep_plot SWEEP.csv OUT.png

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "viz/canvas.hpp"

namespace ifar::graph::bench {
namespace {

using geometry::Point;
using viz::Canvas;
using viz::Color;

struct SweepPoint {
  double vertices = 0.0;
  double median_us = 0.0;
  double p99_us = 0.0;
};

std::vector<std::string> splitCsv(const std::string& line)
{
  std::vector<std::string> fields;
  std::string field;
  bool quoted = false;
  for (const char character : line) {
    if (character == '"') {
      quoted = !quoted;
    } else if (character == ',' && !quoted) {
      fields.push_back(field);
      field.clear();
    } else if (character != '\r') {
      field += character;
    }
  }
  fields.push_back(field);
  return fields;
}

bool parseNumber(const std::string& text, double& value)
{
  std::istringstream stream(text);
  stream >> value;
  return !stream.fail() && std::isfinite(value);
}

/// The sweep's points sorted by vertices; `error` says what is wrong with the file otherwise.
std::vector<SweepPoint> readSweep(const std::string& path, std::string& error)
{
  std::ifstream file(path);
  if (!file) {
    error = path + ": cannot open";
    return {};
  }
  std::map<std::string, std::size_t> columns;
  std::vector<std::vector<std::string>> rows;
  std::size_t skipped = 0;
  for (std::string line; std::getline(file, line);) {
    if (line.empty() || line[0] == '#') {
      continue;
    }
    std::vector<std::string> fields = splitCsv(line);
    if (columns.empty()) {
      // Google Benchmark writes its context (date, CPU, caches) before the header: skip to the header.
      if (std::find(fields.begin(), fields.end(), "vertices") == fields.end()) {
        continue;
      }
      for (std::size_t index = 0; index < fields.size(); ++index) {
        columns[fields[index]] = index;
      }
      continue;
    }
    rows.push_back(std::move(fields));
  }
  if (columns.empty()) {
    error = path + ": no header line naming a 'vertices' column";
    return {};
  }
  for (const char* needed : {"cpu_median_us", "cpu_p99_us"}) {
    if (columns.count(needed) == 0) {
      error = path + ": no column '" + needed + "' in the header";
      return {};
    }
  }
  const auto name_column = columns.find("name");
  const auto isMedianRow = [&](const std::vector<std::string>& row) {
    if (name_column == columns.end() || name_column->second >= row.size()) {
      return false;
    }
    const std::string& name = row[name_column->second];
    return name.size() > 7 && name.compare(name.size() - 7, 7, "_median") == 0;
  };
  const bool only_medians = std::any_of(rows.begin(), rows.end(), isMedianRow);
  std::vector<SweepPoint> points;
  for (const auto& row : rows) {
    if (only_medians && !isMedianRow(row)) {
      continue;
    }
    SweepPoint point;
    const auto field = [&](const char* name) {
      const std::size_t index = columns.at(name);
      return index < row.size() ? row[index] : std::string();
    };
    if (!parseNumber(field("vertices"), point.vertices) ||
        !parseNumber(field("cpu_median_us"), point.median_us) ||
        !parseNumber(field("cpu_p99_us"), point.p99_us) || point.vertices <= 0.0 || point.median_us <= 0.0 ||
        point.p99_us <= 0.0) {
      ++skipped;  // error rows, or rows of other benchmarks in the same file
      continue;
    }
    points.push_back(point);
  }
  if (points.empty()) {
    error = path + ": no row with positive vertices, cpu_median_us and cpu_p99_us (" +
            std::to_string(skipped) + " rows skipped)";
  }
  std::sort(points.begin(), points.end(),
            [](const SweepPoint& a, const SweepPoint& b) { return a.vertices < b.vertices; });
  return points;
}

/// Decades covering [low, high] on a log axis.
std::pair<int, int> decades(double low, double high)
{
  return {static_cast<int>(std::floor(std::log10(low))), static_cast<int>(std::ceil(std::log10(high)))};
}

std::string decadeLabel(int exponent)
{
  if (exponent >= 0 && exponent <= 6) {
    return std::to_string(static_cast<long long>(std::llround(std::pow(10.0, exponent))));
  }
  return "1e" + std::to_string(exponent);
}

int plot(const std::vector<SweepPoint>& points, const std::string& output)
{
  // The canvas works in "world" units; here one unit is one pixel, y up.
  constexpr double kWidth = 820.0;
  constexpr double kHeight = 540.0;
  constexpr double kLeft = 80.0;
  constexpr double kRight = 50.0;
  constexpr double kBottom = 60.0;
  constexpr double kTop = 80.0;
  double low_time = points.front().median_us;
  double high_time = points.front().p99_us;
  for (const SweepPoint& point : points) {
    low_time = std::min({low_time, point.median_us, point.p99_us});
    high_time = std::max({high_time, point.median_us, point.p99_us});
  }
  // Plain names, not structured bindings: C++17 does not let the lambda below capture those.
  const std::pair<int, int> x_range = decades(points.front().vertices, points.back().vertices);
  const std::pair<int, int> y_range = decades(low_time, high_time);
  const int first_x = x_range.first;
  const int last_x = x_range.second;
  const int first_y = y_range.first;
  const int last_y = y_range.second;
  const int x_decades = std::max(1, last_x - first_x);
  const int y_decades = std::max(1, last_y - first_y);
  const auto toPlot = [&](double vertices, double microseconds) {
    return Point(kLeft + (std::log10(vertices) - first_x) / x_decades * (kWidth - kLeft - kRight),
                 kBottom + (std::log10(microseconds) - first_y) / y_decades * (kHeight - kBottom - kTop));
  };

  Canvas canvas(Point(0.0, 0.0), Point(kWidth, kHeight), 1.0);
  const Color grid = Color::gray(220);
  const Color axis = Color::gray(40);
  for (int exponent = first_x; exponent <= first_x + x_decades; ++exponent) {
    for (int multiple = 1; multiple < 10 && exponent + std::log10(multiple) <= first_x + x_decades;
         ++multiple) {
      const double x = toPlot(multiple * std::pow(10.0, exponent), std::pow(10.0, first_y)).x();
      canvas.drawSegment(Point(x, kBottom), Point(x, kHeight - kTop),
                         multiple == 1 ? grid : Color::gray(240));
    }
    const double x = toPlot(std::pow(10.0, exponent), std::pow(10.0, first_y)).x();
    const std::string label = decadeLabel(exponent);
    canvas.drawText(Point(x - 4.5 * static_cast<double>(label.size()), kBottom - 20.0), label, axis, 12);
  }
  for (int exponent = first_y; exponent <= first_y + y_decades; ++exponent) {
    for (int multiple = 1; multiple < 10 && exponent + std::log10(multiple) <= first_y + y_decades;
         ++multiple) {
      const double y = toPlot(std::pow(10.0, first_x), multiple * std::pow(10.0, exponent)).y();
      canvas.drawSegment(Point(kLeft, y), Point(kWidth - kRight, y), multiple == 1 ? grid : Color::gray(240));
    }
    const double y = toPlot(std::pow(10.0, first_x), std::pow(10.0, exponent)).y();
    canvas.drawText(Point(kLeft - 62.0, y - 5.0), decadeLabel(exponent), axis, 12);
  }
  canvas.drawPolyline({Point(kLeft, kHeight - kTop), Point(kLeft, kBottom), Point(kWidth - kRight, kBottom)},
                      axis, 2);
  canvas.drawText(Point(kWidth / 2.0 - 110.0, 15.0), "graph vertices (log scale)", axis, 13);
  // Title and y-axis name to the right of the legend box in the top-left corner.
  canvas.drawText(Point(150.0, kHeight - 28.0), "Global search (attach robot and goal + A*) vs graph size",
                  axis, 14);
  canvas.drawText(Point(150.0, kHeight - 58.0), "y: query time, microseconds of thread CPU (log scale)", axis,
                  12);
  const Color median_color{31, 119, 180};
  const Color p99_color{214, 39, 40};
  for (const auto& [color, use_p99] : {std::pair<Color, bool>{median_color, false}, {p99_color, true}}) {
    std::vector<Point> line;
    line.reserve(points.size());
    for (const SweepPoint& point : points) {
      line.push_back(toPlot(point.vertices, use_p99 ? point.p99_us : point.median_us));
    }
    canvas.drawPolyline(line, color, 2);
    for (const Point& marker : line) {
      canvas.drawCircle(marker, 4.0, {color, color, 1});
    }
  }
  canvas.drawLegend({{"median", median_color}, {"p99", p99_color}});
  const std::string problem = canvas.writePng(output);
  if (!problem.empty()) {
    std::fprintf(stderr, "graph_sweep_plot: %s\n", problem.c_str());
    return 1;
  }
  std::printf("wrote %s (%zu sizes, %s to %s vertices)\n", output.c_str(), points.size(),
              std::to_string(std::llround(points.front().vertices)).c_str(),
              std::to_string(std::llround(points.back().vertices)).c_str());
  return 0;
}

}  // namespace
}  // namespace ifar::graph::bench

int main(int argc, char** argv)
{
  const bool help = argc == 2 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0);
  if (argc != 3) {
    std::fprintf(
        help ? stdout : stderr,
        "usage: graph_sweep_plot SWEEP.csv OUT.png\n"
        "  SWEEP.csv: columns vertices, cpu_median_us, cpu_p99_us (graph_bench "
        "--benchmark_filter=SearchSweep\n"
        "  --benchmark_out=SWEEP.csv --benchmark_out_format=csv, or bench/graph/results/search_sweep.csv)\n");
    return help ? 0 : 2;
  }
  std::string error;
  const auto points = ifar::graph::bench::readSweep(argv[1], error);
  if (points.empty()) {
    std::fprintf(stderr, "graph_sweep_plot: %s\n", error.c_str());
    return 1;
  }
  return ifar::graph::bench::plot(points, argv[2]);
}
