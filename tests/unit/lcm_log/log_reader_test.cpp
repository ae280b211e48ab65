// The LCM log reader on logs written byte by byte: valid events come back exactly; a header claiming more
// bytes than the file holds is a truncation at its offset and allocates nothing of that size; garbage is
// skipped to the next sync word, counted, and recorded once; no cut or flipped byte loses track of a byte.

#include "common/lcm_log/log_reader.hpp"

#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "testing/allocation_tracker.hpp"
#include "testing/temporary_directory.hpp"
#include "tests/unit/lcm_log/log_bytes.hpp"

namespace ifar::lcm_log {
namespace {

using test::append;
using test::Bytes;
using test::eventBytes;
using test::eventHeader;

class LcmLogReader : public ::testing::Test {
 protected:
  /// Writes `bytes` to a file in the test's own folder and opens it.
  LogReader openBytes(const Bytes& bytes)
  {
    const std::string path = (directory_.path() / "test.lcmlog").string();
    EXPECT_TRUE(test::writeFile(path, bytes));
    return LogReader::open(path);
  }

  test_support::TemporaryDirectory directory_{"lcm-log-reader-test"};
};

LogReader readerOf(const Bytes& bytes)
{
  return LogReader(std::make_unique<std::istringstream>(std::string(bytes.begin(), bytes.end())));
}

std::vector<LogEvent> readAll(LogReader& reader)
{
  std::vector<LogEvent> events;
  LogEvent event;
  while (reader.next(event)) {
    events.push_back(event);
  }
  return events;
}

std::uint64_t eventSize(const LogEvent& event)
{
  return kHeaderSize + event.channel.size() + event.data.size();
}

const Bytes kPoseData = {0x00, 0x01, 0xED, 0xA1, 0xDA, 0x01, 0xFF};  // holds a sync word: data is data

TEST_F(LcmLogReader, ATwoEventLogIsReadBackExactly)
{
  Bytes bytes = eventBytes(0, 1'700'000'000'000'001, "POSE", kPoseData);
  append(bytes, eventBytes(1, 1'700'000'000'250'000, "EXEC_STATUS", {}));
  LogReader reader = openBytes(bytes);
  ASSERT_EQ(reader.openError(), "");
  EXPECT_EQ(reader.fileSize(), 28U + 4 + 7 + 28 + 11);

  EXPECT_EQ(reader.position(), 0U);
  LogEvent event;
  ASSERT_TRUE(reader.next(event));
  EXPECT_EQ(reader.position(), 28U + 4 + 7);
  EXPECT_EQ(event.event_number, 0);
  EXPECT_EQ(event.timestamp_us, 1'700'000'000'000'001);
  EXPECT_EQ(event.channel, "POSE");
  EXPECT_EQ(event.data, kPoseData);
  ASSERT_TRUE(reader.next(event));
  EXPECT_EQ(reader.position(), reader.fileSize());
  EXPECT_EQ(event.event_number, 1);
  EXPECT_EQ(event.timestamp_us, 1'700'000'000'250'000);
  EXPECT_EQ(event.channel, "EXEC_STATUS");
  EXPECT_TRUE(event.data.empty());
  EXPECT_FALSE(reader.next(event));
  EXPECT_FALSE(reader.next(event));  // and stays at the end

  EXPECT_EQ(reader.eventCount(), 2U);
  EXPECT_TRUE(reader.clean());
  EXPECT_EQ(reader.skippedBytes(), 0U);
  EXPECT_EQ(reader.problemSummary(), "");
}

TEST_F(LcmLogReader, AHeaderClaimingTwoGigabytesIsATruncationAtItsOffsetAndIsNotAllocated)
{
  // The audit's 136-byte log: one header claiming 0x7fffffff data bytes crashed liblcm's reader.
  Bytes bytes = eventHeader(0, 1, 4, 0x7fffffff);
  append(bytes, Bytes(136 - bytes.size(), 0x55));
  LogReader reader = openBytes(bytes);
  ASSERT_EQ(reader.openError(), "");

  LogEvent event;
  ifar::test_support::startTrackingAllocations();
  const bool read = reader.next(event);
  const std::size_t largest_allocation = ifar::test_support::stopTrackingAllocations();
  EXPECT_GT(largest_allocation, 0U);  // the tracker works: the reader's scan buffer at least
  EXPECT_LT(largest_allocation, 1024U * 1024U);
  EXPECT_FALSE(read);
  EXPECT_EQ(event.data.capacity(), 0U);

  ASSERT_EQ(reader.problemCount(), 1U);
  ASSERT_EQ(reader.problems().size(), 1U);
  EXPECT_EQ(reader.problems()[0].kind, LogProblemKind::kTruncatedEvent);
  EXPECT_EQ(reader.problems()[0].offset, 0U);
  EXPECT_EQ(
      reader.problems()[0].description,
      "byte 0: event truncated: header claims 4 channel and 2147483647 data bytes, only 108 bytes follow "
      "the header; skipped 136 bytes to the end of the file");
  EXPECT_EQ(reader.skippedBytes(), 136U);
  EXPECT_EQ(reader.eventCount(), 0U);
}

TEST_F(LcmLogReader, EventsClaiming100MegabytesAnd1GigabyteBeyondTheEndAreTruncations)
{
  Bytes bytes = eventBytes(0, 10, "POSE", kPoseData);  // 39 bytes
  append(bytes, eventHeader(1, 20, 4, 100'000'000));
  append(bytes, Bytes{'P', 'O', 'S', 'E', 1, 2, 3});
  append(bytes, eventHeader(2, 30, 4, 1'000'000'000));
  append(bytes, Bytes{'P', 'O', 'S', 'E'});
  LogReader reader = openBytes(bytes);

  ifar::test_support::startTrackingAllocations();
  const std::vector<LogEvent> events = readAll(reader);
  EXPECT_LT(ifar::test_support::stopTrackingAllocations(), 1024U * 1024U);

  ASSERT_EQ(events.size(), 1U);
  EXPECT_EQ(events[0].data, kPoseData);
  ASSERT_EQ(reader.problemCount(), 2U);
  EXPECT_EQ(reader.problems()[0].offset, 39U);
  EXPECT_EQ(
      reader.problems()[0].description,
      "byte 39: event truncated: header claims 4 channel and 100000000 data bytes, only 39 bytes follow "
      "the header; skipped 35 bytes to the next sync word at byte 74");
  EXPECT_EQ(reader.problems()[1].offset, 74U);
  EXPECT_EQ(
      reader.problems()[1].description,
      "byte 74: event truncated: header claims 4 channel and 1000000000 data bytes, only 4 bytes follow "
      "the header; skipped 32 bytes to the end of the file");
  EXPECT_EQ(reader.skippedBytes(), 35U + 32U);
}

TEST_F(LcmLogReader, GarbageBetweenTwoEventsIsSkippedCountedAndRecordedOnce)
{
  Bytes bytes = eventBytes(0, 100, "POSE", kPoseData);  // bytes 0..38
  Bytes garbage(37);
  for (std::size_t index = 0; index < garbage.size(); ++index) {
    garbage[index] = static_cast<std::uint8_t>(0x10 + index);
  }
  append(bytes, garbage);                                      // bytes 39..75
  append(bytes, eventBytes(1, 200, "GOAL", {9, 8, 7, 6, 5}));  // from byte 76
  LogReader reader = openBytes(bytes);

  const std::vector<LogEvent> events = readAll(reader);
  ASSERT_EQ(events.size(), 2U);
  EXPECT_EQ(events[0].event_number, 0);
  EXPECT_EQ(events[0].timestamp_us, 100);
  EXPECT_EQ(events[0].channel, "POSE");
  EXPECT_EQ(events[0].data, kPoseData);
  EXPECT_EQ(events[1].event_number, 1);
  EXPECT_EQ(events[1].timestamp_us, 200);
  EXPECT_EQ(events[1].channel, "GOAL");
  EXPECT_EQ(events[1].data, (Bytes{9, 8, 7, 6, 5}));

  EXPECT_EQ(reader.skippedBytes(), 37U);
  ASSERT_EQ(reader.problemCount(), 1U);
  EXPECT_EQ(reader.problems()[0].kind, LogProblemKind::kBadSyncWord);
  EXPECT_EQ(reader.problems()[0].offset, 39U);
  EXPECT_EQ(reader.problems()[0].description,
            "byte 39: bad sync word 0x10111213; skipped 37 bytes to the next sync word at byte 76");
  EXPECT_EQ(reader.problemSummary(),
            "1 problem, 37 bytes skipped; first: byte 39: bad sync word 0x10111213; skipped 37 bytes to the "
            "next sync word at byte 76");
}

TEST_F(LcmLogReader, ATruncatedLastEventIsReportedWithTheBytesLeft)
{
  Bytes bytes = eventBytes(0, 100, "POSE", kPoseData);    // bytes 0..38
  Bytes last = eventBytes(1, 200, "POSE", Bytes(50, 7));  // 82 bytes, cut to 60: the logger was killed
  last.resize(60);
  append(bytes, last);
  LogReader reader = openBytes(bytes);

  const std::vector<LogEvent> events = readAll(reader);
  ASSERT_EQ(events.size(), 1U);
  EXPECT_EQ(events[0].data, kPoseData);
  ASSERT_EQ(reader.problemCount(), 1U);
  EXPECT_EQ(reader.problems()[0].kind, LogProblemKind::kTruncatedEvent);
  EXPECT_EQ(reader.problems()[0].offset, 39U);
  EXPECT_EQ(reader.problems()[0].description,
            "byte 39: event truncated: header claims 4 channel and 50 data bytes, only 32 bytes follow the "
            "header; skipped 60 bytes to the end of the file");
  EXPECT_EQ(reader.skippedBytes(), 60U);
}

TEST_F(LcmLogReader, AFileEndingInsideAHeaderIsATruncatedHeader)
{
  for (const std::size_t kept : {2U, 10U}) {
    Bytes bytes = eventBytes(0, 100, "POSE", kPoseData);
    Bytes header = eventHeader(1, 200, 4, 3);
    header.resize(kept);
    append(bytes, header);
    LogReader reader = readerOf(bytes);
    EXPECT_EQ(readAll(reader).size(), 1U);
    ASSERT_EQ(reader.problemCount(), 1U) << kept;
    EXPECT_EQ(reader.problems()[0].kind, LogProblemKind::kTruncatedHeader) << kept;
    EXPECT_EQ(reader.problems()[0].offset, 39U);
    EXPECT_EQ(reader.skippedBytes(), kept);
  }
  Bytes bytes = eventHeader(1, 200, 4, 3);
  bytes.resize(10);
  LogReader reader = readerOf(bytes);
  LogEvent event;
  EXPECT_FALSE(reader.next(event));
  ASSERT_EQ(reader.problems().size(), 1U);
  EXPECT_EQ(reader.problems()[0].description,
            "byte 0: event header truncated: 28 bytes needed, only 10 left; skipped");
}

TEST_F(LcmLogReader, AnEmptyFileHoldsNoEventsAndNoProblems)
{
  LogReader reader = openBytes({});
  ASSERT_EQ(reader.openError(), "");
  LogEvent event;
  EXPECT_FALSE(reader.next(event));
  EXPECT_EQ(reader.fileSize(), 0U);
  EXPECT_EQ(reader.eventCount(), 0U);
  EXPECT_TRUE(reader.clean());
}

TEST_F(LcmLogReader, RandomBytesAreOneBadSyncWordCoveringTheWholeFile)
{
  std::mt19937 generator(20240611);
  std::uniform_int_distribution<int> byte(0, 255);
  Bytes bytes(5000);
  for (auto& value : bytes) {
    value = static_cast<std::uint8_t>(byte(generator));
  }
  bytes[0] = 0x12;  // the description below names the first four bytes
  bytes[1] = 0x34;
  bytes[2] = 0x56;
  bytes[3] = 0x78;
  for (std::size_t index = 0; index + 4 <= bytes.size(); ++index) {
    ASSERT_FALSE(bytes[index] == 0xED && bytes[index + 1] == 0xA1 && bytes[index + 2] == 0xDA &&
                 bytes[index + 3] == 0x01)
        << "the seed made a sync word at byte " << index << ": pick another";
  }
  LogReader reader = openBytes(bytes);
  EXPECT_TRUE(readAll(reader).empty());
  ASSERT_EQ(reader.problemCount(), 1U);
  EXPECT_EQ(reader.problems()[0].kind, LogProblemKind::kBadSyncWord);
  EXPECT_EQ(reader.problems()[0].description,
            "byte 0: bad sync word 0x12345678; skipped 5000 bytes to the end of the file");
  EXPECT_EQ(reader.skippedBytes(), 5000U);
}

TEST_F(LcmLogReader, ImpossibleLengthsAreSkippedToTheNextEvent)
{
  Bytes bytes = eventHeader(0, 1, 0, 3);  // no channel: liblcm rejects it too
  append(bytes, eventBytes(1, 2, "A", {1}));
  const std::uint64_t second_bad = bytes.size();
  append(bytes, eventHeader(2, 3, 1000, 0));  // longer than liblcm accepts
  append(bytes, eventBytes(3, 4, "B", {2}));
  const std::uint64_t third_bad = bytes.size();
  append(bytes, eventHeader(4, 5, 1, -5));
  append(bytes, eventBytes(5, 6, "C", {3}));
  LogReader reader = readerOf(bytes);

  const std::vector<LogEvent> events = readAll(reader);
  ASSERT_EQ(events.size(), 3U);
  EXPECT_EQ(events[0].channel, "A");
  EXPECT_EQ(events[1].channel, "B");
  EXPECT_EQ(events[2].channel, "C");
  ASSERT_EQ(reader.problemCount(), 3U);
  EXPECT_EQ(reader.problems()[0].kind, LogProblemKind::kBadChannelLength);
  EXPECT_EQ(
      reader.problems()[0].description,
      "byte 0: channel length 0 out of range 1..999; skipped 28 bytes to the next sync word at byte 28");
  EXPECT_EQ(reader.problems()[1].kind, LogProblemKind::kBadChannelLength);
  EXPECT_EQ(reader.problems()[1].offset, second_bad);
  EXPECT_EQ(reader.problems()[2].kind, LogProblemKind::kBadDataLength);
  EXPECT_EQ(reader.problems()[2].offset, third_bad);
  EXPECT_EQ(reader.skippedBytes(), 3U * 28U);
}

TEST_F(LcmLogReader, TheFirstTenProblemsAreKeptAndAllAreCounted)
{
  Bytes bytes;
  for (int index = 0; index < 12; ++index) {
    append(bytes, Bytes{0, 0, 0});
    append(bytes, eventBytes(index, index, "E", {}));
  }
  LogReader reader = readerOf(bytes);
  EXPECT_EQ(readAll(reader).size(), 12U);
  EXPECT_EQ(reader.problemCount(), 12U);
  EXPECT_EQ(reader.problems().size(), LogReader::kMaxKeptProblems);
  EXPECT_EQ(reader.skippedBytes(), 36U);
  EXPECT_EQ(reader.problems()[9].offset, 9U * (3U + 29U));
}

// Every byte of a file is either in an event returned or skipped; a log cut anywhere keeps every whole
// event before the cut and reports the cut part as one problem. (Data holding a sync word would make the
// cut part two problems: the reader, like liblcm, cannot tell it from the start of an event.)
TEST_F(LcmLogReader, ALogCutAtAnyByteKeepsTheWholeEventsBeforeTheCut)
{
  const std::vector<Bytes> events = {eventBytes(0, 1, "POSE", {1, 2, 3, 4, 5, 6, 7}),
                                     eventBytes(1, 2, "GOAL", {}),
                                     eventBytes(2, 3, "DV_GRAPH", Bytes(40, 0xDA))};
  Bytes log;
  std::vector<std::size_t> ends;
  for (const Bytes& event : events) {
    append(log, event);
    ends.push_back(log.size());
  }
  for (std::size_t cut = 0; cut <= log.size(); ++cut) {
    LogReader reader = readerOf(Bytes(log.begin(), log.begin() + static_cast<std::ptrdiff_t>(cut)));
    const std::vector<LogEvent> read = readAll(reader);
    std::size_t whole = 0;
    while (whole < ends.size() && ends[whole] <= cut) {
      ++whole;
    }
    const bool at_boundary = cut == 0 || (whole > 0 && ends[whole - 1] == cut);
    ASSERT_EQ(read.size(), whole) << "cut at " << cut;
    ASSERT_EQ(reader.problemCount(), at_boundary ? 0U : 1U) << "cut at " << cut;
    std::uint64_t read_bytes = 0;
    for (const LogEvent& event : read) {
      read_bytes += eventSize(event);
    }
    ASSERT_EQ(read_bytes + reader.skippedBytes(), cut) << "cut at " << cut;
  }
}

TEST_F(LcmLogReader, AFlippedByteAnywhereLosesNoByteAndNoEventAfterIt)
{
  Bytes log = eventBytes(0, 1, "POSE", kPoseData);
  append(log, eventBytes(1, 2, "GOAL", {4, 5}));
  const std::size_t last_start = log.size();
  append(log, eventBytes(2, 3, "DV_GRAPH", Bytes(40, 0xA1)));
  for (std::size_t index = 0; index < log.size(); ++index) {
    Bytes flipped = log;
    flipped[index] ^= 0xFFU;
    LogReader reader = readerOf(flipped);
    const std::vector<LogEvent> read = readAll(reader);
    std::uint64_t read_bytes = 0;
    for (const LogEvent& event : read) {
      read_bytes += eventSize(event);
    }
    ASSERT_EQ(read_bytes + reader.skippedBytes(), log.size()) << "byte " << index << " flipped";
    ASSERT_LE(read.size(), 3U);
    if (index < last_start) {
      // A sync word is never lost to damage before it: the last event is always found.
      ASSERT_FALSE(read.empty()) << "byte " << index << " flipped";
      EXPECT_EQ(read.back().channel, "DV_GRAPH") << "byte " << index << " flipped";
    }
  }
}

TEST(LcmLogReaderOpen, AMissingFileOrADirectoryIsAnOpenErrorNamingIt)
{
  LogReader missing = LogReader::open("/nonexistent/run.lcmlog");
  EXPECT_EQ(missing.openError(), "cannot open '/nonexistent/run.lcmlog': No such file or directory");
  LogEvent event;
  EXPECT_FALSE(missing.next(event));
  test_support::TemporaryDirectory directory("lcm-log-reader-open");
  LogReader folder = LogReader::open(directory.path().string());
  EXPECT_EQ(folder.openError(), "'" + directory.path().string() + "' is a directory, not an LCM log");
  EXPECT_FALSE(folder.next(event));
}

}  // namespace
}  // namespace ifar::lcm_log
