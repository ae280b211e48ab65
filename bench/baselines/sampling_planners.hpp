#pragma once
// The sampling baselines, RRT* and BIT* from OMPL, in the plane bounded by the map, with exact
// collision checking: a state is valid when it is not strictly inside an obstacle, a motion when its
// straight segment enters no blocked side (graph::ObstacleSet::visible, the same exact test and
// uniform-grid edge index the DV-graph uses), not by sampling points along it.
//
// The paper's protocol: run until a path within `optimum_factor` times the optimal length is found,
// and report the time to that point; the time cap turns a slow query into a recorded Timeout.
// OMPL headers stay in the .cpp file.

#include <cstdint>

#include "bench/baselines/baseline_result.hpp"
#include "common/geometry/point.hpp"
#include "planner/graph/obstacle_set.hpp"

namespace ifar::baselines {

enum class SamplingAlgorithm { RrtStar, BitStar };

const char* toString(SamplingAlgorithm algorithm);

struct SamplingSettings {
  double time_cap_s = 5.0;      // per query, CPU time of the calling thread
  double optimum_factor = 1.5;  // stop once the best path is at most this times the optimum
  double range_m = 0.0;         // RRT* steering distance; 0 lets OMPL choose (a fraction of the extent)
  double goal_bias = 0.05;      // RRT*
};

/// Seeds OMPL's random generators. Call once, before the first plan (OMPL ignores later calls).
void seedSamplingPlanners(std::uint64_t seed);

/// Plans from `start` to `goal` among `obstacles`, which must have bounds (a prior map). `optimal_length`
/// is the known optimum; when it is not finite or not positive the planner stops at its first solution.
BaselineResult planSampling(SamplingAlgorithm algorithm, const graph::ObstacleSet& obstacles,
                            const geometry::Point& start, const geometry::Point& goal, double optimal_length,
                            const SamplingSettings& settings);

}  // namespace ifar::baselines
