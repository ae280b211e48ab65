// ifar replay's parts without a bus: which events it publishes (commands left out by channel, by type and by
// CAN identifier unless allowed), when each is due at a speed and across pauses, what it reports, and the
// command line of lcm-logplayer-gui.

#include <cstdint>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ifar/can_frame_t.hpp"
#include "ifar/velocity_cmd_t.hpp"
#include "lcmtypes/samples/sample_messages.hpp"
#include "tools/replay/log_player_gui.hpp"
#include "tools/replay/playback_clock.hpp"
#include "tools/replay/replay_filter.hpp"
#include "tools/replay/replay_report.hpp"

namespace ifar::replay {
namespace {

template <typename Message>
std::vector<std::uint8_t> encoded(const Message& message)
{
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(message.getEncodedSize()));
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

std::vector<std::uint8_t> canFrame(std::int32_t id, std::int8_t flags = 0)
{
  can_frame_t frame{};
  frame.id = id;
  frame.flags = flags;
  frame.dlc = 2;
  return encoded(frame);
}

const std::vector<std::uint8_t> kNotAProjectType = {1, 2, 3, 4, 5, 6, 7, 8, 9};

TEST(DriveCommandFrames, EveryFrameADriveActsOnAndNoneItSends)
{
  for (const std::int32_t id :
       {0x000, 0x080, 0x100, 0x201, 0x202, 0x27F, 0x301, 0x401, 0x501, 0x601, 0x67F, 0x77F}) {
    EXPECT_TRUE(isDriveCommandFrame(id, 0)) << std::hex << id;
  }
  // EMCY, TPDO1-4, the force sensor, SDO answers, the drives' heartbeats; RPDO and SDO "node 0" do not exist.
  for (const std::int32_t id :
       {0x081, 0x181, 0x190, 0x281, 0x381, 0x481, 0x581, 0x701, 0x702, 0x200, 0x600}) {
    EXPECT_FALSE(isDriveCommandFrame(id, 0)) << std::hex << id;
  }
  // The drives take standard data frames only.
  EXPECT_FALSE(isDriveCommandFrame(0x201, can_frame_t::FLAG_EXTENDED));
  EXPECT_FALSE(isDriveCommandFrame(0x201, can_frame_t::FLAG_REMOTE));
  EXPECT_FALSE(isDriveCommandFrame(0x201, can_frame_t::FLAG_ERROR));
  EXPECT_FALSE(isDriveCommandFrame(0x10000201, 0));
}

TEST(ReplayFilterTest, EverySampleIsPublishedButTheThreeCommandChannels)
{
  const ReplayFilter filter("", "", {});
  std::set<std::string> left_out;
  for (const auto& sample : lcmtypes_samples::allSampleMessages()) {
    if (filter.classify(sample.channel, common::ByteView(sample.encoded)) != Verdict::kPublish) {
      left_out.insert(sample.channel);
    }
  }
  // The CAN_VEHICLE sample is an extended frame: no drive takes it.
  EXPECT_EQ(left_out, (std::set<std::string>{"E_STOP", "GOAL", "VELOCITY_CMD"}));
}

TEST(ReplayFilterTest, CommandsAreKnownByChannelByTypeAndByCanIdentifier)
{
  const ReplayFilter filter("", "", {});
  EXPECT_EQ(filter.classify("GOAL", common::ByteView(kNotAProjectType)), Verdict::kCommand);
  EXPECT_EQ(filter.classify("VELOCITY_CMD", {}), Verdict::kCommand);
  EXPECT_EQ(filter.classify("E_STOP", common::ByteView(kNotAProjectType)), Verdict::kCommand);
  const std::vector<std::uint8_t> command = encoded(velocity_cmd_t{});
  EXPECT_EQ(filter.classify("SIM_VELOCITY", common::ByteView(command)), Verdict::kCommand);
  const std::vector<std::uint8_t> rpdo = canFrame(0x201);
  const std::vector<std::uint8_t> nmt = canFrame(0x000);
  const std::vector<std::uint8_t> sdo_request = canFrame(0x602);
  const std::vector<std::uint8_t> tpdo = canFrame(0x181);
  const std::vector<std::uint8_t> force = canFrame(0x190);
  EXPECT_EQ(filter.classify("CAN_VEHICLE", common::ByteView(rpdo)), Verdict::kDriveCommand);
  EXPECT_EQ(filter.classify("CAN_OTHER", common::ByteView(nmt)), Verdict::kDriveCommand);
  EXPECT_EQ(filter.classify("CAN_VEHICLE", common::ByteView(sdo_request)), Verdict::kDriveCommand);
  EXPECT_EQ(filter.classify("CAN_VEHICLE", common::ByteView(tpdo)), Verdict::kPublish);
  EXPECT_EQ(filter.classify("CAN_VEHICLE", common::ByteView(force)), Verdict::kPublish);
  // A can_frame_t cut short cannot be shown not to be a command.
  const std::vector<std::uint8_t> cut(tpdo.begin(), tpdo.begin() + 12);
  EXPECT_EQ(filter.classify("CAN_VEHICLE", common::ByteView(cut)), Verdict::kDriveCommand);
  EXPECT_EQ(filter.classify("POSE", common::ByteView(kNotAProjectType)), Verdict::kPublish);
}

TEST(ReplayFilterTest, AnAllowedChannelPublishesItsCommandsAndNoOtherChannels)
{
  const ReplayFilter filter("", "", {"VELOCITY_CMD", "CAN_VEHICLE"});
  const std::vector<std::uint8_t> rpdo = canFrame(0x201);
  EXPECT_EQ(filter.classify("VELOCITY_CMD", {}), Verdict::kPublish);
  EXPECT_EQ(filter.classify("CAN_VEHICLE", common::ByteView(rpdo)), Verdict::kPublish);
  EXPECT_EQ(filter.classify("CAN_OTHER", common::ByteView(rpdo)), Verdict::kDriveCommand);
  EXPECT_EQ(filter.classify("GOAL", {}), Verdict::kCommand);
  EXPECT_EQ(filter.description(),
            "leaving out commands: the channels VELOCITY_CMD, E_STOP and GOAL, velocity_cmd_t, e_stop_t and "
            "goal_t on "
            "any channel, and CAN frames the drives act on (NMT, SYNC, TIME, RPDO1-4, SDO requests, "
            "ifar-motor-driver's heartbeat 0x77F) in can_frame_t on any channel, except on CAN_VEHICLE "
            "VELOCITY_CMD "
            "(--allow-command)");
}

TEST(ReplayFilterTest, IncludeAndExcludeMatchWholeChannelNamesAndCommandsStayOut)
{
  const ReplayFilter filter("POSE|GOAL|CAN_.*", "CAN_STATUS", {});
  EXPECT_EQ(filter.classify("POSE", {}), Verdict::kPublish);
  EXPECT_EQ(filter.classify("POSE_2", {}), Verdict::kNotSelected);
  EXPECT_EQ(filter.classify("MY_POSE", {}), Verdict::kNotSelected);
  EXPECT_EQ(filter.classify("CAN_STATUS", {}), Verdict::kNotSelected);
  EXPECT_EQ(filter.classify("GOAL", {}), Verdict::kCommand);
  EXPECT_EQ(filter.classify("CAN_VEHICLE", {}), Verdict::kPublish);
}

TEST(ReplayFilterTest, ARegexThatDoesNotParseNamesItsOption)
{
  try {
    const ReplayFilter filter("", "(", {});
    FAIL() << "accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_EQ(std::string(error.what()).rfind("--exclude '(' is not a regular expression: ", 0), 0U)
        << error.what();
  }
}

TEST(PlaybackClockTest, EventsAreDueOnTheLogsTimeScaledBySpeed)
{
  PlaybackClock clock(2.0);
  EXPECT_EQ(clock.waitFor(5'000'000, 100), 0);        // the first anchors the log at 100 us
  EXPECT_EQ(clock.waitFor(6'000'000, 100), 500'000);  // 1 s of log at speed 2
  EXPECT_EQ(clock.waitFor(6'000'000, 400'100), 100'000);
  EXPECT_EQ(clock.waitFor(6'000'000, 700'000), 0);  // late: due at once
  EXPECT_EQ(clock.waitFor(4'000'000, 700'000), 0);  // stamped before the first one
}

TEST(PlaybackClockTest, APauseHoldsEverythingAndShiftsWhatFollowsByItsLength)
{
  PlaybackClock clock(1.0);
  EXPECT_EQ(clock.waitFor(0, 0), 0);
  clock.pause(200'000);
  EXPECT_TRUE(clock.paused());
  EXPECT_EQ(clock.waitFor(100'000, 300'000), std::nullopt);  // due before the pause ended: still held
  clock.pause(400'000);                                      // a second pause changes nothing
  clock.resume(1'200'000);
  EXPECT_FALSE(clock.paused());
  EXPECT_EQ(clock.waitFor(100'000, 1'200'000), 0);            // due 0.1 s + 1 s paused = 1.1 s: late
  EXPECT_EQ(clock.waitFor(2'000'000, 1'200'000), 1'800'000);  // due 2 s + 1 s
  clock.resume(1'500'000);                                    // not paused: nothing shifts
  EXPECT_EQ(clock.waitFor(2'000'000, 1'200'000), 1'800'000);
}

TEST(PlaybackClockTest, SpeedZeroPlaysEveryEventAtOnce)
{
  PlaybackClock clock(0.0);
  EXPECT_EQ(clock.waitFor(0, 10), 0);
  EXPECT_EQ(clock.waitFor(3'600'000'000, 10), 0);
}

TEST(ReplayReportTest, ProgressAndSummaryCountEachVerdictAndNameTheChannels)
{
  ReplayReport report;
  report.count("POSE", Verdict::kPublish);
  report.count("POSE", Verdict::kPublish);
  report.count("VELOCITY_CMD", Verdict::kCommand);
  report.count("CAN_VEHICLE", Verdict::kDriveCommand);
  report.count("CAN_VEHICLE", Verdict::kDriveCommand);
  report.count("FORCE", Verdict::kNotSelected);
  EXPECT_EQ(report.published(), 2U);
  EXPECT_EQ(report.leftOutCommands(), 3U);
  EXPECT_EQ(report.progressLine(12'345'678, 250, 1000, false),
            "log 12.3 s, 25%, 2 published, 3 commands left out");
  EXPECT_EQ(report.progressLine(0, 0, 0, true), "log 0.0 s, 100%, 2 published, 3 commands left out, paused");
  EXPECT_EQ(report.summary(),
            "2 messages published, 3 commands left out, 1 not selected\n"
            "  left out on CAN_VEHICLE: 2\n"
            "  left out on VELOCITY_CMD: 1");
}

TEST(LogPlayerGui, SwitchedOffChannelsBecomeOneQuotedJavaRegex)
{
  EXPECT_EQ(javaRegexOfNames({}), "");
  EXPECT_EQ(javaRegexOfNames({"GOAL", "CAN_VEHICLE"}), "^(\\QCAN_VEHICLE\\E|\\QGOAL\\E)$");
  EXPECT_EQ(javaRegexOfNames({"A.B\\EC"}), "^(\\QA.B\\E\\\\E\\QC\\E)$");
  EXPECT_EQ(logPlayerArguments("run.lcmlog", {"GOAL"}, "udpm://239.255.76.67:7700?ttl=0", false),
            (std::vector<std::string>{"--lcm-url=udpm://239.255.76.67:7700?ttl=0", "--filter=^(\\QGOAL\\E)$",
                                      "run.lcmlog"}));
  EXPECT_EQ(logPlayerArguments("run.lcmlog", {}, "", false), std::vector<std::string>{"run.lcmlog"});
  EXPECT_EQ(logPlayerArguments("run.lcmlog", {}, "", true),
            (std::vector<std::string>{"--paused", "run.lcmlog"}));
}

}  // namespace
}  // namespace ifar::replay
