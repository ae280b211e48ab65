#include <cmath>
#include <limits>
#include <utility>

#include <gtest/gtest.h>

#include "planner/graph/prior_map.hpp"
#include "planner/graph/search.hpp"
#include "planner/graph/visibility_builder.hpp"
#include "tests/unit/graph/test_maps.hpp"

namespace ifar::graph {
namespace {

using geometry::Point;
using testing::mapFromRows;

SearchResult plan(const PriorMap& prior, const Point& start, const Point& goal)
{
  SearchScratch scratch;
  return findPath(SearchGraph::fromDvGraph(prior.graph), prior.obstacles, start, goal, scratch);
}

TEST(Search, AroundOneBlockedCell)
{
  const PriorMap prior = buildPriorMap(mapFromRows({"...", ".@.", "..."}), 0.0);
  EXPECT_EQ(prior.graph.vertexCount(), 4u);  // the cell's corners; the rim has no convex corner
  const auto result = plan(prior, Point(0, 0), Point(3, 3));
  ASSERT_EQ(result.status, SearchStatus::Found);
  EXPECT_NEAR(result.length, 2.0 * std::sqrt(5.0), 1e-12);
  ASSERT_EQ(result.path.size(), 3u);
  EXPECT_TRUE(result.path[1].position == Point(1, 2) || result.path[1].position == Point(2, 1));
}

TEST(Search, GrazingACornerIsAllowed)
{
  // (1,3) -> (3,1) touches the corner (2,2) of the blocked cell (1,1) only.
  const PriorMap prior = buildPriorMap(mapFromRows({"....", ".@..", "....", "...."}), 0.0);
  const auto result = plan(prior, Point(1, 3), Point(3, 1));
  ASSERT_EQ(result.status, SearchStatus::Found);
  EXPECT_NEAR(result.length, 2.0 * std::sqrt(2.0), 1e-12);
  EXPECT_EQ(result.path.size(), 2u);
}

TEST(Search, NoSqueezingBetweenDiagonalCells)
{
  // Same query, but (2,2) now also blocks: the corner is where two blocked cells touch diagonally.
  const PriorMap prior = buildPriorMap(mapFromRows({"....", ".@..", "..@.", "...."}), 0.0);
  const auto result = plan(prior, Point(1, 3), Point(3, 1));
  ASSERT_EQ(result.status, SearchStatus::Found);
  EXPECT_NEAR(result.length, 4.0, 1e-12);
}

TEST(Search, RunningAlongAWallIsAllowed)
{
  const PriorMap prior = buildPriorMap(mapFromRows({".....", ".@@@.", "....."}), 0.0);
  const auto result = plan(prior, Point(0, 1), Point(5, 1));
  ASSERT_EQ(result.status, SearchStatus::Found);
  EXPECT_NEAR(result.length, 5.0, 1e-12);
}

TEST(Search, ThroughAWallIsRefused)
{
  // A vertical wall with one gap at the bottom: the path must go down and around.
  const PriorMap prior = buildPriorMap(mapFromRows({"..@..", "..@..", "..@..", "....."}), 0.0);
  const auto result = plan(prior, Point(0, 0), Point(5, 0));
  ASSERT_EQ(result.status, SearchStatus::Found);
  EXPECT_NEAR(result.length, 2.0 * std::hypot(2.0, 3.0) + 1.0, 1e-12);  // via the wall's ends (2,3), (3,3)
}

TEST(Search, EnclosedGoalHasNoPath)
{
  const PriorMap prior = buildPriorMap(mapFromRows({"@.", ".@"}), 0.0);
  // The only way from (0,2) to (2,0) is through the diagonal touch at (1,1).
  EXPECT_EQ(plan(prior, Point(0, 2), Point(2, 0)).status, SearchStatus::NoPath);
}

TEST(Search, GoalInsideObstacleIsSnapped)
{
  const PriorMap prior = buildPriorMap(mapFromRows({".....", ".@@@.", ".@@@.", ".@@@.", "....."}), 0.0);
  const auto result = plan(prior, Point(0, 0), Point(2.5, 1.4));
  ASSERT_EQ(result.status, SearchStatus::Found);
  EXPECT_TRUE(result.goal_snapped);
  EXPECT_FALSE(result.start_snapped);
  EXPECT_NEAR(result.goal.x(), 2.5, 1e-12);
  EXPECT_NEAR(result.goal.y(), 1.0, 1e-12);  // nearest boundary point: the block's top side
  EXPECT_NEAR(result.length, std::hypot(2.5, 1.0), 1e-12);
}

SearchResult planRefusingInside(const PriorMap& prior, const Point& start, const Point& goal)
{
  SearchScratch scratch;
  return findPath(SearchGraph::fromDvGraph(prior.graph), prior.obstacles, start, goal, scratch, {}, {},
                  InsideObstacle::Refuse);
}

TEST(Search, StartOrGoalInsideAnObstacleIsReportedWhenNotSnapping)
{
  const PriorMap prior = buildPriorMap(mapFromRows({".....", ".@@@.", ".@@@.", ".@@@.", "....."}), 0.0);
  const auto start_inside = planRefusingInside(prior, Point(2.5, 1.4), Point(0, 0));
  EXPECT_EQ(start_inside.status, SearchStatus::StartInObstacle);
  EXPECT_TRUE(start_inside.path.empty());
  EXPECT_FALSE(start_inside.start_snapped);
  EXPECT_EQ(start_inside.start, Point(2.5, 1.4));  // as given, not moved
  const auto goal_inside = planRefusingInside(prior, Point(0, 0), Point(2.5, 1.4));
  EXPECT_EQ(goal_inside.status, SearchStatus::GoalInObstacle);
  EXPECT_FALSE(goal_inside.goal_snapped);
  // Both inside: the start is named.
  EXPECT_EQ(planRefusingInside(prior, Point(2, 2), Point(3, 3)).status, SearchStatus::StartInObstacle);
  // On the boundary is not inside.
  const auto on_boundary = planRefusingInside(prior, Point(2.5, 1.0), Point(0, 0));
  ASSERT_EQ(on_boundary.status, SearchStatus::Found);
  EXPECT_NEAR(on_boundary.length, std::hypot(2.5, 1.0), 1e-12);
  EXPECT_STREQ(toString(SearchStatus::StartInObstacle), "start_in_obstacle");
  EXPECT_STREQ(toString(SearchStatus::GoalInObstacle), "goal_in_obstacle");
}

TEST(Search, StartInsideObstacleIsSnappedWhenAsked)
{
  const PriorMap prior = buildPriorMap(mapFromRows({".....", ".@@@.", ".@@@.", ".@@@.", "....."}), 0.0);
  const auto result = plan(prior, Point(2.5, 1.4), Point(0, 0));
  ASSERT_EQ(result.status, SearchStatus::Found);
  EXPECT_TRUE(result.start_snapped);
  EXPECT_FALSE(result.goal_snapped);
  EXPECT_EQ(result.start, Point(2.5, 1.0));  // the block's top side
  EXPECT_NEAR(result.length, std::hypot(2.5, 1.0), 1e-12);
}

TEST(Search, ExitCodesPerStatus)
{
  EXPECT_EQ(exitCodeOf(SearchStatus::Found), 0);
  EXPECT_EQ(exitCodeOf(SearchStatus::NoPath), 1);
  EXPECT_EQ(exitCodeOf(SearchStatus::InvalidStart), 2);
  EXPECT_EQ(exitCodeOf(SearchStatus::InvalidGoal), 2);
  EXPECT_EQ(exitCodeOf(SearchStatus::StartOffMap), 2);
  EXPECT_EQ(exitCodeOf(SearchStatus::GoalOffMap), 2);
  EXPECT_EQ(exitCodeOf(SearchStatus::StartInObstacle), 4);
  EXPECT_EQ(exitCodeOf(SearchStatus::GoalInObstacle), 5);
}

TEST(Search, GoalOffTheMapIsFlagged)
{
  const PriorMap prior = buildPriorMap(mapFromRows({"...", "...", "..."}), 0.0);
  EXPECT_EQ(plan(prior, Point(1, 1), Point(7, 1)).status, SearchStatus::GoalOffMap);
  EXPECT_EQ(plan(prior, Point(-1, 1), Point(1, 1)).status, SearchStatus::StartOffMap);
}

TEST(Search, NonFiniteInputsRejected)
{
  const PriorMap prior = buildPriorMap(mapFromRows({"...", ".@.", "..."}), 0.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double infinity = std::numeric_limits<double>::infinity();
  EXPECT_EQ(plan(prior, Point(nan, 0), Point(3, 3)).status, SearchStatus::InvalidStart);
  EXPECT_EQ(plan(prior, Point(0, 0), Point(3, infinity)).status, SearchStatus::InvalidGoal);
}

/// Topological waypoints of object 7 on either side of the wall row of the two-corridor map, at (0.5, 0.5)
/// above it and (0.5, 2.5) below.
std::pair<VertexId, VertexId> addWaypointsAcrossTheWall(PriorMap& prior)
{
  Vertex waypoint;
  waypoint.kind = VertexKind::TopologicalWaypoint;
  waypoint.object_id = 7;
  waypoint.position = Point(0.5, 0.5);
  const VertexId above = prior.graph.addVertex(waypoint);
  waypoint.position = Point(0.5, 2.5);
  return {above, prior.graph.addVertex(waypoint)};
}

TEST(Search, InteractionEdgeTakenWhenCheaper)
{
  // Two free corridors joined only far away; an interaction edge across the wall is cheaper.
  PriorMap prior = buildPriorMap(mapFromRows({"........", "@@@@@@@.", "........"}), 0.0);
  const auto detour = plan(prior, Point(0, 0), Point(0, 3));
  ASSERT_EQ(detour.status, SearchStatus::Found);
  const auto [above, below] = addWaypointsAcrossTheWall(prior);
  ASSERT_TRUE(prior.graph.addInteractionEdge(InteractionEdge{above, below, 7, 3.0, 42}).has_value());
  const auto pushed = plan(prior, Point(0, 0), Point(0, 3));
  ASSERT_EQ(pushed.status, SearchStatus::Found);
  EXPECT_LT(pushed.cost, detour.cost);
  EXPECT_NEAR(pushed.cost, 2.0 * std::hypot(0.5, 0.5) + 3.0, 1e-12);
  bool saw_push = false;
  for (const auto& point : pushed.path) {
    if (point.interaction != kNoInteraction) {
      saw_push = true;
      EXPECT_EQ(point.object_id, 7);
      EXPECT_EQ(point.push_plan, 42u);
      EXPECT_EQ(point.vertex, below);
    }
  }
  EXPECT_TRUE(saw_push);
  // Once the object is known to be unpushable its edges go and the detour is back.
  EXPECT_EQ(prior.graph.removeInteractionEdges(7), 1u);
  EXPECT_NEAR(plan(prior, Point(0, 0), Point(0, 3)).cost, detour.cost, 1e-12);
}

TEST(Search, APushStartsWhereTheRobotIsWhenItIsNearerTheContactThanItsWaypoint)
{
  // The robot stands between the push's start waypoint and its contact (as at a replan mid-approach or
  // mid-push): going back to the waypoint and approaching again from it is not paid. J is chosen so that
  // with that paid the detour wins by 0.3 m, and without it the push wins.
  PriorMap prior = buildPriorMap(mapFromRows({"........", "@@@@@@@.", "........"}), 0.0);
  const Point robot(0.6, 0.85);
  const Point goal(0, 3);
  const auto detour = plan(prior, robot, goal);
  ASSERT_EQ(detour.status, SearchStatus::Found);
  const Point behind(2.0, 0.5);
  const double detour_from_behind = plan(prior, behind, goal).cost;
  const auto [above, below] = addWaypointsAcrossTheWall(prior);
  const double to_waypoint = (Point(0.5, 0.5) - robot).norm();
  const double onward = (Point(0.5, 2.5) - goal).norm();
  const double cost = detour.cost + 0.3 - to_waypoint - onward;
  InteractionEdge edge{above, below, 7, cost, 42};
  edge.contact = Point(0.5, 0.9);
  edge.approach_m = 0.4;
  ASSERT_TRUE(prior.graph.addInteractionEdge(edge).has_value());
  const auto pushed = plan(prior, robot, goal);
  ASSERT_EQ(pushed.status, SearchStatus::Found);
  const double to_contact = (Point(0.5, 0.9) - robot).norm();
  EXPECT_NEAR(pushed.cost, to_contact + cost - 0.4 + onward, 1e-9);
  ASSERT_EQ(pushed.path.size(), 4u);
  EXPECT_EQ(pushed.path[1].vertex, above);  // the push still starts at its waypoint for the executive
  EXPECT_EQ(pushed.path[2].push_plan, 42u);

  // Farther from the contact than the waypoint is, the robot pays the whole approach.
  EXPECT_NEAR(plan(prior, behind, goal).cost,
              std::min((Point(0.5, 0.5) - behind).norm() + cost + onward, detour_from_behind), 1e-9);
  // Without a known approach, J stands as it is and the detour wins, as before.
  prior.graph.removeInteractionEdges(7);
  edge.approach_m = 0.0;
  ASSERT_TRUE(prior.graph.addInteractionEdge(edge).has_value());
  EXPECT_NEAR(plan(prior, robot, goal).cost, detour.cost, 1e-9);
}

std::vector<VertexId> routeOf(const SearchResult& result)
{
  std::vector<VertexId> route;
  for (const PathPoint& point : result.path) {
    if (point.vertex != kNoVertex) {
      route.push_back(point.vertex);
    }
  }
  return route;
}

TEST(Search, ThePreviousRouteStaysUntilAnotherIsClearlyShorter)
{
  // A block with a way round either side; the start and goal sit 0.05 m off its middle line, so one
  // side is 0.17 m shorter than the other.
  const PriorMap prior = buildPriorMap(mapFromRows({".....", ".@@@.", ".@@@.", ".@@@.", "....."}), 0.0);
  const SearchGraph graph = SearchGraph::fromDvGraph(prior.graph);
  SearchScratch scratch;
  const SearchResult shortest = findPath(graph, prior.obstacles, Point(0, 2.45), Point(5, 2.45), scratch);
  const SearchResult other_side = findPath(graph, prior.obstacles, Point(0, 2.55), Point(5, 2.55), scratch);
  ASSERT_EQ(shortest.status, SearchStatus::Found);
  ASSERT_EQ(other_side.status, SearchStatus::Found);
  const std::vector<VertexId> other_route = routeOf(other_side);
  ASSERT_EQ(other_route.size(), 2U);
  ASSERT_NE(routeOf(shortest), other_route);
  const double long_way = 2.0 * std::hypot(1.0, 1.55) + 3.0;
  EXPECT_NEAR(shortest.cost, 2.0 * std::hypot(1.0, 1.45) + 3.0, 1e-9);

  // Preferring the other side by 10 % of its 3 m edge (0.3 m) outweighs 0.17 m: the route stays, and
  // the cost reported is the true one.
  const SearchResult kept = findPath(graph, prior.obstacles, Point(0, 2.45), Point(5, 2.45), scratch,
                                     RoutePreference{other_route, 0.1});
  ASSERT_EQ(kept.status, SearchStatus::Found);
  EXPECT_EQ(routeOf(kept), other_route);
  EXPECT_NEAR(kept.cost, long_way, 1e-9);
  EXPECT_NEAR(kept.length, long_way, 1e-9);
  // By 2 % (0.06 m) it does not: the shorter side wins.
  const SearchResult switched = findPath(graph, prior.obstacles, Point(0, 2.45), Point(5, 2.45), scratch,
                                         RoutePreference{other_route, 0.02});
  EXPECT_EQ(routeOf(switched), routeOf(shortest));
  EXPECT_NEAR(switched.cost, shortest.cost, 1e-9);
  // A cap in metres bounds the whole preference, however large the fraction: 0.3 m of the 1.5 m that half
  // the edge would take off keeps the route, 0.1 m (less than the 0.17 m it is longer) does not.
  const SearchResult capped_kept = findPath(graph, prior.obstacles, Point(0, 2.45), Point(5, 2.45), scratch,
                                            RoutePreference{other_route, 0.5, 0.3});
  EXPECT_EQ(routeOf(capped_kept), other_route);
  EXPECT_NEAR(capped_kept.cost, long_way, 1e-9);
  const SearchResult capped_switched = findPath(graph, prior.obstacles, Point(0, 2.45), Point(5, 2.45),
                                                scratch, RoutePreference{other_route, 0.5, 0.1});
  EXPECT_EQ(routeOf(capped_switched), routeOf(shortest));
  EXPECT_NEAR(capped_switched.cost, shortest.cost, 1e-9);
  // Vertices the graph no longer has are skipped, not trusted.
  const SearchResult stale = findPath(graph, prior.obstacles, Point(0, 2.45), Point(5, 2.45), scratch,
                                      RoutePreference{{other_route[0], 100000U, other_route[1]}, 0.1});
  EXPECT_EQ(routeOf(stale), routeOf(shortest));
}

TEST(Search, ASurchargeOnOneSideTurnsTheRouteToTheOther)
{
  // The block of the test above: the shorter side is 0.17 m shorter than the other.
  const PriorMap prior = buildPriorMap(mapFromRows({".....", ".@@@.", ".@@@.", ".@@@.", "....."}), 0.0);
  const SearchGraph graph = SearchGraph::fromDvGraph(prior.graph);
  SearchScratch scratch;
  const Point start(0, 2.45);
  const Point goal(5, 2.45);
  const SearchResult shortest = findPath(graph, prior.obstacles, start, goal, scratch);
  const SearchResult other_side = findPath(graph, prior.obstacles, Point(0, 2.55), Point(5, 2.55), scratch);
  ASSERT_EQ(shortest.status, SearchStatus::Found);
  ASSERT_EQ(shortest.path.size(), 4U);
  const double long_way = 2.0 * std::hypot(1.0, 1.55) + 3.0;

  // 0.2 m on each of the three stretches that touch the shorter side's corners (as unseen space would
  // cost there): more than the 0.17 m it is shorter by.
  const Point corner_a = shortest.path[1].position;
  const Point corner_b = shortest.path[2].position;
  const auto on_shorter_side = [&](const Point& from, const Point& to) {
    const bool touches = (from - corner_a).norm() < 1e-9 || (from - corner_b).norm() < 1e-9 ||
                         (to - corner_a).norm() < 1e-9 || (to - corner_b).norm() < 1e-9;
    return touches ? 0.2 : 0.0;
  };
  const SearchResult turned = findPath(graph, prior.obstacles, start, goal, scratch, {}, on_shorter_side);
  ASSERT_EQ(turned.status, SearchStatus::Found);
  EXPECT_EQ(routeOf(turned), routeOf(other_side));
  EXPECT_NEAR(turned.length, long_way, 1e-9);
  EXPECT_NEAR(turned.cost, long_way, 1e-9);

  // A surcharge on every stretch (the robot's link, the edge, the goal's link) is in the cost, not the
  // length; a negative one counts as none.
  const SearchResult everywhere = findPath(graph, prior.obstacles, start, goal, scratch, {},
                                           [](const Point&, const Point&) { return 0.5; });
  EXPECT_EQ(routeOf(everywhere), routeOf(shortest));
  EXPECT_NEAR(everywhere.cost, shortest.cost + 1.5, 1e-9);
  EXPECT_NEAR(everywhere.length, shortest.length, 1e-9);
  const SearchResult negative = findPath(graph, prior.obstacles, start, goal, scratch, {},
                                         [](const Point&, const Point&) { return -5.0; });
  EXPECT_NEAR(negative.cost, shortest.cost, 1e-9);

  // Preferring the shorter side by half its 3 m edge outweighs the surcharge: the route stays, and the
  // cost reported is the true one, surcharge included.
  const SearchResult kept = findPath(graph, prior.obstacles, start, goal, scratch,
                                     RoutePreference{routeOf(shortest), 0.5}, on_shorter_side);
  EXPECT_EQ(routeOf(kept), routeOf(shortest));
  EXPECT_NEAR(kept.cost, shortest.cost + 0.6, 1e-9);
}

TEST(Search, ScratchReusedAcrossGraphs)
{
  const PriorMap small = buildPriorMap(mapFromRows({"...", ".@.", "..."}), 0.0);
  const PriorMap larger = buildPriorMap(mapFromRows({".....", ".@.@.", ".....", ".@.@.", "....."}), 0.0);
  SearchScratch scratch;
  const auto small_graph = SearchGraph::fromDvGraph(small.graph);
  const auto larger_graph = SearchGraph::fromDvGraph(larger.graph);
  for (int round = 0; round < 3; ++round) {
    EXPECT_NEAR(findPath(small_graph, small.obstacles, Point(0, 0), Point(3, 3), scratch).length,
                2.0 * std::sqrt(5.0), 1e-12);
    EXPECT_NEAR(findPath(larger_graph, larger.obstacles, Point(1, 0), Point(1, 5), scratch).length, 5.0,
                1e-12);
  }
}

}  // namespace
}  // namespace ifar::graph

namespace ifar::graph {
namespace {

TEST(Search, PerceptionPolygonsInEitherOrientation)
{
  // A clockwise square (as a contour tracer may give it) blocks like a counter-clockwise one.
  const geometry::Polygon clockwise = {Point(1, 1), Point(1, 3), Point(3, 3), Point(3, 1)};
  const ObstacleSet obstacles({loopFromPolygon(clockwise, 5)});
  EXPECT_EQ(obstacles.loops().front().object_id, 5);
  EXPECT_FALSE(obstacles.visible(Point(0, 2), Point(4, 2)));
  EXPECT_TRUE(obstacles.visible(Point(0, 3), Point(4, 3)));  // along the side
  EXPECT_TRUE(obstacles.isBlocked(Point(2, 2)));
  EXPECT_FALSE(obstacles.isBlocked(Point(0, 0)));
  DvGraph graph;
  addReducedVisibilityGraph(obstacles, graph);
  EXPECT_EQ(graph.vertexCount(), 4u);
  EXPECT_EQ(graph.visibilityEdgeCount(), 4u);  // the sides; the diagonals cross the inside
  SearchScratch scratch;
  const auto result = findPath(SearchGraph::fromDvGraph(graph), obstacles, Point(0, 2), Point(4, 2), scratch);
  ASSERT_EQ(result.status, SearchStatus::Found);
  EXPECT_NEAR(result.length, 2.0 * std::sqrt(2.0) + 2.0, 1e-12);
}

}  // namespace
}  // namespace ifar::graph

namespace ifar::graph {
namespace {

TEST(Search, WaypointConnectedByVisibility)
{
  PriorMap prior = buildPriorMap(testing::mapFromRows({".....", ".@.@.", "....."}), 0.0);
  Vertex waypoint;
  waypoint.kind = VertexKind::TopologicalWaypoint;
  waypoint.position = Point(2.5, 1.5);  // in the gap between the two blocked cells
  const VertexId id = prior.graph.addVertex(waypoint);
  // It sees the four corners facing the gap and the four outer ones along the rows above and below...
  const std::size_t added = connectByVisibility(prior.obstacles, prior.graph, id);
  EXPECT_EQ(added, prior.graph.visibilityLinks(id).size());
  EXPECT_GE(added, 4u);
  for (const auto& link : prior.graph.visibilityLinks(id)) {
    const Vertex* other = prior.graph.vertex(link.other);
    ASSERT_NE(other, nullptr);
    EXPECT_TRUE(prior.obstacles.visible(waypoint.position, other->position));
  }
  EXPECT_EQ(connectByVisibility(prior.obstacles, prior.graph, id), 0u);  // idempotent
  EXPECT_EQ(connectByVisibility(prior.obstacles, prior.graph, kNoVertex), 0u);
}

}  // namespace
}  // namespace ifar::graph

namespace ifar::graph {
namespace {

TEST(ObstacleSet, NonFiniteAndFarPointsHandled)
{
  const ObstacleSet obstacles({loopFromPolygon({Point(1, 1), Point(3, 1), Point(3, 3), Point(1, 3)})});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  BlockerCache cache;
  EXPECT_FALSE(obstacles.visible(Point(nan, 0), Point(4, 4)));
  EXPECT_FALSE(obstacles.visible(Point(0, 0), Point(4, std::numeric_limits<double>::infinity()), cache));
  EXPECT_TRUE(obstacles.isBlocked(Point(nan, 1)));
  EXPECT_FALSE(obstacles.isBlocked(Point(1e300, 2)));
  EXPECT_FALSE(obstacles.isBlocked(Point(-1e300, -1e300)));
  EXPECT_TRUE(obstacles.visible(Point(-1e12, 0), Point(1e12, 0)));
  EXPECT_FALSE(obstacles.visible(Point(-1e6, 2), Point(1e6, 2)));
}

}  // namespace
}  // namespace ifar::graph

namespace ifar::graph {
namespace {

TEST(SearchNoPath, SaysWhereTheGraphIsCutOff)
{
  // Column 3 is a wall from rim to rim; the start's side holds one blocked cell, whose four corners are
  // all the search reaches. The nearest of them to the goal (4.5, 3) is (2, 2).
  const PriorMap prior = buildPriorMap(mapFromRows({"...@.", ".@.@.", "...@.", "...@."}), 0.0);
  const SearchResult result = plan(prior, Point(0.5, 0.5), Point(4.5, 3.0));
  ASSERT_EQ(result.status, SearchStatus::NoPath);
  EXPECT_EQ(result.nearest_reached, Point(2.0, 2.0));
  EXPECT_DOUBLE_EQ(result.nearest_reached_distance, std::hypot(2.5, 1.0));
  EXPECT_EQ(
      describeNoPath(result),
      "the 4 vertices reachable from the start do not see the goal: the nearest, at (2.00, 2.00), is 2.69 m "
      "from it (the graph is cut off there)");
}

TEST(SearchNoPath, SaysWhenTheStartIsEnclosed)
{
  // The start's side of the wall has no corner at all.
  const PriorMap prior = buildPriorMap(mapFromRows({"..@..", "..@.@", "..@..", "..@.."}), 0.0);
  const SearchResult result = plan(prior, Point(0.5, 0.5), Point(3.5, 3.0));
  ASSERT_EQ(result.status, SearchStatus::NoPath);
  EXPECT_EQ(describeNoPath(result), "no graph vertex is visible from the start: it is enclosed");
  const SearchResult found = plan(prior, Point(0.5, 0.5), Point(1.5, 3.0));
  EXPECT_EQ(found.status, SearchStatus::Found);
  EXPECT_EQ(describeNoPath(found), "");
}

}  // namespace
}  // namespace ifar::graph
