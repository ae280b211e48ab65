// The log reader and liblcm agree on the format: what lcm::LogFile (the writer behind lcm-logger) writes
// is read back exactly, and the hand-written bytes the reader's tests use are what liblcm reads.

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include "common/lcm_log/log_reader.hpp"
#include "testing/temporary_directory.hpp"
#include "tests/unit/lcm_log/log_bytes.hpp"

namespace ifar::lcm_log {
namespace {

struct Written {
  std::int64_t timestamp_us;
  std::string channel;
  std::vector<std::uint8_t> data;
};

std::vector<Written> examples()
{
  std::mt19937 generator(7);
  std::uniform_int_distribution<int> byte(0, 255);
  std::vector<std::uint8_t> large(100'000);
  for (auto& value : large) {
    value = static_cast<std::uint8_t>(byte(generator));
  }
  return {
      {1'700'000'000'000'000, "POSE", {1, 2, 3}},
      {1'700'000'000'000'001, "EMPTY", {}},
      {1'700'000'000'000'002, "X", {0xED, 0xA1, 0xDA, 0x01, 0xED, 0xA1, 0xDA, 0x01}},  // sync words as data
      {1'700'000'000'000'003, std::string(63, 'C'), {0}},  // the longest channel LCM publishes
      {-5, "VELODYNE_PACKET", large},                      // a timestamp is whatever the logger wrote
  };
}

TEST(LcmLogFormat, WhatLiblcmWritesIsReadBackExactly)
{
  test_support::TemporaryDirectory directory("lcm-log-format");
  const std::string path = (directory.path() / "written-by-lcm.lcmlog").string();
  const std::vector<Written> written = examples();
  {
    lcm::LogFile log(path, "w");
    ASSERT_TRUE(log.good());
    for (const Written& example : written) {
      lcm::LogEvent event{};
      event.timestamp = example.timestamp_us;
      event.channel = example.channel;
      event.datalen = static_cast<std::int32_t>(example.data.size());
      std::vector<std::uint8_t> data = example.data;  // LCM's API takes a non-const pointer
      event.data = data.data();
      ASSERT_EQ(log.writeEvent(&event), 0);
    }
  }

  LogReader reader = LogReader::open(path);
  ASSERT_EQ(reader.openError(), "");
  LogEvent event;
  for (std::size_t index = 0; index < written.size(); ++index) {
    ASSERT_TRUE(reader.next(event)) << "event " << index;
    EXPECT_EQ(event.event_number, static_cast<std::int64_t>(index));  // liblcm numbers the events from 0
    EXPECT_EQ(event.timestamp_us, written[index].timestamp_us);
    EXPECT_EQ(event.channel, written[index].channel);
    EXPECT_EQ(event.data, written[index].data) << "event " << index;
  }
  EXPECT_FALSE(reader.next(event));
  EXPECT_TRUE(reader.clean()) << reader.problemSummary();
  EXPECT_EQ(reader.skippedBytes(), 0U);
}

TEST(LcmLogFormat, TheTestsHandWrittenLogsAreWhatLiblcmReads)
{
  test_support::TemporaryDirectory directory("lcm-log-format");
  const std::string path = (directory.path() / "written-by-hand.lcmlog").string();
  const std::vector<Written> written = examples();
  test::Bytes bytes;
  for (std::size_t index = 0; index < written.size(); ++index) {
    test::append(bytes, test::eventBytes(static_cast<std::int64_t>(index), written[index].timestamp_us,
                                         written[index].channel, written[index].data));
  }
  ASSERT_TRUE(test::writeFile(path, bytes));

  lcm::LogFile log(path, "r");
  ASSERT_TRUE(log.good());
  for (std::size_t index = 0; index < written.size(); ++index) {
    const lcm::LogEvent* event = log.readNextEvent();
    ASSERT_NE(event, nullptr) << "event " << index;
    EXPECT_EQ(event->eventnum, static_cast<std::int64_t>(index));
    EXPECT_EQ(event->timestamp, written[index].timestamp_us);
    EXPECT_EQ(event->channel, written[index].channel);
    const auto* data = static_cast<const std::uint8_t*>(event->data);
    EXPECT_EQ(std::vector<std::uint8_t>(data, data + event->datalen), written[index].data)
        << "event " << index;
  }
  EXPECT_EQ(log.readNextEvent(), nullptr);
}

}  // namespace
}  // namespace ifar::lcm_log
