// ifar replay as a process onto a private LCM URL, a listener in the test counting what arrives: exactly the
// non-command messages of a log, byte for byte and in order, and the commands only of the channels allowed;
// a corrupt length or a last event claiming 2 GB stops it with exit code 2 naming the byte offset, after the
// events before it; SIGUSR1 pauses and SIGUSR2 resumes; --gui starts lcm-logplayer-gui (Java 17, under
// Xvfb) with the command channels switched off.

#include <signal.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ifar/can_frame_t.hpp"
#include "ifar/velocity_cmd_t.hpp"
#include "lcmtypes/samples/sample_messages.hpp"
#include "testing/child_process.hpp"
#include "testing/temporary_directory.hpp"
#include "tests/integration/record_replay/tool_test_support.hpp"

namespace ifar::record_replay_test {
namespace {

using test_support::ChildOptions;
using test_support::ChildProcess;

template <typename Message>
std::vector<std::uint8_t> encoded(const Message& message)
{
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(message.getEncodedSize()));
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

Received canFrame(std::int32_t id)
{
  can_frame_t frame{};
  frame.id = id;
  frame.dlc = 8;
  frame.data[0] = 0x0F;
  return Received{"CAN_VEHICLE", encoded(frame)};
}

/// Every sample on its channel, then CAN frames to and from the drives, then a velocity command on a channel
/// of another name; `commands` gets the events a replay must leave out by default.
std::vector<Received> mixedLog(std::vector<Received>& commands)
{
  std::vector<Received> events;
  for (const auto& sample : lcmtypes_samples::allSampleMessages()) {
    events.push_back(Received{sample.channel, sample.encoded});
    if (sample.channel == "VELOCITY_CMD" || sample.channel == "E_STOP" || sample.channel == "GOAL") {
      commands.push_back(events.back());
    }
  }
  for (const std::int32_t id : {0x201, 0x181, 0x000, 0x190, 0x601, 0x581, 0x77F, 0x701}) {
    events.push_back(canFrame(id));
    if (id == 0x201 || id == 0x000 || id == 0x601 || id == 0x77F) {
      commands.push_back(events.back());
    }
  }
  velocity_cmd_t command{};
  command.linear_velocity = 0.5;
  events.push_back(Received{"SIM_VELOCITY", encoded(command)});
  commands.push_back(events.back());
  return events;
}

std::vector<Received> without(const std::vector<Received>& events, const std::vector<Received>& left_out)
{
  std::vector<Received> kept;
  for (const Received& event : events) {
    if (std::find(left_out.begin(), left_out.end(), event) == left_out.end()) {
      kept.push_back(event);
    }
  }
  return kept;
}

/// Ends a whole process group when it goes (SIGTERM), whatever the test did before.
struct ProcessGroupStop {
  pid_t group;
  ProcessGroupStop(const ProcessGroupStop&) = delete;
  ProcessGroupStop& operator=(const ProcessGroupStop&) = delete;
  ~ProcessGroupStop()
  {
    if (group > 0) {
      kill(-group, SIGTERM);
    }
  }
};

class ReplayProcess : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return (directory_.path() / name).string(); }
  std::string output() const { return test_support::readText(path("replay.out")); }

  /// Runs ifar replay on `log` with `arguments` onto `url` while `listener` takes what arrives: its exit
  /// code.
  std::optional<int> replay(BusListener& listener, const std::string& log, const std::string& url,
                            std::vector<std::string> arguments)
  {
    std::vector<std::string> command = {toolPath("ifar-replay"), log, "--lcm-url", url};
    command.insert(command.end(), arguments.begin(), arguments.end());
    ChildProcess child(command, ChildOptions{path("replay.out"), "", {}});
    return listener.spinUntilExit(child, 30.0);
  }

  test_support::TemporaryDirectory directory_{"replay-process-test"};
};

