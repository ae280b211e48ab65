#pragma once
// Puts one object's interaction results into the DV-graph: a TopologicalWaypoint vertex per component
// and a directed interaction edge (cost J) per found push plan. Kept out of ifar_interaction so the
// search library does not depend on the graph.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "planner/graph/dv_graph.hpp"
#include "planner/interaction/interaction_planner.hpp"

namespace ifar::interaction {

struct InsertedInteractions {
  std::vector<graph::VertexId> waypoint_vertices;  ///< index = waypoint / component index
  std::vector<std::uint32_t> edges;                ///< interaction edge indices, one per found plan
  std::size_t plans_without_edge = 0;              ///< ordered pairs with no plan (status != Found)
};

/// Replaces the object's interaction edges: removes the old ones, then adds waypoint vertices and an
/// edge per found plan. Edge i's push_plan handle is `first_plan_handle` plus the plan's index in
/// `interactions.plans`, so the caller can keep the plans in a vector beside the graph.
InsertedInteractions insertInteractions(graph::DvGraph& graph, std::int64_t object_id,
                                        const ObjectInteractions& interactions,
                                        std::uint32_t first_plan_handle);

}  // namespace ifar::interaction
