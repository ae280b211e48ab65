#pragma once
// A generic hybrid A* (Nav2 Smac's split): the search owns the open list, duplicate detection, the
// deadline and the analytic expansion's schedule; a search space supplies what its states are. Node
// storage is an index-linked vector, so a found path is read back from its goal.
//
// A Space provides:
//   using State = ...;                                  // copyable
//   std::uint64_t key(const State&) const;              // duplicate-detection cell (discretised state)
//   double heuristic(const State&) const;               // cost-to-go estimate
//   bool isGoal(const State&) const;
//   std::optional<HybridAStarStep<State>> analyticExpansion(const State&) const;   // a shot to the goal
//   template <typename Add> void expand(const State&, bool root, Add&& add) const; // add(next, step_cost)
// Roots are not duplicate-checked against each other: each is a separate way into the search.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <queue>
#include <unordered_map>
#include <utility>
#include <vector>

#include "planner/interaction/search_deadline.hpp"

namespace ifar::interaction {

enum class HybridAStarStatus {
  Found,           ///< a goal state was reached; the path ends there
  ExpansionLimit,  ///< the deadline's expansions ran out
  TimeBudget,      ///< the deadline's time ran out
  Exhausted,       ///< every state reachable from the roots was expanded
};

/// A successor state and the cost of the step to it.
template <typename State>
struct HybridAStarStep {
  State state;
  double cost = 0.0;
};

template <typename State>
struct HybridAStarResult {
  HybridAStarStatus status = HybridAStarStatus::Exhausted;
  std::vector<State> path;  ///< root first, the goal state last; empty unless Found
  std::size_t expansions = 0;
};

template <typename Space>
class HybridAStar {
 public:
  using State = typename Space::State;

  /// The analytic expansion is tried at every root and every `analytic_interval` expansions.
  HybridAStar(const Space& space, const SearchDeadline& deadline, std::size_t analytic_interval)
      : space_(space), deadline_(deadline), analytic_interval_(std::max<std::size_t>(1, analytic_interval))
  {
  }

  /// Searches from `roots` (each with its cost so far) until a goal, the deadline or exhaustion.
  HybridAStarResult<State> run(const std::vector<HybridAStarStep<State>>& roots)
  {
    for (const HybridAStarStep<State>& root : roots) {
      nodes_.push_back(Node{root.state, root.cost, -1, true});
      open_.push(QueueEntry{root.cost + space_.heuristic(root.state), static_cast<int>(nodes_.size() - 1)});
    }
    HybridAStarResult<State> result;
    int goal_node = -1;
    while (!open_.empty()) {
      if (deadline_.outOfExpansions(result.expansions)) {
        result.status = HybridAStarStatus::ExpansionLimit;
        break;
      }
      // The clock is read every 16 expansions only: a budget is many expansions long.
      if ((result.expansions & 15U) == 0 && deadline_.outOfTime()) {
        result.status = HybridAStarStatus::TimeBudget;
        break;
      }
      goal_node = step(result.expansions);
      if (goal_node >= 0) {
        break;
      }
    }
    if (goal_node >= 0) {
      result.status = HybridAStarStatus::Found;
      result.path = pathTo(goal_node);
    }
    return result;
  }

 private:
  struct Node {
    State state;
    double cost = 0.0;
    int parent = -1;
    bool root = false;
  };
  struct QueueEntry {
    double priority;
    int node;
    bool operator>(const QueueEntry& other) const { return priority > other.priority; }
  };

  /// Pops the best open node and expands it; returns the goal node when one is reached, else -1.
  int step(std::size_t& expansions)
  {
    const int current_index = open_.top().node;
    open_.pop();
    const Node current = nodes_[static_cast<std::size_t>(current_index)];  // a copy: nodes_ grows below
    const auto settled = best_cost_.find(space_.key(current.state));
    if (!current.root && settled != best_cost_.end() && settled->second < current.cost - 1e-9) {
      return -1;  // a cheaper copy of this state was queued later
    }
    if (space_.isGoal(current.state)) {
      return current_index;
    }
    ++expansions;
    if (current.root || expansions % analytic_interval_ == 0) {
      if (std::optional<HybridAStarStep<State>> shot = space_.analyticExpansion(current.state)) {
        nodes_.push_back(Node{std::move(shot->state), current.cost + shot->cost, current_index, false});
        return static_cast<int>(nodes_.size() - 1);
      }
    }
    space_.expand(current.state, current.root, [&](const State& next, double step_cost) {
      add(current_index, next, current.cost + step_cost);
    });
    return -1;
  }

  /// Queues `state` unless a copy at most as costly was queued before.
  void add(int parent, const State& state, double cost)
  {
    const std::uint64_t key = space_.key(state);
    const auto found = best_cost_.find(key);
    if (found != best_cost_.end() && found->second <= cost + 1e-9) {
      return;
    }
    best_cost_[key] = cost;
    nodes_.push_back(Node{state, cost, parent, false});
    open_.push(QueueEntry{cost + space_.heuristic(state), static_cast<int>(nodes_.size() - 1)});
  }

  std::vector<State> pathTo(int goal_node) const
  {
    std::vector<State> path;
    for (int index = goal_node; index >= 0; index = nodes_[static_cast<std::size_t>(index)].parent) {
      path.push_back(nodes_[static_cast<std::size_t>(index)].state);
    }
    std::reverse(path.begin(), path.end());
    return path;
  }

  const Space& space_;
  SearchDeadline deadline_;
  std::size_t analytic_interval_;
  std::vector<Node> nodes_;
  std::priority_queue<QueueEntry, std::vector<QueueEntry>, std::greater<QueueEntry>> open_;
  std::unordered_map<std::uint64_t, double> best_cost_;
};

}  // namespace ifar::interaction
