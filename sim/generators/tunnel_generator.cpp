#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <queue>
#include <vector>

#include "sim/generators/generators.hpp"
#include "sim/generators/world_builder.hpp"

namespace ifar::sim {
namespace {

constexpr double kWidth = 330.0;
constexpr double kHeight = 270.0;
constexpr double kTunnel = 4.0;      // tunnel width
constexpr double kFrame = 3.0;       // rock around the network
constexpr double kCrateDepth = 1.2;  // along the tunnel; a crate is 0.4 m narrower than the tunnel
constexpr int kColumns = 7;
constexpr int kRows = 6;
constexpr double kTargetPath = 450.0;
constexpr double kNiche = 4.0;  // rock left out of a closed tunnel's end to take a crate pushed into it

struct Edge {
  int from = 0;  // junction index = row * kColumns + column
  int to = 0;
  bool horizontal = true;
  bool open = true;
};

class Lattice {
 public:
  Lattice(std::vector<double> xs, std::vector<double> ys) : xs_(std::move(xs)), ys_(std::move(ys))
  {
    for (int row = 0; row < kRows; ++row) {
      for (int column = 0; column < kColumns; ++column) {
        if (column + 1 < kColumns) {
          edges_.push_back({index(column, row), index(column + 1, row), true, true});
        }
        if (row + 1 < kRows) {
          edges_.push_back({index(column, row), index(column, row + 1), false, true});
        }
      }
    }
  }

  static int index(int column, int row) { return row * kColumns + column; }
  geometry::Point junction(int node) const { return {xs_[node % kColumns], ys_[node / kColumns]}; }
  double length(const Edge& edge) const { return (junction(edge.to) - junction(edge.from)).norm(); }
  std::vector<Edge>& edges() { return edges_; }
  const std::vector<Edge>& edges() const { return edges_; }
  double x(int column) const { return xs_[column]; }
  double y(int row) const { return ys_[row]; }

  /// Shortest distances over open edges, skipping edge `skip` (-1 = none); `previous` gets the edge
  /// index each node was reached by.
  std::vector<double> distances(int source, int skip, std::vector<int>* previous = nullptr) const
  {
    const int count = kColumns * kRows;
    std::vector<double> distance(count, std::numeric_limits<double>::infinity());
    std::vector<int> via(count, -1);
    using Entry = std::pair<double, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    distance[source] = 0.0;
    queue.push({0.0, source});
    while (!queue.empty()) {
      const auto [cost, node] = queue.top();
      queue.pop();
      if (cost > distance[node]) {
        continue;
      }
      for (int index = 0; index < static_cast<int>(edges_.size()); ++index) {
        const Edge& edge = edges_[index];
        if (!edge.open || index == skip || (edge.from != node && edge.to != node)) {
          continue;
        }
        const int other = edge.from == node ? edge.to : edge.from;
        const double next = cost + length(edge);
        if (next < distance[other]) {
          distance[other] = next;
          via[other] = index;
          queue.push({next, other});
        }
      }
    }
    if (previous != nullptr) {
      *previous = via;
    }
    return distance;
  }

  /// The edge that goes on straight through `to` coming from `from` (neighbouring junctions), or -1 at the
  /// lattice's border.
  int straightOn(int from, int to) const
  {
    const int column = to % kColumns + (to % kColumns - from % kColumns);
    const int row = to / kColumns + (to / kColumns - from / kColumns);
    if (column < 0 || row < 0 || column >= kColumns || row >= kRows) {
      return -1;
    }
    return edgeBetween(to, index(column, row));
  }

  int edgeBetween(int first, int second) const
  {
    for (int index = 0; index < static_cast<int>(edges_.size()); ++index) {
      const Edge& edge = edges_[index];
      if ((edge.from == first && edge.to == second) || (edge.from == second && edge.to == first)) {
        return index;
      }
    }
    return -1;
  }

  bool connected() const
  {
    const auto distance = distances(0, -1);
    return std::all_of(distance.begin(), distance.end(), [](double value) { return std::isfinite(value); });
  }

