#include "bus/duplicate_process_watch.hpp"

#include <gtest/gtest.h>

namespace ifar::bus {
namespace {

TEST(DuplicateProcessWatch, ItsOwnBeatsAndOtherNamesAreNotDuplicates)
{
  DuplicateProcessWatch watch("planner", 100);
  EXPECT_FALSE(watch.onBeat("planner", 100, 0).has_value());
  EXPECT_FALSE(watch.onBeat("executive", 200, 0).has_value());
  EXPECT_EQ(watch.problem(0), "");
}

TEST(DuplicateProcessWatch, AnotherProcessOfTheNameIsAlarmedOnceAndReportedWhilePresent)
{
  DuplicateProcessWatch watch("planner", 100, 3'000'000);
  const auto alarm = watch.onBeat("planner", 200, 1'000'000);
  ASSERT_TRUE(alarm.has_value());
  EXPECT_EQ(*alarm,
            "another planner (pid 200) beats on this LCM URL beside this one (pid 100): two stacks or a "
            "replayed log share the bus; give each stack its own LCM URL");
  EXPECT_FALSE(watch.onBeat("planner", 200, 2'000'000).has_value());
  EXPECT_EQ(watch.problem(2'500'000), "another planner on this LCM URL (pid 200)");
  EXPECT_TRUE(watch.onBeat("planner", 300, 2'600'000).has_value());
  EXPECT_EQ(watch.problem(2'700'000), "another planner on this LCM URL (pid 200, 300)");
  // Gone quiet for longer than the window: no longer present, and alarmed again if it returns.
  EXPECT_EQ(watch.problem(5'700'000), "");
  EXPECT_TRUE(watch.onBeat("planner", 200, 9'000'000).has_value());
}

}  // namespace
}  // namespace ifar::bus
