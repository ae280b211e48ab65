#include "bench/scenarios/forked_items.hpp"

#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>

#include <gtest/gtest.h>

namespace ifar::scenarios {
namespace {

constexpr std::chrono::milliseconds kDeadline{std::chrono::seconds(20)};

/// Runs `count` items with `answer`, one child for all unless `per_child` says otherwise.
std::map<std::size_t, ForkedOutcome> runAll(std::size_t count,
                                            const std::function<std::string(std::size_t)>& answer,
                                            std::size_t per_child, int parallel = 1,
                                            std::chrono::milliseconds deadline = kDeadline)
{
  std::map<std::size_t, ForkedOutcome> outcomes;
  ForkedItems items;
  items.count = count;
  items.parallel = parallel;
  items.items_per_child = per_child;
  items.answer = answer;
  items.deadline = [deadline](std::size_t) { return deadline; };
  items.finished = [&](std::size_t index, const ForkedOutcome& outcome) {
    EXPECT_EQ(outcomes.count(index), 0u) << "item " << index << " finished twice";
    outcomes[index] = outcome;
  };
  runForked(items);
  EXPECT_EQ(outcomes.size(), count);
  return outcomes;
}

std::string processAndItem(std::size_t index)
{
  return std::to_string(::getpid()) + "/" + std::to_string(index);
}

std::string processOf(const ForkedOutcome& outcome)
{
  return outcome.answer.substr(0, outcome.answer.find('/'));
}

TEST(ForkedItems, EveryAnswerComesBackExactlyFromOneChild)
{
  const std::string awkward("sizes 12\n: and a zero byte \0 inside", 34);
  const auto outcomes = runAll(
      4, [&](std::size_t index) { return index == 2 ? awkward : processAndItem(index); }, 4);
  for (const auto& [index, outcome] : outcomes) {
    ASSERT_TRUE(outcome.answered) << index << ": " << outcome.reason;
  }
  EXPECT_EQ(outcomes.at(2).answer, awkward);
  EXPECT_EQ(outcomes.at(0).answer.substr(outcomes.at(0).answer.find('/')), "/0");
  EXPECT_EQ(processOf(outcomes.at(0)), processOf(outcomes.at(3)));  // one child answered the run
  EXPECT_NE(processOf(outcomes.at(0)), std::to_string(::getpid()));
}

TEST(ForkedItems, ACrashCostsItsOwnItemAndANewChildGoesOn)
{
  const auto outcomes = runAll(
      5,
      [](std::size_t index) {
        if (index == 2) {
          std::abort();
        }
        if (index == 3) {
          // The default action, as in a process without handlers: a sanitizer's handler would turn the
          // segmentation fault into an abort.
          std::signal(SIGSEGV, SIG_DFL);
          std::raise(SIGSEGV);
        }
        return processAndItem(index);
      },
      5);
  EXPECT_TRUE(outcomes.at(0).answered);
  EXPECT_TRUE(outcomes.at(1).answered);
  EXPECT_FALSE(outcomes.at(2).answered);
  EXPECT_EQ(outcomes.at(2).status, "error");
  EXPECT_EQ(outcomes.at(2).reason.rfind("crashed: signal 6 (", 0), 0u) << outcomes.at(2).reason;
  EXPECT_EQ(outcomes.at(3).status, "error");
  EXPECT_EQ(outcomes.at(3).reason.rfind("crashed: signal 11 (", 0), 0u) << outcomes.at(3).reason;
  ASSERT_TRUE(outcomes.at(4).answered);
  EXPECT_EQ(processOf(outcomes.at(0)), processOf(outcomes.at(1)));
  EXPECT_NE(processOf(outcomes.at(1)), processOf(outcomes.at(4)));
}

TEST(ForkedItems, AHungItemIsKilledAtItsDeadlineAsATimeout)
{
  const auto began = std::chrono::steady_clock::now();
  const auto outcomes = runAll(
      3,
      [](std::size_t index) {
        if (index == 1) {
          for (;;) {
            std::this_thread::sleep_for(std::chrono::seconds(1));
          }
        }
        return processAndItem(index);
      },
      3, 1, std::chrono::milliseconds(300));
  const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  EXPECT_TRUE(outcomes.at(0).answered);
  EXPECT_FALSE(outcomes.at(1).answered);
  EXPECT_EQ(outcomes.at(1).status, "timeout");
  EXPECT_EQ(outcomes.at(1).reason, "killed after 0.3 s of wall time without an answer");
  EXPECT_TRUE(outcomes.at(2).answered);
  EXPECT_GE(waited, 0.3);
}

TEST(ForkedItems, AnItemThatThrowsOrExitsIsAnError)
{
  const auto outcomes = runAll(
      2,
      [](std::size_t index) -> std::string {
        if (index == 0) {
          throw std::runtime_error("no memory for the tree");
        }
        std::_Exit(7);
      },
      2);
  EXPECT_EQ(outcomes.at(0).status, "error");
  EXPECT_EQ(outcomes.at(0).reason, "its child process exited with status 4 without an answer");
  EXPECT_EQ(outcomes.at(1).reason, "its child process exited with status 7 without an answer");
}

TEST(ForkedItems, ParallelChildrenAnswerOneItemEach)
{
  const auto outcomes = runAll(6, processAndItem, 1, 3);
  std::set<std::string> processes;
  for (const auto& [index, outcome] : outcomes) {
    ASSERT_TRUE(outcome.answered) << index;
    EXPECT_EQ(outcome.answer.substr(outcome.answer.find('/') + 1), std::to_string(index));
    processes.insert(processOf(outcome));
  }
  EXPECT_EQ(processes.size(), 6u);
}

TEST(ForkedItems, SkippedItemsAreNeverStarted)
{
  std::map<std::size_t, ForkedOutcome> outcomes;
  ForkedItems items;
  items.count = 4;
  items.answer = processAndItem;
  items.deadline = [](std::size_t) { return kDeadline; };
  items.skip = [](std::size_t index) { return index >= 2; };
  items.finished = [&](std::size_t index, const ForkedOutcome& outcome) { outcomes[index] = outcome; };
  runForked(items);
  ASSERT_EQ(outcomes.size(), 4u);
  EXPECT_TRUE(outcomes.at(1).answered);
  EXPECT_FALSE(outcomes.at(2).answered);
  EXPECT_EQ(outcomes.at(2).status, "skipped");
  EXPECT_EQ(outcomes.at(3).status, "skipped");
}

}  // namespace
}  // namespace ifar::scenarios
