#include "bench/graph/synthetic_worlds.hpp"

#include <algorithm>
#include <random>

#include "planner/graph/merge.hpp"
#include "planner/graph/visibility_builder.hpp"

namespace ifar::graph::bench {

std::vector<ObstacleLoop> rectangles(const RectangleField& field)
{
  std::mt19937 generator(field.seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double cell_width = field.width_m / field.columns;
  const double cell_height = field.height_m / field.rows;
  std::vector<ObstacleLoop> loops;
  for (int row = 0; row < field.rows; ++row) {
    for (int column = 0; column < field.columns; ++column) {
      // Keep a 10 % margin on each side so neighbouring rectangles never touch.
      const double side_x = std::min(
          field.min_side_m + unit(generator) * (field.max_side_m - field.min_side_m), 0.8 * cell_width);
      const double side_y = std::min(
          field.min_side_m + unit(generator) * (field.max_side_m - field.min_side_m), 0.8 * cell_height);
      const double x = column * cell_width + 0.1 * cell_width + unit(generator) * (0.8 * cell_width - side_x);
      const double y = row * cell_height + 0.1 * cell_height + unit(generator) * (0.8 * cell_height - side_y);
      loops.push_back(ObstacleLoop{{geometry::Point(x, y), geometry::Point(x + side_x, y),
                                    geometry::Point(x + side_x, y + side_y), geometry::Point(x, y + side_y)},
                                   0});
    }
  }
  return loops;
}

DvGraph fullGraph(const ObstacleSet& obstacles)
{
  DvGraph graph;
  addReducedVisibilityGraph(obstacles, graph);
  return graph;
}

DvGraph mergedGraph(const std::vector<ObstacleLoop>& loops, double width_m, double height_m, double window_m)
{
  DvGraph global;
  GraphSettings settings;
  settings.association_distance_m = 1e-6;
  settings.votes = 1000000;  // a static field: nothing disappears
  const double step = 0.5 * window_m;
  // Integer counters: a summed double step could add or drop a window at the far edge.
  for (int row = 0; row * step < height_m; ++row) {
    const double y = row * step;
    for (int column = 0; column * step < width_m; ++column) {
      const double x = column * step;
      std::vector<ObstacleLoop> local;
      for (const auto& loop : loops) {
        const auto& corner = loop.vertices.front();
        if (corner.x() >= x && corner.x() < x + window_m && corner.y() >= y && corner.y() < y + window_m) {
          local.push_back(loop);
        }
      }
      const ObstacleSet obstacles(std::move(local));
      DvGraph local_graph;
      addReducedVisibilityGraph(obstacles, local_graph);
      // The view disc covers the whole square window (0.75 > sqrt(2) / 2).
      const geometry::Point centre(x + 0.5 * window_m, y + 0.5 * window_m);
      mergeLocalIntoGlobal(toLocalLayer(local_graph), SensorView{centre, 0.75 * window_m}, settings, global);
    }
  }
  return global;
}

}  // namespace ifar::graph::bench
