// The loss accounting on constructed runs, written through the recorder as the runner writes them: a
// dead-end exploration, a failed push, a route switch, a loop off the path and a completed push, each
// with its buckets computed by hand (open ground, so the achievable distance to the goal is the straight
// line); and the buckets of a long random walk adding up to its excess.

#include "system/loss_accounting.hpp"

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "system/path_arc.hpp"
#include "system/run_trace.hpp"

namespace ifar::runner {
namespace {

using geometry::Point;

const Point kGoal(10.0, 0.0);

double straightToGoal(const Point& from)
{
  return (from - kGoal).norm();
}

/// Drives in a straight line to `to` in steps of at most 1 cm (as simulator steps would), with the
/// executive in `mode` (pushing `object` when it is a push mode).
void driveTo(RunTraceRecorder& recorder, Point& at, const Point& to, executive::Mode mode,
             std::int64_t object = -1, int pushes = 0)
{
  const double length = (to - at).norm();
  const int steps = std::max(1, static_cast<int>(std::ceil(length / 0.01)));
  const Point from = at;
  for (int step = 1; step <= steps; ++step) {
    recorder.executiveCycle(ExecutiveCycle{mode, object, pushes, false});
    at = from + (to - from) * (static_cast<double>(step) / steps);
    recorder.position(at);
  }
}

void plan(RunTraceRecorder& recorder, const std::vector<Point>& polyline, const Point& vehicle,
          const WayOpen& way_open = {})
{
  recorder.plannedPath(polyline, vehicle, way_open);
}

/// A wall across x < 0 at y = 2, seen once the vehicle is 4 m out along y = 0.
bool openBelowTheWall(const Point& from, const Point& to)
{
  const bool crosses = (from.y() - 2.0) * (to.y() - 2.0) < 0.0;
  const double x = from.x() + (to.x() - from.x()) * (2.0 - from.y()) / (to.y() - from.y());
  return !(crosses && x < 0.0);
}

void expectBuckets(const LossAccount& account, const LossBuckets& expected)
{
  ASSERT_TRUE(account.valid) << account.problem;
  constexpr double kTolerance = 1e-6;
  EXPECT_NEAR(account.buckets.exploring_m, expected.exploring_m, kTolerance);
  EXPECT_NEAR(account.buckets.attempts_m, expected.attempts_m, kTolerance);
  EXPECT_NEAR(account.buckets.route_switches_m, expected.route_switches_m, kTolerance);
  EXPECT_NEAR(account.buckets.route_choice_m, expected.route_choice_m, kTolerance);
  EXPECT_NEAR(account.buckets.execution_m, expected.execution_m, kTolerance);
  EXPECT_NEAR(account.buckets.push_overhead_m, expected.push_overhead_m, kTolerance);
  EXPECT_NEAR(account.buckets.total(), account.excess_m, kTolerance);
}

TEST(LossAccounting, ADeadEndExplorationCostsTwiceItsDepthToExploring)
{
  RunTraceRecorder recorder;
  Point at(0.0, 0.0);
  recorder.position(at);
  // The first route leads away from the goal into space not seen yet; 4 m in, a wall across it is seen
  // and the planner's new route leads back past the start.
  plan(recorder, {at, Point(-4.0, 0.0), Point(-4.0, 20.0), kGoal}, at);
  driveTo(recorder, at, Point(-4.0, 0.0), executive::Mode::Follow);
  plan(recorder, {at, kGoal}, at, openBelowTheWall);
  driveTo(recorder, at, Point(9.5, 0.0), executive::Mode::Follow);
  const RunTrace trace = recorder.finish();
  ASSERT_EQ(trace.routes.size(), 2U);
  EXPECT_EQ(trace.routes[0].end, RouteEnd::WorldChanged);
  EXPECT_EQ(trace.routes[1].end, RouteEnd::Kept);

  const LossAccount account = accountLosses(trace, straightToGoal);
  EXPECT_NEAR(account.travelled_m, 17.5, 1e-9);
  EXPECT_NEAR(account.achievable_m, 10.0, 1e-12);
  EXPECT_NEAR(account.remaining_m, 0.5, 1e-12);
  EXPECT_NEAR(account.excess_m, 8.0, 1e-9);
  // 4 m out: the vehicle drove 4 m and got 4 m further from the goal.
  LossBuckets expected;
  expected.exploring_m = 8.0;
  expectBuckets(account, expected);
}

TEST(LossAccounting, AFailedPushBooksTheWayToItAndTheAttemptToAttempts)
{
  RunTraceRecorder recorder;
  Point at(0.0, 0.0);
  recorder.position(at);
  // Through a door north of the start where a box stands; the achievable way is straight east.
  plan(recorder, {at, Point(0.0, 3.0), Point(10.0, 3.0), kGoal}, at);
  driveTo(recorder, at, Point(0.0, 2.0), executive::Mode::Follow);
  driveTo(recorder, at, Point(0.0, 2.5), executive::Mode::Approach, 7);
  driveTo(recorder, at, Point(0.0, 2.5), executive::Mode::Push, 7);
  // The box does not move under the maximum force: the executive says so and waits for a new plan.
  recorder.executiveCycle(ExecutiveCycle{executive::Mode::Push, 7, 0, true});
  recorder.executiveCycle(ExecutiveCycle{executive::Mode::ReplanWait, 7, 0, false});
  plan(recorder, {at, kGoal}, at);
  driveTo(recorder, at, kGoal, executive::Mode::Follow);
  const RunTrace trace = recorder.finish();
  ASSERT_EQ(trace.pushes.size(), 1U);
  EXPECT_EQ(trace.pushes[0].object_id, 7);
  EXPECT_EQ(trace.pushes[0].outcome, PushOutcome::Failed);
  ASSERT_EQ(trace.routes.size(), 2U);
  EXPECT_EQ(trace.routes[0].end, RouteEnd::AttemptFailed);

  const LossAccount account = accountLosses(trace, straightToGoal);
  // 2.5 m north and back down the diagonal: 2.5 + |(10, -2.5)| - 10.
  const double excess = 2.5 + std::hypot(10.0, 2.5) - 10.0;
  EXPECT_NEAR(account.excess_m, excess, 1e-9);
  LossBuckets expected;
  expected.attempts_m = excess;
  expectBuckets(account, expected);
}

TEST(LossAccounting, ARouteGivenUpWhileStillOpenIsARouteSwitch)
{
  RunTraceRecorder recorder;
  Point at(0.0, 0.0);
  recorder.position(at);
  // Over a hump for no reason: the planner drops the route for the straight one while the first is
  // still open.
  plan(recorder, {at, Point(5.0, 5.0), kGoal}, at);
  driveTo(recorder, at, Point(1.0, 1.0), executive::Mode::Follow);
  plan(recorder, {at, kGoal}, at);
  driveTo(recorder, at, kGoal, executive::Mode::Follow);
  const RunTrace trace = recorder.finish();
  ASSERT_EQ(trace.routes.size(), 2U);
  EXPECT_EQ(trace.routes[0].end, RouteEnd::Switched);

  LossBuckets expected;
  // sqrt(2) driven for 10 - |(9, -1)| nearer the goal.
  expected.route_switches_m = std::sqrt(2.0) + std::hypot(9.0, 1.0) - 10.0;
  expectBuckets(accountLosses(trace, straightToGoal), expected);
}

TEST(LossAccounting, AStepOffThePathAndBackIsExecution)
{
  RunTraceRecorder recorder;
  Point at(0.0, 0.0);
  recorder.position(at);
  plan(recorder, {at, kGoal}, at);
  // A square kink: 1 m off the path, 1 m along beside it, 1 m back on.
  driveTo(recorder, at, Point(2.0, 0.0), executive::Mode::Follow);
  driveTo(recorder, at, Point(2.0, 1.0), executive::Mode::Follow);
  driveTo(recorder, at, Point(3.0, 1.0), executive::Mode::Follow);
  driveTo(recorder, at, Point(3.0, 0.0), executive::Mode::Follow);
  driveTo(recorder, at, kGoal, executive::Mode::Follow);
  const RunTrace trace = recorder.finish();
  EXPECT_EQ(trace.routes.size(), 1U);
  LossBuckets expected;
  expected.execution_m = 2.0;
  expectBuckets(accountLosses(trace, straightToGoal), expected);
}

TEST(LossAccounting, ACompletedPushBooksItsManoeuvringToPushOverhead)
{
  RunTraceRecorder recorder;
  Point at(0.0, 0.0);
  recorder.position(at);
  plan(recorder, {at, Point(3.0, 0.0), kGoal}, at);
  driveTo(recorder, at, Point(2.0, 0.0), executive::Mode::Follow);
  // Round to the box's far side and push it 2 m aside, then back onto the way.
  driveTo(recorder, at, Point(2.0, 1.0), executive::Mode::Approach, 3);
  driveTo(recorder, at, Point(4.0, 1.0), executive::Mode::Push, 3);
  recorder.executiveCycle(ExecutiveCycle{executive::Mode::Follow, -1, 1, false});
  driveTo(recorder, at, Point(4.0, 0.0), executive::Mode::Follow, -1, 1);
  driveTo(recorder, at, kGoal, executive::Mode::Follow, -1, 1);
  const RunTrace trace = recorder.finish();
  ASSERT_EQ(trace.pushes.size(), 1U);
  EXPECT_EQ(trace.pushes[0].outcome, PushOutcome::Completed);
  LossBuckets expected;
  // The push: 3 m driven for 8 - |(6, -1)| nearer the goal. The step back down onto the path is 1 m
  // driven for no progress along it, and 6 - |(6, -1)| nearer the goal than that progress.
  expected.push_overhead_m = 3.0 + std::hypot(6.0, 1.0) - 8.0;
  expected.execution_m = 1.0;
  expected.route_choice_m = 6.0 - std::hypot(6.0, 1.0);
  expectBuckets(accountLosses(trace, straightToGoal), expected);
}

TEST(LossAccounting, TheBucketsOfARandomWalkAddUpToItsExcess)
{
  RunTraceRecorder recorder;
  std::mt19937 random(5);
  std::uniform_real_distribution<double> step(-0.02, 0.03);
  Point at(0.0, 0.0);
  recorder.position(at);
  for (int index = 0; index < 20000; ++index) {
    if (index % 500 == 0) {
      plan(recorder, {at, Point(at.x() + 1.0, at.y() + (index % 1000 == 0 ? 3.0 : -3.0)), kGoal}, at);
    }
    const executive::Mode mode = (index / 700) % 3 == 1 ? executive::Mode::Push : executive::Mode::Follow;
    recorder.executiveCycle(ExecutiveCycle{mode, 4, index / 2100, index % 1500 == 3});
    at += Point(step(random), step(random));
    recorder.position(at);
  }
  const LossAccount account = accountLosses(recorder.finish(), straightToGoal);
  ASSERT_TRUE(account.valid) << account.problem;
  EXPECT_NEAR(account.buckets.total(), account.excess_m, 1e-6);
  EXPECT_NEAR(account.excess_m, account.travelled_m - (account.achievable_m - account.remaining_m), 1e-9);
}

TEST(LossAccounting, NoWayFromTheStartIsNotAccounted)
{
  RunTraceRecorder recorder;
  recorder.position(Point(0.0, 0.0));
  const LossAccount account =
      accountLosses(recorder.finish(), [](const Point&) { return std::numeric_limits<double>::infinity(); });
  EXPECT_FALSE(account.valid);
  EXPECT_EQ(account.problem, "no achievable way leads from the start to the goal");
  EXPECT_FALSE(accountLosses(RunTrace{}, straightToGoal).valid);
}

TEST(PathArc, NearestWithinAStretchAndTheRemainder)
{
  const PathArc path({Point(0.0, 0.0), Point(4.0, 0.0), Point(4.0, 4.0), Point(0.0, 4.0)});
  EXPECT_DOUBLE_EQ(path.length(), 12.0);
  // Beside the third leg, nearer it than the first; limited to the first leg's stretch, on the first.
  const PathArc::Foot anywhere = path.nearest(Point(1.0, 3.0));
  EXPECT_DOUBLE_EQ(anywhere.arc, 11.0);
  EXPECT_DOUBLE_EQ(anywhere.distance, 1.0);
  const PathArc::Foot early = path.nearest(Point(1.0, 3.0), 0.0, 3.0);
  EXPECT_DOUBLE_EQ(early.arc, 1.0);
  EXPECT_DOUBLE_EQ(early.distance, 3.0);
  const PathArc::Foot window = path.nearest(Point(5.0, 1.0), 6.0, 7.0);
  EXPECT_DOUBLE_EQ(window.arc, 6.0);
  EXPECT_EQ(window.point, Point(4.0, 2.0));
  const std::vector<Point> remainder = path.remainderFrom(Point(5.0, 2.0));
  EXPECT_EQ(remainder,
            (std::vector<Point>{Point(5.0, 2.0), Point(4.0, 2.0), Point(4.0, 4.0), Point(0.0, 4.0)}));
}

}  // namespace
}  // namespace ifar::runner
