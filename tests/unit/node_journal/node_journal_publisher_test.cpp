// The journal on a run loop (memq://, manual clock): the node's inputs journaled with the receive time
// and hash of their bytes after the before-input step, other subscriptions not; batches on the timer
// and the rest when the publisher goes.

#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include <spdlog/sinks/null_sink.h>

#include "bus/node_journal/input_hash.hpp"
#include "bus/node_journal_publisher.hpp"
#include "ifar/goal_t.hpp"
#include "ifar/heartbeat_t.hpp"
#include "ifar/node_journal_t.hpp"

namespace {

std::shared_ptr<spdlog::logger> quietLogger()
{
  return std::make_shared<spdlog::logger>("journal_test", std::make_shared<spdlog::sinks::null_sink_mt>());
}

std::vector<std::uint8_t> encoded(const ifar::goal_t& goal)
{
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(goal.getEncodedSize()));
  goal.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

TEST(NodeJournalPublisher, JournalsTheNodesInputsAfterTheBeforeInputStepAndPublishesTheRestWhenItGoes)
{
  std::int64_t now = 5'000'000;
  ifar::bus::RunLoop loop("memq://", quietLogger(), [&now] { return now; });
  std::vector<ifar::node_journal_t> batches;
  loop.subscribe<ifar::node_journal_t>(
      "TEST_JOURNAL", [&](const ifar::node_journal_t& batch, std::int64_t) { batches.push_back(batch); });
  std::vector<std::string> order;
  loop.subscribe<ifar::goal_t>("GOAL", [&](const ifar::goal_t&, std::int64_t) { order.push_back("goal"); });
  loop.subscribe<ifar::heartbeat_t>("HEARTBEAT",
                                    [&](const ifar::heartbeat_t&, std::int64_t) { order.push_back("beat"); });

  ifar::goal_t goal{};
  goal.goal_id = 3;
  goal.x = 8.0;
  goal.y = 26.0;
  {
    ifar::bus::NodeJournalPublisher journal(loop, "TEST_JOURNAL", "planner", 4'000'000, {"GOAL"},
                                            [&order] { order.push_back("before"); });
    loop.publish("GOAL", goal);
    loop.publish("HEARTBEAT", ifar::heartbeat_t{});
    loop.deliverPending();
    EXPECT_EQ(order, (std::vector<std::string>{"before", "goal", "beat"}));
    now += 300'000;  // past the batch period
    loop.runDueTimers();
    loop.deliverPending();
    ASSERT_EQ(batches.size(), 1U);
    const ifar::node_journal_t& batch = batches.front();
    EXPECT_EQ(batch.node, "planner");
    EXPECT_EQ(batch.start_utime, 4'000'000);
    EXPECT_EQ(batch.first_event, 0);
    EXPECT_EQ(batch.channels, (std::vector<std::string>{"GOAL"}));
    ASSERT_EQ(batch.num_events, 1);
    EXPECT_EQ(batch.kinds[0], ifar::node_journal_t::KIND_INPUT);
    EXPECT_EQ(batch.utimes[0], 5'000'000);
    const std::vector<std::uint8_t> goal_bytes = encoded(goal);
    EXPECT_EQ(batch.hashes[0], ifar::node_journal::inputHash(goal_bytes));

    journal.recorder().timer(0, now);
  }
  loop.deliverPending();
  ASSERT_EQ(batches.size(), 2U) << "the last events leave with the publisher";
  EXPECT_EQ(batches.back().first_event, 1);
  EXPECT_EQ(batches.back().kinds, (std::vector<std::int8_t>{ifar::node_journal_t::KIND_TIMER}));

  loop.publish("GOAL", goal);
  loop.deliverPending();
  EXPECT_EQ(order.back(), "goal") << "inputs still reach their handlers after the journal has gone";
}

}  // namespace
