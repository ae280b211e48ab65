// A log of the daemons fed by its journal: inputs in the journal's order with the journal's times, found
// among the logged ones by hash (also when logged after their batch), the ones the node never took counted;
// a lost batch, a restarted node or an input the log lacks end the comparable part at the last whole batch.

#include "tools/replay_test/journal_feed.hpp"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bus/node_journal/journal_recorder.hpp"

namespace ifar::replay_test {
namespace {

constexpr std::int64_t kStart = 1'000'000;
constexpr std::int32_t kPid = 4321;

std::vector<std::uint8_t> bytesOf(const std::string& text)
{
  return {text.begin(), text.end()};
}

void record(node_journal::JournalRecorder& recorder, const std::string& channel, const std::string& text,
            std::int64_t utime)
{
  const std::vector<std::uint8_t> bytes = bytesOf(text);
  recorder.input(channel, bytes, utime);
}

lcm_log::LogEvent logged(std::int64_t utime, const std::string& channel, std::vector<std::uint8_t> data)
{
  lcm_log::LogEvent event;
  event.timestamp_us = utime;
  event.channel = channel;
  event.data = std::move(data);
  return event;
}

lcm_log::LogEvent loggedBatch(std::int64_t utime, const node_journal_t& batch)
{
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(batch.getEncodedSize()));
  batch.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return logged(utime, "JOURNAL", std::move(bytes));
}

/// What the hooks were called with, one line each.
struct Calls {
  std::vector<std::string> lines;
  JournalHooks hooks()
  {
    return {[this](const std::string& channel, common::ByteView bytes, std::int64_t utime) {
              lines.push_back(channel + " " + std::string(bytes.begin(), bytes.end()) + " @" +
                              std::to_string(utime));
            },
            [this](std::int8_t kind, std::int16_t code, std::int64_t utime) {
              lines.push_back("event " + std::to_string(kind) + "." + std::to_string(code) + " @" +
                              std::to_string(utime));
            }};
  }
};

TEST(JournalFeed, InputsGoInTheJournalsOrderWithItsTimesFoundByTheirBytes)
{
  node_journal::JournalRecorder recorder("planner", kStart, kPid);
  record(recorder, "GOAL", "g1", 1'100);
  recorder.timer(0, 1'150);
  record(recorder, "POSE", "p1", 1'200);
  const node_journal_t batch = *recorder.takeBatch(1'300);
  Calls calls;
  JournalFeed feed("JOURNAL", batch, {"GOAL", "POSE"}, calls.hooks());
  feed.add(logged(1'000, "POSE", bytesOf("p0")));  // logged, but before the node took anything
  feed.add(logged(1'001, "POSE", bytesOf("p1")));
  feed.add(logged(1'002, "GOAL", bytesOf("g1")));
  feed.add(logged(1'003, "GLOBAL_PATH", bytesOf("x")));
  EXPECT_TRUE(calls.lines.empty()) << "nothing before the journal says so";
  feed.add(loggedBatch(1'301, batch));
  feed.finish();
  EXPECT_EQ(calls.lines, (std::vector<std::string>{"GOAL g1 @1100", "event 2.0 @1150", "POSE p1 @1200"}));
  EXPECT_EQ(feed.inputsDelivered(), 2);
  EXPECT_EQ(feed.inputsNotTaken(), 1);
  EXPECT_EQ(feed.completeBatches(), 1);
  EXPECT_EQ(feed.completeUntilUtime(), 1'301);
  EXPECT_TRUE(feed.endReason().empty()) << feed.endReason();
}

TEST(JournalFeed, AnInputLoggedAfterItsBatchIsWaitedFor)
{
  node_journal::JournalRecorder recorder("executive", kStart, kPid);
  record(recorder, "POSE", "p1", 2'000);
  recorder.timer(0, 2'010);
  const node_journal_t batch = *recorder.takeBatch(2'100);
  Calls calls;
  JournalFeed feed("JOURNAL", batch, {"POSE"}, calls.hooks());
  feed.add(loggedBatch(2'101, batch));
  EXPECT_TRUE(calls.lines.empty());
  EXPECT_EQ(feed.batchesLogged(), 1);
  EXPECT_EQ(feed.completeBatches(), 0);
  feed.add(logged(2'102, "POSE", bytesOf("p1")));
  EXPECT_EQ(calls.lines, (std::vector<std::string>{"POSE p1 @2000", "event 2.0 @2010"}));
  EXPECT_EQ(feed.completeBatches(), 1);
}

TEST(JournalFeed, ALostBatchEndsTheReplayAtTheLastWholeOne)
{
  node_journal::JournalRecorder recorder("planner", kStart, kPid);
  recorder.timer(0, 10);
  const node_journal_t first = *recorder.takeBatch(20);
  recorder.timer(0, 30);
  (void)recorder.takeBatch(40);  // never logged
  recorder.timer(0, 50);
  const node_journal_t third = *recorder.takeBatch(60);
  Calls calls;
  JournalFeed feed("JOURNAL", first, {"POSE"}, calls.hooks());
  feed.add(loggedBatch(21, first));
  feed.add(loggedBatch(61, third));
  feed.finish();
  EXPECT_EQ(calls.lines, (std::vector<std::string>{"event 2.0 @10"}));
  EXPECT_EQ(feed.completeBatches(), 1);
  EXPECT_NE(feed.endReason().find("journal events 1 to 1 are not in the log"), std::string::npos)
      << feed.endReason();
}

TEST(JournalFeed, ARestartedNodeEndsTheReplay)
{
  node_journal::JournalRecorder recorder("planner", kStart, kPid);
  recorder.timer(0, 10);
  const node_journal_t first = *recorder.takeBatch(20);
  node_journal::JournalRecorder restarted("planner", kStart + 5'000'000, kPid + 1);
  restarted.timer(0, kStart + 5'100'000);
  Calls calls;
  JournalFeed feed("JOURNAL", first, {"POSE"}, calls.hooks());
  feed.add(loggedBatch(21, first));
  feed.add(loggedBatch(kStart + 5'200'000, *restarted.takeBatch(kStart + 5'200'000)));
  feed.finish();
  EXPECT_EQ(calls.lines.size(), 1U);
  EXPECT_EQ(feed.completeBatches(), 1);
  EXPECT_NE(feed.endReason().find("the node restarted"), std::string::npos) << feed.endReason();
  EXPECT_NE(feed.endReason().find("pid 4322"), std::string::npos) << feed.endReason();
}

TEST(JournalFeed, AnInputTheLogLacksEndsTheReplayBeforeItsBatch)
{
  node_journal::JournalRecorder recorder("planner", kStart, kPid);
  record(recorder, "POSE", "p1", kStart + 100);
  const node_journal_t first = *recorder.takeBatch(kStart + 200);
  record(recorder, "POSE", "p2", kStart + 300);  // the logger missed it
  recorder.timer(1, kStart + 310);
  const node_journal_t second = *recorder.takeBatch(kStart + 400);
  Calls calls;
  JournalFeed feed("JOURNAL", first, {"POSE"}, calls.hooks());
  feed.add(logged(kStart + 101, "POSE", bytesOf("p1")));
  feed.add(loggedBatch(kStart + 201, first));
  feed.add(loggedBatch(kStart + 401, second));
  EXPECT_EQ(feed.batch(), 1) << "waiting in the second batch";
  feed.finish();
  EXPECT_EQ(calls.lines, (std::vector<std::string>{"POSE p1 @1000100"}));
  EXPECT_EQ(feed.completeBatches(), 1);
  EXPECT_EQ(feed.endReason(),
            "the node took a POSE message (its time 0.000300 s after its start) that is not "
            "in the log");
}

TEST(JournalFeed, AJournalNamingAnotherNodesChannelEndsTheReplay)
{
  node_journal::JournalRecorder recorder("planner", kStart, kPid);
  record(recorder, "FORCE", "f", 10);
  const node_journal_t batch = *recorder.takeBatch(20);
  Calls calls;
  JournalFeed feed("JOURNAL", batch, {"POSE"}, calls.hooks());
  feed.add(loggedBatch(21, batch));
  feed.finish();
  EXPECT_TRUE(calls.lines.empty());
  EXPECT_EQ(feed.completeBatches(), 0);
  EXPECT_NE(feed.endReason().find("input channel FORCE, not one of this node's"), std::string::npos)
      << feed.endReason();
}

}  // namespace
}  // namespace ifar::replay_test