TEST_F(ReplayProcess, DeliversExactlyTheNonCommandMessagesByteForByteAndSaysWhatItLeavesOut)
{
  std::vector<Received> commands;
  const std::vector<Received> events = mixedLog(commands);
  ASSERT_EQ(events.size(), 37U);
  ASSERT_EQ(commands.size(), 8U);
  ASSERT_TRUE(writeLog(path("mixed.lcmlog"), events));
  const std::string url = privateUrl(7841);
  BusListener listener(url, ".*");
  ASSERT_TRUE(listener.good());
  EXPECT_EQ(replay(listener, path("mixed.lcmlog"), url, {}), 0) << output();
  EXPECT_EQ(listener.received().size(), 29U);
  EXPECT_EQ(listener.received(), without(events, commands));
  const std::string text = output();
  EXPECT_TRUE(contains(text, "leaving out commands: the channels VELOCITY_CMD, E_STOP and GOAL")) << text;
  EXPECT_TRUE(contains(text, "end of log: 29 messages published, 8 commands left out, 0 not selected"))
      << text;
  EXPECT_TRUE(contains(text, "  left out on CAN_VEHICLE: 4\n")) << text;
  EXPECT_TRUE(contains(text, "  left out on SIM_VELOCITY: 1\n")) << text;
}

TEST_F(ReplayProcess, CommandsOfTheAllowedChannelsOnlyAreDelivered)
{
  std::vector<Received> commands;
  const std::vector<Received> events = mixedLog(commands);
  ASSERT_TRUE(writeLog(path("mixed.lcmlog"), events));
  const std::string url = privateUrl(7842);
  BusListener listener(url, ".*");
  EXPECT_EQ(replay(listener, path("mixed.lcmlog"), url,
                   {"--speed", "0", "--allow-command", "VELOCITY_CMD", "--allow-command", "CAN_VEHICLE"}),
            0)
      << output();
  std::vector<Received> still_out;
  for (const Received& command : commands) {
    if (command.channel != "VELOCITY_CMD" && command.channel != "CAN_VEHICLE") {
      still_out.push_back(command);
    }
  }
  ASSERT_EQ(still_out.size(), 3U);  // E_STOP, GOAL, SIM_VELOCITY
  EXPECT_EQ(listener.received(), without(events, still_out));
}

TEST_F(ReplayProcess, ChannelsAndExcludeSelectWholeNames)
{
  std::vector<Received> commands;
  const std::vector<Received> events = mixedLog(commands);
  ASSERT_TRUE(writeLog(path("mixed.lcmlog"), events));
  const std::string url = privateUrl(7843);
  BusListener listener(url, ".*");
  EXPECT_EQ(replay(listener, path("mixed.lcmlog"), url,
                   {"--speed", "0", "--channels", "POSE|GOAL|CAN_.*", "--exclude", "CAN_STATUS"}),
            0)
      << output();
  std::vector<std::string> channels;
  for (const Received& message : listener.received()) {
    channels.push_back(message.channel);
  }
  // GOAL is selected but a command; CAN_VEHICLE's four frames from the drives and sensor are not commands.
  EXPECT_EQ(channels, (std::vector<std::string>{"CAN_VEHICLE", "POSE", "CAN_VEHICLE", "CAN_VEHICLE",
                                                "CAN_VEHICLE", "CAN_VEHICLE"}));
}

/// The bytes of the events as a log file, and where each event starts.
std::vector<std::uint64_t> eventOffsets(const std::vector<Received>& events)
{
  std::vector<std::uint64_t> offsets;
  std::uint64_t offset = 0;
  for (const Received& event : events) {
    offsets.push_back(offset);
    offset += 28 + event.channel.size() + event.data.size();
  }
  offsets.push_back(offset);
  return offsets;
}

std::vector<std::uint8_t> fileBytes(const std::string& path)
{
  const std::string text = test_support::readText(path);
  return std::vector<std::uint8_t>(text.begin(), text.end());
}

