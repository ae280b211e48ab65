// The strict reading the replay and echo tools use: whole logs come through event by event; reading stops at
// the first problem; an event whose length does not end where an event starts is held back and named.

#include "common/lcm_log/strict_event_reader.hpp"

#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/unit/lcm_log/log_bytes.hpp"

namespace ifar::lcm_log {
namespace {

using test::append;
using test::Bytes;
using test::eventBytes;
using test::eventHeader;

LogReader readerOf(const Bytes& bytes)
{
  return LogReader(std::make_unique<std::istringstream>(std::string(bytes.begin(), bytes.end())));
}

std::vector<std::string> channelsRead(StrictEventReader& events)
{
  std::vector<std::string> channels;
  LogEvent event;
  while (events.next(event)) {
    channels.push_back(event.channel);
  }
  return channels;
}

/// Three events of 28 + 1 + 4 = 33 bytes each, on channels A, B, C.
Bytes threeEvents()
{
  Bytes bytes;
  append(bytes, eventBytes(0, 100, "A", {1, 2, 3, 4}));
  append(bytes, eventBytes(1, 200, "B", {5, 6, 7, 8}));
  append(bytes, eventBytes(2, 300, "C", {9, 10, 11, 12}));
  return bytes;
}

TEST(StrictEventReader, AWholeLogComesThroughEventByEventWithTheirBytes)
{
  LogReader reader = readerOf(threeEvents());
  StrictEventReader events(reader);
  LogEvent event;
  ASSERT_TRUE(events.next(event));
  EXPECT_EQ(event.channel, "A");
  EXPECT_EQ(event.timestamp_us, 100);
  EXPECT_EQ(event.data, (Bytes{1, 2, 3, 4}));
  ASSERT_TRUE(events.next(event));
  EXPECT_EQ(event.channel, "B");
  EXPECT_EQ(event.data, (Bytes{5, 6, 7, 8}));
  ASSERT_TRUE(events.next(event));
  EXPECT_EQ(event.channel, "C");
  EXPECT_EQ(event.event_number, 2);
  EXPECT_EQ(event.data, (Bytes{9, 10, 11, 12}));
  EXPECT_FALSE(events.next(event));
  EXPECT_FALSE(events.next(event));
  EXPECT_EQ(events.problem(), "");
}

TEST(StrictEventReader, AnEmptyLogHasNoEventsAndNoProblem)
{
  LogReader reader = readerOf({});
  StrictEventReader events(reader);
  EXPECT_TRUE(channelsRead(events).empty());
  EXPECT_EQ(events.problem(), "");
}

TEST(StrictEventReader, ALengthMadeLargerHoldsItsEventBackAndNamesBothOffsets)
{
  Bytes bytes = threeEvents();
  bytes[33 + 27] = 7;  // B claims 7 data bytes: it swallows 3 bytes of C's sync word, ED A1 DA
  LogReader reader = readerOf(bytes);
  StrictEventReader events(reader);
  EXPECT_EQ(channelsRead(events), std::vector<std::string>{"A"});
  EXPECT_EQ(events.problem(),
            "byte 69: bad sync word 0x01000000; skipped 30 bytes to the end of the file; the event at byte "
            "33 before "
            "it is left out: its length does not end where an event starts");
}

TEST(StrictEventReader, ALastEventClaimingTwoGigabytesStopsAfterTheEventsBeforeIt)
{
  Bytes bytes = threeEvents();
  Bytes huge = eventHeader(3, 400, 1, 0x7fffffff);
  append(huge, Bytes{'D', 1, 2});
  append(bytes, huge);
  LogReader reader = readerOf(bytes);
  StrictEventReader events(reader);
  EXPECT_EQ(channelsRead(events), (std::vector<std::string>{"A", "B", "C"}));
  EXPECT_EQ(
      events.problem(),
      "byte 99: event truncated: header claims 1 channel and 2147483647 data bytes, only 3 bytes follow the "
      "header; skipped 31 bytes to the end of the file");
}

TEST(StrictEventReader, GarbageBetweenEventsStopsReadingThereThoughValidEventsFollow)
{
  Bytes bytes = eventBytes(0, 100, "A", {1, 2, 3, 4});
  append(bytes, Bytes{0xDE, 0xAD});  // A's length is right; the next header is not where it should be
  append(bytes, eventBytes(1, 200, "B", {5}));
  LogReader reader = readerOf(bytes);
  StrictEventReader events(reader);
  // A's end is followed by bytes that are no sync word: A itself is suspect and held back.
  EXPECT_TRUE(channelsRead(events).empty());
  EXPECT_EQ(events.problem(),
            "byte 33: bad sync word 0xDEADEDA1; skipped 2 bytes to the next sync word at byte 35; the event "
            "at byte 0 "
            "before it is left out: its length does not end where an event starts");
}

TEST(StrictEventReader, ANegativeLengthInTheNextHeaderStillPassesTheEventBeforeIt)
{
  Bytes bytes = eventBytes(0, 100, "A", {1, 2, 3, 4});
  append(bytes, eventHeader(1, 200, 1, -5));
  LogReader reader = readerOf(bytes);
  StrictEventReader events(reader);
  EXPECT_EQ(channelsRead(events), std::vector<std::string>{"A"});
  EXPECT_EQ(events.problem(), "byte 33: negative data length -5; skipped 28 bytes to the end of the file");
}

}  // namespace
}  // namespace ifar::lcm_log
