#include "bench/search_comparison/query_set.hpp"

#include <cmath>
#include <limits>
#include <random>

namespace ifar::bench {

namespace {

// A path search that only needs to know "connected, and how long".
double searchLength(const graph::PriorMap& prior, const graph::SearchGraph& search_graph,
                    graph::SearchScratch& scratch, const geometry::Point& start, const geometry::Point& goal)
{
  const graph::SearchResult result = graph::findPath(search_graph, prior.obstacles, start, goal, scratch);
  if (result.status != graph::SearchStatus::Found || result.start_snapped || result.goal_snapped) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  return result.length;
}

}  // namespace

double exactOptimum(const graph::PriorMap& exact, const geometry::Point& start, const geometry::Point& goal)
{
  const graph::SearchGraph search_graph = graph::SearchGraph::fromDvGraph(exact.graph);
  graph::SearchScratch scratch;
  return searchLength(exact, search_graph, scratch, start, goal);
}

std::vector<Query> randomQueries(const grid_map::GridMap& planning_grid, grid_map::UnknownPolicy policy,
                                 const graph::PriorMap& planning, const graph::PriorMap& exact,
                                 const RandomQuerySettings& settings)
{
  std::vector<grid_map::CellIndex> free_cells;
  for (int y = 0; y < planning_grid.height(); ++y) {
    for (int x = 0; x < planning_grid.width(); ++x) {
      if (!planning_grid.blocked(x, y, policy)) {
        free_cells.push_back(grid_map::CellIndex{x, y});
      }
    }
  }
  std::vector<Query> queries;
  if (free_cells.size() < 2 || settings.count <= 0) {
    return queries;
  }
  const graph::SearchGraph planning_graph = graph::SearchGraph::fromDvGraph(planning.graph);
  const graph::SearchGraph exact_graph = graph::SearchGraph::fromDvGraph(exact.graph);
  graph::SearchScratch scratch;
  std::mt19937_64 random(settings.seed);
  std::uniform_int_distribution<std::size_t> pick(0, free_cells.size() - 1);
  const long long attempts = static_cast<long long>(settings.count) * settings.max_attempts_per_query;
  for (long long attempt = 0; attempt < attempts && static_cast<int>(queries.size()) < settings.count;
       ++attempt) {
    const grid_map::CellIndex a = free_cells[pick(random)];
    const grid_map::CellIndex b = free_cells[pick(random)];
    const geometry::Point start = planning_grid.cellCentre(a.x, a.y);
    const geometry::Point goal = planning_grid.cellCentre(b.x, b.y);
    const double optimal = searchLength(exact, exact_graph, scratch, start, goal);
    if (!std::isfinite(optimal) || optimal < settings.min_length || optimal <= 0.0) {
      continue;
    }
    if (!std::isfinite(searchLength(planning, planning_graph, scratch, start, goal))) {
      continue;  // connected without inflation but not on the planners' map
    }
    queries.push_back(Query{"q" + std::to_string(queries.size()), start, goal, optimal});
  }
  return queries;
}

}  // namespace ifar::bench
