#include "bench/scenarios/goal_sequence_tasks.hpp"

#include <cmath>
#include <string>

#include "bench/scenarios/task_lengths.hpp"

namespace ifar::scenarios {

std::vector<Task> goalSequenceTasks(const sim::World& world, const ScenarioMaps& maps,
                                    double goal_tolerance_m)
{
  std::vector<Task> tasks;
  graph::SearchScratch scratch;
  for (std::size_t index = 0; index < world.goals.size(); ++index) {
    Task task;
    task.id = "g" + std::to_string(index);
    task.start = index == 0 ? world.start.position() : world.goals[index - 1].position;
    task.goal = world.goals[index].position;
    // A scenario's goal may lie on the rasterised edge of a wall: the snapped path still measures it.
    const ExactOptimum optimum = exactOptimum(maps, task.start, task.goal, scratch, true);
    // With no exact path at all (an enclosed goal) the straight line stands in, a lower bound that only
    // sizes the run's time limit: such a goal is unreachable whatever the vehicle does.
    task.optimal = std::isfinite(optimum.length) ? optimum.length : (task.goal - task.start).norm();
    task.start_heading = index == 0 ? world.start.heading : optimum.heading;
    task.achievable = lengthOn(maps.pushing, task.start, task.goal, scratch, goal_tolerance_m);
    task.without_pushing = lengthOn(maps.far, task.start, task.goal, scratch, goal_tolerance_m);
    task.reachable_with_pushing = std::isfinite(task.achievable) && std::isfinite(optimum.length);
    task.from_world = true;
    tasks.push_back(task);
  }
  return tasks;
}

}  // namespace ifar::scenarios