void writeBytes(const std::string& path, const std::vector<std::uint8_t>& bytes)
{
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

TEST_F(ReplayProcess, OneLengthChangedStopsWithExitTwoNamingTheOffsetAfterTheEventsBeforeIt)
{
  std::vector<Received> events;
  for (const auto& sample : lcmtypes_samples::allSampleMessages()) {
    if (sample.channel != "VELOCITY_CMD" && sample.channel != "E_STOP" && sample.channel != "GOAL") {
      events.push_back(Received{sample.channel, sample.encoded});
    }
  }
  ASSERT_TRUE(writeLog(path("whole.lcmlog"), events));
  const std::vector<std::uint64_t> offsets = eventOffsets(events);
  std::vector<std::uint8_t> bytes = fileBytes(path("whole.lcmlog"));
  ASSERT_EQ(bytes.size(), offsets.back());
  // Event 10's data length, the last 4 bytes of its header (big-endian), made 3 larger.
  std::uint32_t length = 0;
  for (std::uint64_t index = 24; index < 28; ++index) {
    length = (length << 8U) | bytes[offsets[10] + index];
  }
  length += 3;
  for (std::uint64_t index = 24; index < 28; ++index) {
    bytes[offsets[10] + index] = static_cast<std::uint8_t>(length >> (8U * (27 - index)));
  }
  writeBytes(path("corrupt.lcmlog"), bytes);

  const std::string url = privateUrl(7844);
  BusListener listener(url, ".*");
  EXPECT_EQ(replay(listener, path("corrupt.lcmlog"), url, {"--speed", "0"}), 2) << output();
  EXPECT_EQ(listener.received(), std::vector<Received>(events.begin(), events.begin() + 10));
  const std::string text = output();
  EXPECT_TRUE(contains(text, "ifar replay: error: '" + path("corrupt.lcmlog") + "' is corrupt at byte " +
                                 std::to_string(offsets[11] + 3) + ": bad sync word"))
      << text;
  EXPECT_TRUE(
      contains(text, "the event at byte " + std::to_string(offsets[10]) +
                         " before it is left out: its length does not end where an event starts; stopped "
                         "there. 10 messages published"))
      << text;
}

TEST_F(ReplayProcess, ALastEventClaimingTwoGigabytesStopsWithExitTwoNamingItsOffset)
{
  const std::vector<Received> events = {
      {"POSE", {9, 8, 7, 6, 5}}, {"FORCE", {1, 2, 3}}, {"ODOMETRY", {4, 5, 6, 7}}};
  ASSERT_TRUE(writeLog(path("whole.lcmlog"), events));
  const std::vector<std::uint64_t> offsets = eventOffsets(events);
  std::vector<std::uint8_t> bytes = fileBytes(path("whole.lcmlog"));
  for (int index = 0; index < 4; ++index) {
    bytes[offsets[2] + 24 + static_cast<std::uint64_t>(index)] = index == 0 ? 0x7F : 0xFF;
  }
  writeBytes(path("huge.lcmlog"), bytes);

  const std::string url = privateUrl(7845);
  BusListener listener(url, ".*");
  EXPECT_EQ(replay(listener, path("huge.lcmlog"), url, {"--speed", "0"}), 2) << output();
  EXPECT_EQ(listener.received(), std::vector<Received>(events.begin(), events.begin() + 2));
  EXPECT_TRUE(
      contains(output(), "is corrupt at byte " + std::to_string(offsets[2]) +
                             ": event truncated: header claims 8 channel and 2147483647 data bytes, only 12 "
                             "bytes follow the header"))
      << output();
}

TEST_F(ReplayProcess, SigusrOnePausesAndSigusrTwoResumes)
{
  std::vector<Received> events;
  for (std::uint8_t index = 0; index < 40; ++index) {
    events.push_back(Received{"POSE", {index}});  // 5 ms apart: 0.195 s of log, 0.39 s at speed 0.5
  }
  ASSERT_TRUE(writeLog(path("poses.lcmlog"), events));
  const std::string url = privateUrl(7846);
  BusListener listener(url, ".*");
  const auto start = std::chrono::steady_clock::now();
  ChildProcess child({toolPath("ifar-replay"), path("poses.lcmlog"), "--lcm-url", url, "--speed", "0.5"},
                     ChildOptions{path("replay.out"), "", {}});
  listener.spin(10.0, [&] { return listener.received().size() >= 5; });
  kill(child.pid(), SIGUSR1);
  listener.spin(0.1);
  const std::size_t at_pause = listener.received().size();
  listener.spin(0.8);
  EXPECT_EQ(listener.received().size(), at_pause) << "messages arrived while paused";
  EXPECT_LT(at_pause, events.size());
  kill(child.pid(), SIGUSR2);
  EXPECT_EQ(listener.spinUntilExit(child, 10.0), 0) << output();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(listener.received().size(), events.size());
  EXPECT_GT(seconds, 0.39 + 0.9);  // the log's 0.39 s at half speed, and the pause
  EXPECT_TRUE(contains(output(), "ifar replay: paused at log ")) << output();
  EXPECT_TRUE(contains(output(), "ifar replay: resumed at log ")) << output();
}

TEST_F(ReplayProcess, GuiStartsLogPlayerOnJava17WithTheCommandChannelsSwitchedOff)
{
  ASSERT_TRUE(std::filesystem::exists("/usr/bin/xvfb-run"))
      << "xvfb-run missing (scripts/setup installs xvfb)";
  std::vector<Received> commands;
  const std::vector<Received> events = mixedLog(commands);
  ASSERT_TRUE(writeLog(path("mixed.lcmlog"), events));
  const std::string url = privateUrl(7847);
  BusListener listener(url, ".*");
  // In a process group of its own (setsid execs in place), so that if the test stops early the player
  // (ifar replay execs into java), xvfb-run and its X server all end together: xvfb-run stopped alone
  // leaves its server running.
  ChildProcess child({"/usr/bin/setsid", "/usr/bin/xvfb-run", "-a", toolPath("ifar-replay"),
                      path("mixed.lcmlog"), "--gui", "--lcm-url", url},
                     ChildOptions{path("replay.out"), "", {}});
  const ProcessGroupStop stop_group{child.pid()};
  // The player cannot leave out single CAN frames: CAN_VEHICLE, with its commands, starts switched off.
  std::vector<Received> expected;
  for (const Received& event : events) {
    if (std::find(commands.begin(), commands.end(), event) == commands.end() &&
        event.channel != "CAN_VEHICLE") {
      expected.push_back(event);
    }
  }
  ASSERT_EQ(expected.size(), 24U);
  listener.spin(14.0, [&] { return listener.received().size() >= expected.size(); });
  listener.spin(0.5);
  // The player stopped, xvfb-run stops its X server, removes its files and ends.
  for (const pid_t process : childrenOf(child.pid())) {
    if (test_support::readText("/proc/" + std::to_string(process) + "/comm") == "java\n") {
      kill(process, SIGTERM);
    }
  }
  EXPECT_TRUE(child.waitFor(10.0).has_value()) << "xvfb-run did not end with the player";
  const std::string text = output();
  EXPECT_TRUE(contains(text,
                       "lcm-logplayer-gui with these channels switched off: CAN_VEHICLE E_STOP GOAL "
                       "SIM_VELOCITY VELOCITY_CMD"))
      << text;
  EXPECT_FALSE(contains(text, "Unrecognized option")) << text;
  std::set<std::string> channels;
  for (const Received& message : listener.received()) {
    channels.insert(message.channel);
  }
  EXPECT_EQ(channels.count("CAN_VEHICLE") + channels.count("E_STOP") + channels.count("GOAL") +
                channels.count("SIM_VELOCITY") + channels.count("VELOCITY_CMD"),
            0U)
      << text;
  std::vector<Received> received = listener.received();
  EXPECT_EQ(received, expected) << text;
}

}  // namespace
}  // namespace ifar::record_replay_test
