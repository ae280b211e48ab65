// The planner daemon's worker stays busy from a job's hand-over until the loop has taken its outputs, on
// its own thread as in line: whether the next job may go depends on the loop's steps only, which is what
// the planner's journal replays (ifar replay-test on a log of the daemons).

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "planner/daemon/planner_worker.hpp"

namespace ifar::planner {
namespace {

constexpr std::int64_t kStamp = 42'000'000;

PlannerJob goalJob()
{
  PlannerJob job;
  Goal goal;
  goal.id = 7;
  goal.position = geometry::Point(3.0, 4.0);
  job.new_goal = goal;
  return job;
}

TEST(PlannerWorker, InLineABusyWorkerIsFreeOnlyOnceItsOutputsAreTaken)
{
  PlannerWorker worker(
      Planner(PlannerSettings{}), [] { return kStamp; }, WorkerThreading::InLine);
  EXPECT_FALSE(worker.busy());
  worker.submit(goalJob());
  EXPECT_TRUE(worker.busy()) << "the job has run, but its outputs are not taken yet";
  const std::vector<PlannerOutputs> finished = worker.takeFinished();
  ASSERT_EQ(finished.size(), 1U);
  EXPECT_EQ(finished.front().path.utime, kStamp);
  EXPECT_FALSE(worker.busy());
}

TEST(PlannerWorker, OnItsOwnThreadAFinishedJobKeepsItBusyUntilTaken)
{
  PlannerWorker worker(
      Planner(PlannerSettings{}), [] { return kStamp; }, WorkerThreading::OwnThread);
  worker.submit(goalJob());
  std::vector<PlannerOutputs> finished;
  for (int wait = 0; wait < 500 && finished.empty(); ++wait) {
    EXPECT_TRUE(worker.busy());
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    if (wait % 10 == 9) {
      finished = worker.takeFinished();
    }
  }
  ASSERT_EQ(finished.size(), 1U) << "the job did not finish in 5 s";
  EXPECT_FALSE(worker.busy());
}

}  // namespace
}  // namespace ifar::planner
