#include "bench/scenarios/plots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "bench/scenarios/search_suite.hpp"
#include "common/vehicle.hpp"
#include "sim/world/world_geometry.hpp"
#include "viz/canvas.hpp"

namespace ifar::scenarios {
namespace {

using viz::Color;

Color plannerColor(const std::string& planner)
{
  if (planner == "grid_astar") {
    return {200, 120, 0};
  }
  if (planner == "rrt_star") {
    return {150, 60, 200};
  }
  if (planner == "bit_star") {
    return {220, 40, 40};
  }
  if (planner == "far") {
    return {30, 90, 220};
  }
  return {20, 160, 60};
}

Color bucketColor(int bucket)
{
  static const Color kColors[runner::kLossBucketCount] = {{70, 130, 200}, {200, 60, 50}, {240, 170, 40},
                                                          {140, 90, 170}, {90, 160, 90}, {150, 150, 150}};
  return kColors[bucket];
}

}  // namespace

std::string writeTimeVsGraphSizePlot(const std::vector<ResultRow>& rows, const std::string& path)
{
  // The world's graph size: FAR mode's vertex count, the same x for every planner on that world.
  std::map<std::string, double> world_size;
  for (const ResultRow& row : rows) {
    if (row.table == "search" && row.planner == "far") {
      world_size[row.world] = row.graph_vertices;
    }
  }
  struct Sample {
    std::string planner;
    double x;
    double y;
  };
  std::vector<Sample> samples;
  for (const ResultRow& row : rows) {
    const auto size = world_size.find(row.world);
    if (row.table == "search" && row.success && std::isfinite(row.ms) && row.ms > 0.0 &&
        size != world_size.end() && size->second > 0.0) {
      samples.push_back({row.planner, std::log10(size->second), std::log10(row.ms)});
    }
  }
  // Plot area in canvas units (1 unit = 1 pixel), y up.
  const double left = 90.0;
  const double bottom = 60.0;
  const double width = 760.0;
  const double height = 460.0;
  double x_min = 1.0;
  double x_max = 4.0;
  double y_min = -3.0;
  double y_max = 4.0;
  if (!samples.empty()) {
    x_min = std::floor(
        std::min_element(samples.begin(), samples.end(), [](auto& a, auto& b) { return a.x < b.x; })->x);
    x_max = std::ceil(
        std::max_element(samples.begin(), samples.end(), [](auto& a, auto& b) { return a.x < b.x; })->x);
    y_min = std::floor(
        std::min_element(samples.begin(), samples.end(), [](auto& a, auto& b) { return a.y < b.y; })->y);
    y_max = std::ceil(
        std::max_element(samples.begin(), samples.end(), [](auto& a, auto& b) { return a.y < b.y; })->y);
    x_max = std::max(x_max, x_min + 1.0);
    y_max = std::max(y_max, y_min + 1.0);
  }
  const auto at = [&](double x, double y) {
    return geometry::Point(left + (x - x_min) / (x_max - x_min) * width,
                           bottom + (y - y_min) / (y_max - y_min) * height);
  };
  viz::Canvas canvas(geometry::Point(0.0, 0.0), geometry::Point(left + width + 40.0, bottom + height + 50.0),
                     1.0);
  const Color axis = Color::gray(40);
  const Color grid = Color::gray(225);
  // The limits are whole decades: one grid line and label per power of ten.
  for (int decade = static_cast<int>(x_min); decade <= static_cast<int>(x_max); ++decade) {
    const double x = decade;
    canvas.drawSegment(at(x, y_min), at(x, y_max), grid);
    canvas.drawText(at(x, y_min) + geometry::Point(-12.0, -22.0), "1e" + std::to_string(decade), axis);
  }
  for (int decade = static_cast<int>(y_min); decade <= static_cast<int>(y_max); ++decade) {
    const double y = decade;
    canvas.drawSegment(at(x_min, y), at(x_max, y), grid);
    canvas.drawText(at(x_min, y) + geometry::Point(-50.0, -5.0), "1e" + std::to_string(decade), axis);
  }
  canvas.drawSegment(at(x_min, y_min), at(x_max, y_min), axis, 2);
  canvas.drawSegment(at(x_min, y_min), at(x_min, y_max), axis, 2);
  canvas.drawText(geometry::Point(left + 0.5 * width - 180.0, 12.0),
                  "DV-graph vertices of the world (planning map, log)", axis);
  canvas.drawText(geometry::Point(left + 200.0, bottom + height + 25.0),
                  "search time per query, CPU ms (log)", axis);
  std::vector<viz::LegendEntry> legend;
  for (const std::string& planner : searchPlanners()) {
    legend.push_back({planner, plannerColor(planner)});
  }
  // A small per-planner horizontal offset keeps the planners' columns apart at the same graph size.
  for (const Sample& sample : samples) {
    const auto index = std::find(searchPlanners().begin(), searchPlanners().end(), sample.planner) -
                       searchPlanners().begin();
    const geometry::Point point =
        at(sample.x, sample.y) + geometry::Point(6.0 * (static_cast<double>(index) - 2.0), 0.0);
    canvas.drawCircle(point, 2.5, {plannerColor(sample.planner), std::nullopt, 1});
  }
  canvas.drawLegend(legend);
  return canvas.writePng(path);
}

std::string writeLossPlot(const std::vector<ResultRow>& rows, const std::string& kind,
                          const std::string& path)
{
  struct Bar {
    std::string label;
    int runs = 0;
    double excess = 0.0;
    runner::LossBuckets sums;
  };
  std::vector<Bar> bars;
  for (const ResultRow& row : rows) {
    if (row.table != "system" || row.kind != kind || !std::isfinite(row.excess_m)) {
      continue;
    }
    const std::string label = row.planner + (row.sensing == "ideal" ? "" : " (" + row.sensing + ")");
    auto bar =
        std::find_if(bars.begin(), bars.end(), [&label](const Bar& other) { return other.label == label; });
    if (bar == bars.end()) {
      bars.push_back(Bar{label, 0, 0.0, {}});
      bar = bars.end() - 1;
    }
    ++bar->runs;
    bar->excess += row.excess_m;
    for (int bucket = 0; bucket < runner::kLossBucketCount; ++bucket) {
      runner::lossBucket(bar->sums, bucket) += runner::lossBucket(row.losses, bucket);
    }
  }
  if (bars.empty()) {
    return {};
  }
  // The ideal profile's bars first, FAR mode before ours within a profile.
  std::stable_sort(bars.begin(), bars.end(), [](const Bar& a, const Bar& b) {
    return (a.label.find('(') == std::string::npos) > (b.label.find('(') == std::string::npos);
  });
  double top = 1.0;
  double bottom = 0.0;
  for (const Bar& bar : bars) {
    double up = 0.0;
    double down = 0.0;
    for (int bucket = 0; bucket < runner::kLossBucketCount; ++bucket) {
      const double value = runner::lossBucket(bar.sums, bucket) / bar.runs;
      (value > 0.0 ? up : down) += value;
    }
    top = std::max(top, up);
    bottom = std::min(bottom, down);
  }
  // A round step for the grid, about five lines over the range.
  const double range = top - bottom;
  const double step = std::pow(10.0, std::floor(std::log10(range / 5.0)));
  const double grid_step = range / step > 25.0 ? 5.0 * step : (range / step > 10.0 ? 2.0 * step : step);
  top = std::ceil(top / grid_step) * grid_step;
  bottom = std::floor(bottom / grid_step) * grid_step;

  const double left = 230.0;  // the legend takes the top-left corner
  const double base = 60.0;
  const double height = 380.0;
  const double bar_width = 70.0;
  const double gap = 50.0;
  // At least as wide as the title under the plot.
  const double width = std::max(static_cast<double>(bars.size()) * (bar_width + gap) + gap, 400.0);
  const auto y_of = [&](double metres) { return base + (metres - bottom) / (top - bottom) * height; };
  viz::Canvas canvas(geometry::Point(0.0, 0.0), geometry::Point(left + width + 40.0, base + height + 60.0),
                     1.0);
  const Color axis = Color::gray(40);
  for (double value = bottom; value <= top + 1e-9; value += grid_step) {
    canvas.drawSegment(geometry::Point(left, y_of(value)), geometry::Point(left + width, y_of(value)),
                       Color::gray(value == 0.0 ? 120 : 225));
    char label[32];
    std::snprintf(label, sizeof(label), "%g", value);
    canvas.drawText(geometry::Point(left - 45.0, y_of(value) - 5.0), label, axis);
  }
  canvas.drawSegment(geometry::Point(left, y_of(bottom)), geometry::Point(left, y_of(top)), axis, 2);
  for (std::size_t index = 0; index < bars.size(); ++index) {
    const Bar& bar = bars[index];
    const double x0 = left + gap + static_cast<double>(index) * (bar_width + gap);
    double up = 0.0;
    double down = 0.0;
    for (int bucket = 0; bucket < runner::kLossBucketCount; ++bucket) {
      const double value = runner::lossBucket(bar.sums, bucket) / bar.runs;
      double& end = value > 0.0 ? up : down;
      const double from = end;
      end += value;
      const geometry::Polygon block{
          geometry::Point(x0, y_of(from)), geometry::Point(x0 + bar_width, y_of(from)),
          geometry::Point(x0 + bar_width, y_of(end)), geometry::Point(x0, y_of(end))};
      canvas.drawPolygon(block, {bucketColor(bucket), Color::gray(60), 1});
    }
    // The mean excess: the net height of the stack, drawn as a black tick.
    const double excess = bar.excess / bar.runs;
    canvas.drawSegment(geometry::Point(x0 - 6.0, y_of(excess)),
                       geometry::Point(x0 + bar_width + 6.0, y_of(excess)), Color::gray(0), 3);
    canvas.drawText(geometry::Point(x0, base - 22.0), bar.label, axis);
    canvas.drawText(geometry::Point(x0, base - 40.0),
                    std::to_string(bar.runs) + (bar.runs == 1 ? " run" : " runs"), Color::gray(90));
  }
  canvas.drawText(geometry::Point(left - 45.0, base + height + 30.0), kind + ": metres per run beyond the",
                  axis, 14);
  canvas.drawText(geometry::Point(left - 45.0, base + height + 12.0), "achievable way (black: the excess)",
                  axis, 14);
  std::vector<viz::LegendEntry> legend;
  for (int bucket = 0; bucket < runner::kLossBucketCount; ++bucket) {
    std::string name = runner::lossBucketName(bucket);
    std::replace(name.begin(), name.end(), '_', ' ');
    legend.push_back({name, bucketColor(bucket)});
  }
  canvas.drawLegend(legend);
  return canvas.writePng(path);
}

std::string writePathPlot(const sim::World& world, const std::vector<PathPair>& paths,
                          const std::string& title, const std::string& path)
{
  const geometry::Point extent = world.bounds_max - world.bounds_min;
  const double metres_per_pixel = std::max(0.02, std::max(extent.x(), extent.y()) / 1400.0);
  const geometry::Point margin(2.0, 2.0);
  // Room for the title under the world (the legend takes the top-left corner).
  const geometry::Point title_room(0.0, 40.0 * metres_per_pixel);
  viz::Canvas canvas(world.bounds_min - margin - title_room, world.bounds_max + margin, metres_per_pixel);
  const Color wall = Color::gray(90);
  for (const sim::StaticObstacle& obstacle : world.obstacles) {
    canvas.drawPolygon(obstacle.outline, {wall, wall, 1});
  }
  const common::VehicleSettings vehicle;
  for (const sim::MovableObject& object : world.objects) {
    const Color color = sim::isPushable(object, vehicle) ? Color{240, 160, 40} : Color{140, 20, 20};
    canvas.drawPolygon(sim::placedOutline(object), {color, Color::gray(30), 1});
  }
  const int thickness = 2;
  for (const PathPair& pair : paths) {
    canvas.drawPolyline(pair.far, Color{30, 90, 220}, thickness + 2);
    canvas.drawPolyline(pair.ours, Color{20, 160, 60}, thickness);
    canvas.drawCircle(pair.start, 0.4, {Color::gray(0), std::nullopt, 1});
    canvas.drawCircle(pair.goal, 0.6, {std::nullopt, Color{220, 30, 30}, 2});
  }
  canvas.drawText(
      world.bounds_min - margin - geometry::Point(-10.0 * metres_per_pixel, 28.0 * metres_per_pixel), title,
      Color::gray(20), 14);
  canvas.drawLegend({{"FAR mode", Color{30, 90, 220}},
                     {"ours", Color{20, 160, 60}},
                     {"light object", Color{240, 160, 40}},
                     {"heavy object", Color{140, 20, 20}}});
  return canvas.writePng(path);
}

}  // namespace ifar::scenarios
