#include "planner/interaction/push_problem.hpp"

#include "planner/interaction/body_frame.hpp"

namespace ifar::interaction {

using geometry::Point;
using geometry::Polygon;
using geometry::Segment;
using geometry::Vector;

namespace {

std::vector<PushContact> reachableContacts(const PushObject& object, const PushCollisionChecker& checker,
                                           const Point& start)
{
  std::vector<PushContact> contacts;
  const ObjectModel& model = object.model();
  const Polygon outline_world = transformed(model.travel_outline, model.pose);
  for (std::size_t edge = 0; edge < object.edgeOptions().size(); ++edge) {
    if (!object.edgeOptions()[edge].pushable()) {
      continue;
    }
    const Point standing = model.pose.transform(object.standingPoint(edge));
    if (checker.pointBlocked(standing)) {
      continue;
    }
    const Segment approach{start, standing};
    bool visible = true;
    for (std::size_t index = 0; index < outline_world.size() && visible; ++index) {
      visible = !geometry::segmentsCrossProperly(approach, geometry::polygonEdge(outline_world, index));
    }
    if (visible && !checker.crossesAnObstacle(approach)) {
      contacts.push_back(PushContact{edge, approach.length()});
    }
  }
  return contacts;
}

}  // namespace

PushProblemResult makePushProblem(const PushObject& object, const PushCollisionChecker& checker,
                                  const PushGoalTest& goal_test, const Point& start, const Point& goal)
{
  PushProblemResult result;
  if (!start.allFinite() || !goal.allFinite() || (goal - start).norm() < 1e-6 ||
      checker.pointBlocked(start) || checker.pointBlocked(goal)) {
    result.status = PlanStatus::InvalidWaypoints;
    return result;
  }
  PushProblem& problem = result.problem;
  problem.start = start;
  problem.goal = goal;
  problem.goal_region = goal_test.region(start, goal);
  const Vector& normal = object.face().normal;
  const bool depth_along_normal = normal.dot(object.model().pose.position() - start) >= 0.0;
  problem.depth_direction = depth_along_normal ? normal : Vector(-normal);
  problem.depth_side = depth_along_normal ? 0 : 1;
  problem.contacts = reachableContacts(object, checker, start);
  if (problem.contacts.empty()) {
    result.status = PlanStatus::UnreachableContact;
  }
  return result;
}

}  // namespace ifar::interaction
