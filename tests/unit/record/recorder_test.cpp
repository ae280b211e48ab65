// ifar record without a bus: the lcm-logger command line (no option that takes the next argument by
// mistake), the health the recorder's heartbeat carries, and the file names read from lcm-logger's output.

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ifar/heartbeat_t.hpp"
#include "tools/record/logger_command.hpp"
#include "tools/record/logger_process.hpp"
#include "tools/record/recorder_watch.hpp"

namespace ifar::record {
namespace {

TEST(LoggerCommand, ChannelsStrftimeAndNumberingAreEachOneArgumentBeforeTheFile)
{
  LoggerRequest request;
  request.file_pattern = "logs/ifar-%Y.lcmlog";
  request.channels = "POSE|GOAL";
  request.split_mb = 512.0;
  EXPECT_EQ(loggerArguments(request),
            (std::vector<std::string>{"lcm-logger", "-s", "--channel=POSE|GOAL", "-i", "--split-mb=512", "--",
                                      "logs/ifar-%Y.lcmlog"}));
}

TEST(LoggerCommand, RotationReplacesNumberingAndSplitZeroIsLeftOut)
{
  LoggerRequest request;
  request.file_pattern = "-odd-name.lcmlog";
  request.rotate = 10;
  request.split_mb = 0.0;
  EXPECT_EQ(loggerArguments(request), (std::vector<std::string>{"lcm-logger", "-s", "--channel=.*",
                                                                "--rotate=10", "--", "-odd-name.lcmlog"}));
  request.rotate = 0;
  request.split_mb = 0.25;
  EXPECT_EQ(loggerArguments(request),
            (std::vector<std::string>{"lcm-logger", "-s", "--channel=.*", "-i", "--split-mb=0.25", "--",
                                      "-odd-name.lcmlog"}));
}

TEST(LoggerEnvironment, AVariableGivenReplacesTheParentsAndANewOneIsAddedAtTheEnd)
{
  const std::vector<std::string> parent = {"PATH=/usr/bin", "LCM_DEFAULT_URL=udpm://old", "LCM=x",
                                           "HOME=/root"};
  EXPECT_EQ(environmentWith(parent, {"LCM_DEFAULT_URL=udpm://new", "LD_PRELOAD=/lib/a.so", "HOME="}),
            (std::vector<std::string>{"PATH=/usr/bin", "LCM_DEFAULT_URL=udpm://new", "LCM=x",
                                      "HOME=", "LD_PRELOAD=/lib/a.so"}));
  EXPECT_EQ(environmentWith(parent, {}), parent);
}

TEST(LoggerOutput, TheOpenedFileIsReadFromItsLineOnly)
{
  EXPECT_EQ(openedLogFile("Opening log file \"logs/ifar-2025.lcmlog.00\""), "logs/ifar-2025.lcmlog.00");
  EXPECT_EQ(openedLogFile("Opening log file \"\""), std::nullopt);
  EXPECT_EQ(openedLogFile("Summary: logs/x ti: 1sec Events: 3"), std::nullopt);
  EXPECT_EQ(openedLogFile("Opening log file \"unterminated"), std::nullopt);
}

constexpr std::int64_t kStallUs = 3'000'000;

TEST(RecorderWatchTest, GrowingWhileMessagesArriveIsHealthy)
{
  RecorderWatch watch(kStallUs);
  watch.onLogFile("logs/a.lcmlog.00", 0);
  watch.onFileSize(0, 0);
  for (std::int64_t now = 100'000; now <= 10'000'000; now += 100'000) {
    watch.onMessage(now);
    watch.onFileSize(static_cast<std::uint64_t>(now / 1000), now);
    const RecorderHealth health = watch.health(now);
    ASSERT_EQ(health.level, heartbeat_t::HEALTH_OK) << now;
    ASSERT_EQ(health.message, "");
  }
  EXPECT_EQ(watch.logFile(), "logs/a.lcmlog.00");
}

TEST(RecorderWatchTest, NoMessagesNoGrowthIsHealthy)
{
  RecorderWatch watch(kStallUs);
  watch.onLogFile("logs/a.lcmlog.00", 0);
  watch.onFileSize(0, 0);
  watch.onFileSize(0, 60'000'000);
  EXPECT_EQ(watch.health(60'000'000).level, heartbeat_t::HEALTH_OK);
}

TEST(RecorderWatchTest, AFileThatStopsGrowingWhileMessagesArriveIsAnErrorAfterTheStallTime)
{
  RecorderWatch watch(kStallUs);
  watch.onLogFile("logs/a.lcmlog.00", 0);
  watch.onFileSize(100, 0);
  for (std::int64_t now = 1'000'000; now <= 4'000'000; now += 1'000'000) {
    watch.onMessage(now);
    watch.onFileSize(100, now);
  }
  EXPECT_EQ(watch.health(3'999'999).level, heartbeat_t::HEALTH_OK);
  const RecorderHealth stalled = watch.health(4'000'000);
  EXPECT_EQ(stalled.level, heartbeat_t::HEALTH_ERROR);
  EXPECT_EQ(stalled.message,
            "log file logs/a.lcmlog.00 has not grown for 3.0 s while 4 messages arrived (disk full? logger "
            "stuck?)");
  // It grows again: healthy at once.
  watch.onFileSize(101, 4'100'000);
  EXPECT_EQ(watch.health(4'100'000).level, heartbeat_t::HEALTH_OK);
}

TEST(RecorderWatchTest, ANewFileAfterASplitCountsAsGrowth)
{
  RecorderWatch watch(kStallUs);
  watch.onLogFile("logs/a.lcmlog.00", 0);
  watch.onFileSize(512, 0);
  watch.onMessage(1'000'000);
  watch.onLogFile("logs/a.lcmlog.01", 1'500'000);
  watch.onFileSize(0, 1'500'000);
  EXPECT_EQ(watch.health(9'000'000).level, heartbeat_t::HEALTH_OK);
}

TEST(RecorderWatchTest, MessagesBeforeAnyFileOpenedAreAnErrorAfterTheStallTime)
{
  RecorderWatch watch(kStallUs);
  watch.onMessage(0);
  watch.onMessage(500'000);
  EXPECT_EQ(watch.health(2'999'999).level, heartbeat_t::HEALTH_DEGRADED);
  EXPECT_EQ(watch.health(2'999'999).message, "waiting for lcm-logger to open its log file");
  EXPECT_EQ(watch.health(3'000'000).message,
            "lcm-logger has opened no log file while 2 messages arrived (disk full? logger stuck?)");
}

TEST(RecorderWatchTest, ReadyOnlyOnceTheFileGrowsAfterAMessageArrived)
{
  RecorderWatch watch(kStallUs);
  EXPECT_EQ(watch.health(0).level, heartbeat_t::HEALTH_DEGRADED);
  watch.onMessage(50'000);  // the recorder's own first beat, before lcm-logger subscribed
  watch.onLogFile("logs/a.lcmlog.00", 100'000);
  watch.onFileSize(0, 100'000);
  watch.onMessage(200'000);
  watch.onFileSize(0, 200'000);
  // Long after the file opened, still not ready while what arrived is not in it.
  const RecorderHealth waiting = watch.health(2'000'000);
  EXPECT_EQ(waiting.level, heartbeat_t::HEALTH_DEGRADED);
  EXPECT_EQ(waiting.message, "waiting for lcm-logger to write its first message to logs/a.lcmlog.00");
  watch.onFileSize(96, 2'000'000);
  EXPECT_EQ(watch.health(2'000'000).level, heartbeat_t::HEALTH_OK);
  // A split's new empty file does not make it wait again.
  watch.onLogFile("logs/a.lcmlog.01", 3'000'000);
  watch.onFileSize(0, 3'000'000);
  EXPECT_EQ(watch.health(3'000'000).level, heartbeat_t::HEALTH_OK);
}

TEST(RecorderWatchTest, NothingRecordedArrivingIsReadyASecondAfterTheFileOpened)
{
  RecorderWatch watch(kStallUs);
  watch.onLogFile("logs/a.lcmlog.00", 100'000);
  watch.onFileSize(0, 100'000);
  EXPECT_EQ(watch.health(1'099'999).level, heartbeat_t::HEALTH_DEGRADED);
  EXPECT_EQ(watch.health(1'100'000).level, heartbeat_t::HEALTH_OK);
}

TEST(RecorderWatchTest, AFileThatCannotBeReadIsAnError)
{
  RecorderWatch watch(kStallUs);
  watch.onLogFile("logs/a.lcmlog.00", 0);
  watch.onFileSize(std::nullopt, 100'000);
  const RecorderHealth health = watch.health(100'000);
  EXPECT_EQ(health.level, heartbeat_t::HEALTH_ERROR);
  EXPECT_EQ(health.message, "log file logs/a.lcmlog.00 cannot be read (removed?): its messages may be lost");
}

TEST(RecorderWatchTest, ALoggerThatEndedIsAnErrorNamingHowItEnded)
{
  RecorderWatch watch(kStallUs);
  watch.onLogFile("logs/a.lcmlog.00", 0);
  watch.onFileSize(100, 0);
  watch.onLoggerExit("killed by signal 9 (Killed)");
  const RecorderHealth health = watch.health(1);
  EXPECT_EQ(health.level, heartbeat_t::HEALTH_ERROR);
  EXPECT_EQ(health.message, "lcm-logger killed by signal 9 (Killed): nothing is recorded");
}

}  // namespace
}  // namespace ifar::record