 private:
  std::vector<double> xs_;
  std::vector<double> ys_;
  std::vector<Edge> edges_;
};

std::vector<double> positions(SeededRandom& random, double extent, int count)
{
  const double first = kFrame + 0.5 * kTunnel;
  const double last = extent - kFrame - 0.5 * kTunnel;
  const double spacing = (last - first) / (count - 1);
  std::vector<double> values;
  for (int index = 0; index < count; ++index) {
    const double jitter = (index == 0 || index == count - 1) ? 0.0 : random.uniform(-0.15, 0.15) * spacing;
    values.push_back(std::round((first + index * spacing + jitter) * 10.0) / 10.0);
  }
  return values;
}

/// Where along an edge a crate goes (a point on the tunnel's centre line at least 8 m from junctions).
geometry::Point alongEdge(const Lattice& lattice, const Edge& edge, SeededRandom& random)
{
  const geometry::Point from = lattice.junction(edge.from);
  const geometry::Point to = lattice.junction(edge.to);
  const double length = (to - from).norm();
  const double at = random.uniform(8.0, length - 8.0);
  const geometry::Point point = from + (to - from) * (at / length);
  return {std::round(point.x() * 10.0) / 10.0, std::round(point.y() * 10.0) / 10.0};
}

/// Where a crate across the tunnel from `near_end` to `far_end` goes: its far face 0.3-0.9 m short of the
/// far junction, so a push of about 3-4 m (the interaction planner's reach) puts it into the junction and
/// clears the turn there.
geometry::Point beforeJunction(const Lattice& lattice, int near_end, int far_end, SeededRandom& random)
{
  const geometry::Point from = lattice.junction(near_end);
  const geometry::Point to = lattice.junction(far_end);
  const geometry::Point direction = (to - from).normalized();
  const double back = 0.5 * kTunnel + 0.5 * kCrateDepth + random.uniform(0.3, 0.9);
  const geometry::Point point = to - direction * back;
  return {std::round(point.x() * 10.0) / 10.0, std::round(point.y() * 10.0) / 10.0};
}

}  // namespace

World generateTunnel(std::uint64_t seed)
{
  return generateTunnel(seed, TunnelCrates::Mixed);
}

World generateTunnel(std::uint64_t seed, TunnelCrates crate_choice)
{
  const bool light_on_detours = crate_choice == TunnelCrates::LightOnLongestDetours;
  SeededRandom random(seed);
  Lattice lattice(positions(random, kWidth, kColumns), positions(random, kHeight, kRows));

  // Close about a third of the tunnels while everything stays connected.
  auto& edges = lattice.edges();
  std::vector<int> order(edges.size());
  for (int index = 0; index < static_cast<int>(order.size()); ++index) {
    order[index] = index;
  }
  for (int index = static_cast<int>(order.size()) - 1; index > 0; --index) {
    std::swap(order[index], order[random.integer(0, index)]);
  }
  const std::size_t to_close = edges.size() / 3;
  std::size_t closed = 0;
  for (const int candidate : order) {
    if (closed == to_close) {
      break;
    }
    edges[candidate].open = false;
    if (lattice.connected()) {
      ++closed;
    } else {
      edges[candidate].open = true;
    }
  }

  WorldBuilder builder(
      light_on_detours ? "blocked_tunnel" : "tunnel",
      std::string(light_on_detours ? "generator blocked_tunnel seed " : "generator tunnel seed ") +
          std::to_string(seed));
  const double half = 0.5 * kTunnel;
  builder.addRectangle("rock", {0.0, 0.0, kWidth, kFrame}, 4.0);
  builder.addRectangle("rock", {0.0, kHeight - kFrame, kWidth, kHeight}, 4.0);
  builder.addRectangle("rock", {0.0, kFrame, kFrame, kHeight - kFrame}, 4.0);
  builder.addRectangle("rock", {kWidth - kFrame, kFrame, kWidth, kHeight - kFrame}, 4.0);
  for (int row = 0; row + 1 < kRows; ++row) {
    for (int column = 0; column + 1 < kColumns; ++column) {
      builder.addRectangle("rock",
                           {lattice.x(column) + half, lattice.y(row) + half, lattice.x(column + 1) - half,
                            lattice.y(row + 1) - half},
                           4.0);
    }
  }

  // Goal: the junction whose shortest route from the start junction is nearest the target length.
  const int start_node = 0;
  const auto distance = lattice.distances(start_node, -1);
  int goal_node = start_node;
  for (int node = 0; node < static_cast<int>(distance.size()); ++node) {
    if (std::abs(distance[node] - kTargetPath) < std::abs(distance[goal_node] - kTargetPath)) {
      goal_node = node;
    }
  }
  builder.setStart({lattice.junction(start_node).x(), lattice.junction(start_node).y(), 0.0});
  builder.addGoal(lattice.junction(goal_node));

  // Crates across tunnels of the shortest route: light ones to push, heavy ones only where a way round
  // exists (the tunnel is not a bridge between start and goal). A crate fills the tunnel's width, so the
  // vehicle can only push it ahead along the tunnel: it goes only where the route turns at the next
  // junction and the tunnel straight on is open, so it can be pushed through the junction and out of the
  // way. Never into the goal's junction: a dead end there would leave the crate on the goal. It stands just
  // short of that junction, so the push is a short one.
  // The shortest route over the open tunnels, as junctions and the tunnels between them.
  struct Route {
    std::vector<int> nodes;  // start to goal
    std::vector<int> edges;  // edges[i] joins nodes[i] and nodes[i + 1]
  };
  const auto shortestRoute = [&]() {
    std::vector<int> via;
    lattice.distances(start_node, -1, &via);
    Route found{{goal_node}, {}};
    for (int node = goal_node; node != start_node;) {
      const int edge = via[node];
      found.edges.push_back(edge);
      node = edges[edge].from == node ? edges[edge].to : edges[edge].from;
      found.nodes.push_back(node);
    }
    std::reverse(found.nodes.begin(), found.nodes.end());
    std::reverse(found.edges.begin(), found.edges.end());
    return found;
  };
  // A crate across a route's tunnel, just short of its far junction.
  struct Crate {
    int edge;
    int near_end;
    int far_end;
    ObjectWeight weight;
  };
  // Where a crate can stand on a route: a tunnel long enough, the route turning at its far junction, and
  // the tunnel straight on there open to take the pushed crate (or, with light crates on the detours,
  // closed: a niche is left there for it).
  const auto crateSteps = [&](const Route& route) {
    std::vector<std::size_t> steps;
    for (std::size_t step = 0; step + 2 < route.nodes.size(); ++step) {
      const int straight_on = lattice.straightOn(route.nodes[step], route.nodes[step + 1]);
      const bool turns = straight_on != route.edges[step + 1];
      if (lattice.length(edges[route.edges[step]]) >= 20.0 && turns && straight_on >= 0 &&
          (edges[straight_on].open || light_on_detours)) {
        steps.push_back(step);
      }
    }
    return steps;
  };
  const Route route = shortestRoute();
  std::vector<Crate> chosen;
  if (light_on_detours) {
    // Light crates, up to five, one at a time: on the current shortest route (the crates before closing
    // their tunnels), the tunnel whose closing lengthens the way from start to goal most while a way
    // remains, so that without pushing the goal is still reachable but far.
    for (int crate = 0; crate < 5; ++crate) {
      const Route current = shortestRoute();
      double longest = 0.0;
      std::optional<Crate> best;
      for (const std::size_t step : crateSteps(current)) {
        const int straight_on = lattice.straightOn(current.nodes[step], current.nodes[step + 1]);
        if (std::any_of(chosen.begin(), chosen.end(),
                        [&](const Crate& other) { return other.edge == straight_on; })) {
          continue;  // a crate pushed on would meet another
        }
        Edge& tunnel = edges[current.edges[step]];
        tunnel.open = false;
        const double way = lattice.distances(start_node, -1)[goal_node];
        tunnel.open = true;
        if (std::isfinite(way) && way > longest) {
          longest = way;
          best =
              Crate{current.edges[step], current.nodes[step], current.nodes[step + 1], ObjectWeight::Light};
        }
      }
      if (!best) {
        break;
      }
      edges[best->edge].open = false;
      chosen.push_back(*best);
    }
    for (const Crate& crate : chosen) {
      edges[crate.edge].open = true;  // the crates stand in open tunnels
    }
  } else {
    // Up to three on the shortest route, the second heavy unless its tunnel is a bridge.
    for (const std::size_t step : crateSteps(route)) {
      if (chosen.size() == 3) {
        break;
      }
      const bool bridge = !std::isfinite(lattice.distances(start_node, route.edges[step])[goal_node]);
      chosen.push_back(Crate{route.edges[step], route.nodes[step], route.nodes[step + 1],
                             (chosen.size() == 1 && !bridge) ? ObjectWeight::Heavy : ObjectWeight::Light});
    }
  }
  // The closed tunnels' rock; where a crate is to be pushed straight on into a closed tunnel, a niche
  // of kNiche is left at that junction's end to take it.
  std::vector<std::pair<int, int>> niches;  // closed edge, junction
  for (const Crate& crate : chosen) {
    const int straight_on = lattice.straightOn(crate.near_end, crate.far_end);
    if (!edges[straight_on].open) {
      niches.emplace_back(straight_on, crate.far_end);
    }
  }
  for (int index = 0; index < static_cast<int>(edges.size()); ++index) {
    const Edge& edge = edges[index];
    if (edge.open) {
      continue;
    }
    const auto niche_at = [&](int junction) {
      return std::find(niches.begin(), niches.end(), std::make_pair(index, junction)) != niches.end() ? kNiche
                                                                                                      : 0.0;
    };
    const auto a = lattice.junction(edge.from);
    const auto b = lattice.junction(edge.to);
    if (edge.horizontal) {
      builder.addRectangle(
          "rock",
          {a.x() + half + niche_at(edge.from), a.y() - half, b.x() - half - niche_at(edge.to), a.y() + half},
          4.0);
    } else {
      builder.addRectangle(
          "rock",
          {a.x() - half, a.y() + half + niche_at(edge.from), a.x() + half, b.y() - half - niche_at(edge.to)},
          4.0);
    }
  }
  std::vector<geometry::Point> placed_objects;
  for (const Crate& crate : chosen) {
    const auto centre = beforeJunction(lattice, crate.near_end, crate.far_end, random);
    const bool horizontal = edges[crate.edge].horizontal;
    builder.addObject(centre, horizontal ? kCrateDepth : kTunnel - 0.4,
                      horizontal ? kTunnel - 0.4 : kCrateDepth, 0.0, crate.weight, random);
    placed_objects.push_back(centre);
  }
  // Loose boxes against tunnel sides elsewhere: they narrow a tunnel but do not close it.
  for (int placed = 0, tries = 0; placed < 12 && tries < 100; ++tries) {
    const int edge_index = random.integer(0, static_cast<int>(edges.size()) - 1);
    const Edge& edge = edges[edge_index];
    const bool crate_tunnel = std::any_of(chosen.begin(), chosen.end(),
                                          [&](const Crate& crate) { return crate.edge == edge_index; });
    if (!edge.open || crate_tunnel ||
        std::find(route.edges.begin(), route.edges.end(), edge_index) != route.edges.end() ||
        lattice.length(edge) < 20.0) {
      continue;
    }
    const auto point = alongEdge(lattice, edge, random);
    const double side = random.chance(0.5) ? 1.0 : -1.0;
    const geometry::Point centre = edge.horizontal
                                       ? geometry::Point(point.x(), point.y() + side * (half - 0.6))
                                       : geometry::Point(point.x() + side * (half - 0.6), point.y());
    // Rock lines every tunnel, so only the distance to other objects matters.
    bool free = true;
    for (const auto& other : placed_objects) {
      free = free && (other - centre).norm() > 5.0;
    }
    if (free) {
      placed_objects.push_back(centre);
      builder.addObject(centre, 1.0, 1.0, 0.0, placed % 3 == 0 ? ObjectWeight::Heavy : ObjectWeight::Light,
                        random);
      ++placed;
    }
  }
  return builder.build();
}

}  // namespace ifar::sim
