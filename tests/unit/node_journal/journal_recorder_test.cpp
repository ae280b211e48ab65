// The journal's batches: events in order with their codes, times and hashes, numbered across batches,
// the channel list kept from batch to batch; the hash is FNV-1a as published test vectors give it.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "bus/node_journal/input_hash.hpp"
#include "bus/node_journal/journal_recorder.hpp"

namespace {

using ifar::node_journal_t;

std::vector<std::uint8_t> bytesOf(const std::string& text)
{
  return {text.begin(), text.end()};
}

std::int32_t asSigned(std::uint32_t value)
{
  return static_cast<std::int32_t>(value);
}

TEST(InputHash, IsFnv1aOf32Bits)
{
  const std::vector<std::uint8_t> empty;
  EXPECT_EQ(ifar::node_journal::inputHash(empty), asSigned(0x811c9dc5U));
  const std::vector<std::uint8_t> a = bytesOf("a");
  const std::vector<std::uint8_t> foobar = bytesOf("foobar");
  EXPECT_EQ(ifar::node_journal::inputHash(a), asSigned(0xe40c292cU));
  EXPECT_EQ(ifar::node_journal::inputHash(foobar), asSigned(0xbf9cf968U));
}

TEST(JournalRecorder, BatchesHoldTheEventsInOrderNumberedFromTheStart)
{
  ifar::node_journal::JournalRecorder recorder("planner", 1'000'000, 77);
  EXPECT_FALSE(recorder.takeBatch(1'000'001).has_value()) << "no events, no batch";

  const std::vector<std::uint8_t> pose = bytesOf("pose bytes");
  const std::vector<std::uint8_t> packet = bytesOf("packet bytes");
  recorder.input("POSE", pose, 1'000'100);
  recorder.input("VELODYNE_PACKET", packet, 1'000'200);
  recorder.input("POSE", packet, 1'000'300);
  recorder.timer(1, 1'000'400);
  recorder.jobFinished(1'000'350);
  const auto first = recorder.takeBatch(1'250'000);
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(first->utime, 1'250'000);
  EXPECT_EQ(first->node, "planner");
  EXPECT_EQ(first->start_utime, 1'000'000);
  EXPECT_EQ(first->pid, 77);
  EXPECT_EQ(first->first_event, 0);
  EXPECT_EQ(first->channels, (std::vector<std::string>{"POSE", "VELODYNE_PACKET"}));
  EXPECT_EQ(first->num_channels, 2);
  EXPECT_EQ(first->num_events, 5);
  EXPECT_EQ(first->kinds, (std::vector<std::int8_t>{node_journal_t::KIND_INPUT, node_journal_t::KIND_INPUT,
                                                    node_journal_t::KIND_INPUT, node_journal_t::KIND_TIMER,
                                                    node_journal_t::KIND_JOB_FINISHED}));
  EXPECT_EQ(first->codes, (std::vector<std::int16_t>{0, 1, 0, 1, 0}));
  EXPECT_EQ(first->utimes,
            (std::vector<std::int64_t>{1'000'100, 1'000'200, 1'000'300, 1'000'400, 1'000'350}));
  EXPECT_EQ(first->hashes[0], ifar::node_journal::inputHash(pose));
  EXPECT_EQ(first->hashes[1], ifar::node_journal::inputHash(packet));
  EXPECT_EQ(first->hashes[2], ifar::node_journal::inputHash(packet));
  EXPECT_EQ(first->hashes[3], 0);
  EXPECT_EQ(recorder.events(), 5);

  recorder.stop(1'300'000);
  recorder.input("GOAL", pose, 1'300'100);
  const auto second = recorder.takeBatch(1'500'000);
  ASSERT_TRUE(second.has_value());
  EXPECT_EQ(second->first_event, 5);
  EXPECT_EQ(second->channels, (std::vector<std::string>{"POSE", "VELODYNE_PACKET", "GOAL"}));
  EXPECT_EQ(second->kinds, (std::vector<std::int8_t>{node_journal_t::KIND_STOP, node_journal_t::KIND_INPUT}));
  EXPECT_EQ(second->codes, (std::vector<std::int16_t>{0, 2}));
  EXPECT_FALSE(recorder.takeBatch(1'750'000).has_value());
}

}  // namespace

TEST(JournalRecorder, TheFirstBatchAloneCarriesTheSettings)
{
  ifar::node_journal::JournalRecorder recorder("executive", 5'000'000, 12);
  recorder.setSettings("log_level: \"\"\nrate_hz: 20\n");
  EXPECT_FALSE(recorder.takeBatch(5'000'001).has_value()) << "settings alone make no batch";
  recorder.timer(0, 5'050'000);
  const auto first = recorder.takeBatch(5'250'000);
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(first->first_event, 0);
  EXPECT_EQ(first->settings, "log_level: \"\"\nrate_hz: 20\n");
  recorder.timer(0, 5'300'000);
  const auto second = recorder.takeBatch(5'500'000);
  ASSERT_TRUE(second.has_value());
  EXPECT_EQ(second->first_event, 1);
  EXPECT_EQ(second->settings, "");
}
