// The tools that read LCM logs, run as processes on logs written byte by byte. With liblcm's reader a
// header claiming 2 GB killed all three with SIGSEGV, and garbage, a cut last event or a log of random
// bytes passed `ifar log-info --check`. Now: no crash; --check fails naming the first bad byte (and fails
// on an empty log); run-summary and render-graph use the events they can read and warn, or fail naming
// the file and the offset when there are none.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lcmtypes/samples/sample_messages.hpp"
#include "testing/child_process.hpp"
#include "testing/temporary_directory.hpp"
#include "tests/unit/lcm_log/log_bytes.hpp"

namespace ifar::lcm_log::test {
namespace {

struct ToolRun {
  int exit_code = -1;  // -1: killed by a signal (the old crash) or timed out
  std::string output;  // stdout and stderr
};

/// One event per project type, each on its channel with its sample value: a log every check passes.
Bytes sampleLog()
{
  Bytes bytes;
  std::int64_t number = 0;
  for (const auto& sample : lcmtypes_samples::allSampleMessages()) {
    append(bytes,
           eventBytes(number, 1'700'000'000'000'000 + number * 100'000, sample.channel, sample.encoded));
    ++number;
  }
  return bytes;
}

/// The sample event of one channel.
Bytes sampleEvent(const std::string& channel, std::int64_t number)
{
  for (const auto& sample : lcmtypes_samples::allSampleMessages()) {
    if (sample.channel == channel) {
      return eventBytes(number, 1'700'000'000'000'000 + number * 100'000, channel, sample.encoded);
    }
  }
  ADD_FAILURE() << "no sample on " << channel;
  return {};
}

/// The audit's 136-byte log: one event header claiming 0x7fffffff data bytes.
Bytes hugeClaimLog()
{
  Bytes bytes = eventHeader(0, 1, 4, 0x7fffffff);
  append(bytes, Bytes{'P', 'O', 'S', 'E'});
  append(bytes, Bytes(136 - bytes.size(), 0x55));
  return bytes;
}

const char* const kHugeClaimProblem =
    "byte 0: event truncated: header claims 4 channel and 2147483647 data bytes, only 108 bytes follow the "
    "header";

class LogTools : public ::testing::Test {
 protected:
  std::string writeLog(const std::string& name, const Bytes& bytes)
  {
    const std::string path = (directory_.path() / name).string();
    EXPECT_TRUE(writeFile(path, bytes));
    return path;
  }

  ToolRun run(const std::string& tool, const std::vector<std::string>& arguments)
  {
    std::vector<std::string> command = {std::string(IFAR_BINARY_DIR) + "/bin/" + tool};
    command.insert(command.end(), arguments.begin(), arguments.end());
    const std::string output_path = (directory_.path() / "tool.out").string();
    ToolRun result;
    result.exit_code = test_support::runToEnd(command, test_support::ChildOptions{output_path, "", {}}, 30.0);
    std::ifstream output(output_path);
    std::stringstream text;
    text << output.rdbuf();
    result.output = text.str();
    return result;
  }

  test_support::TemporaryDirectory directory_{"log-tools-test"};
};

bool contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

TEST_F(LogTools, LogInfoCheckFailsOnAHeaderClaimingTwoGigabytesNamingItsOffset)
{
  const std::string log = writeLog("huge.lcmlog", hugeClaimLog());
  const ToolRun check = run("ifar-log-info", {"--check", log});
  EXPECT_EQ(check.exit_code, 1) << check.output;
  EXPECT_TRUE(contains(check.output, "check: " + log + " is corrupt: 1 problem, 136 bytes skipped"))
      << check.output;
  EXPECT_TRUE(contains(check.output, kHugeClaimProblem)) << check.output;
  EXPECT_TRUE(contains(check.output, "check: FAILED")) << check.output;

  const ToolRun info = run("ifar-log-info", {log});
  EXPECT_EQ(info.exit_code, 0) << info.output;  // without --check the tool lists, and warns
  EXPECT_TRUE(contains(info.output, "0 messages on 0 channels")) << info.output;
  EXPECT_TRUE(contains(info.output, "ifar log-info: warning: " + log + " is corrupt")) << info.output;
  EXPECT_TRUE(contains(info.output, kHugeClaimProblem)) << info.output;
}

TEST_F(LogTools, LogInfoCheckPassesAValidLogAndFailsOnceGarbageFollowsIt)
{
  const Bytes valid = sampleLog();
  const std::size_t count = lcmtypes_samples::allSampleMessages().size();
  const std::string counted = std::to_string(count) + " messages on " + std::to_string(count) + " channels";
  const ToolRun clean = run("ifar-log-info", {"--check", writeLog("valid.lcmlog", valid)});
  EXPECT_EQ(clean.exit_code, 0) << clean.output;
  EXPECT_TRUE(contains(clean.output, counted)) << clean.output;
  EXPECT_TRUE(contains(clean.output, "check: every message decodes")) << clean.output;

  Bytes corrupt = valid;
  append(corrupt, Bytes(40, 0x11));
  const std::string log = writeLog("garbage-after.lcmlog", corrupt);
  const std::string problem = "byte " + std::to_string(valid.size()) +
                              ": bad sync word 0x11111111; skipped 40 bytes to the end of the file";
  const ToolRun check = run("ifar-log-info", {"--check", log});
  EXPECT_EQ(check.exit_code, 1) << check.output;
  EXPECT_TRUE(contains(check.output, counted)) << check.output;  // every event before the garbage
  EXPECT_TRUE(contains(check.output, problem)) << check.output;

  const ToolRun info = run("ifar-log-info", {log});
  EXPECT_EQ(info.exit_code, 0) << info.output;
  EXPECT_TRUE(contains(info.output, counted)) << info.output;
  EXPECT_TRUE(contains(info.output, "warning: ")) << info.output;
  EXPECT_TRUE(contains(info.output, problem)) << info.output;
}

TEST_F(LogTools, LogInfoCheckFailsOnGarbageBetweenEventsACutLastEventRandomBytesAndAnEmptyLog)
{
  Bytes between = sampleEvent("POSE", 0);
  const std::size_t garbage_at = between.size();
  append(between, Bytes(13, 0x22));
  append(between, sampleEvent("GOAL", 1));
  const ToolRun garbage = run("ifar-log-info", {"--check", writeLog("between.lcmlog", between)});
  EXPECT_EQ(garbage.exit_code, 1) << garbage.output;
  EXPECT_TRUE(contains(garbage.output, "2 messages on 2 channels")) << garbage.output;
  EXPECT_TRUE(contains(garbage.output, "byte " + std::to_string(garbage_at) + ": bad sync word 0x22222222"))
      << garbage.output;

  Bytes cut = sampleLog();
  cut.resize(cut.size() - 3);
  const ToolRun truncated = run("ifar-log-info", {"--check", writeLog("cut.lcmlog", cut)});
  EXPECT_EQ(truncated.exit_code, 1) << truncated.output;
  EXPECT_TRUE(contains(truncated.output, "event truncated")) << truncated.output;

  Bytes random(5000);
  for (std::size_t index = 0; index < random.size(); ++index) {
    random[index] = static_cast<std::uint8_t>((index * 7919U + 13U) % 251U);  // no sync word in it
  }
  const ToolRun noise = run("ifar-log-info", {"--check", writeLog("random.lcmlog", random)});
  EXPECT_EQ(noise.exit_code, 1) << noise.output;
  EXPECT_TRUE(contains(noise.output, "byte 0: bad sync word")) << noise.output;
  EXPECT_TRUE(contains(noise.output, "skipped 5000 bytes to the end of the file")) << noise.output;

  const std::string empty_log = writeLog("empty.lcmlog", {});
  const ToolRun empty = run("ifar-log-info", {"--check", empty_log});
  EXPECT_EQ(empty.exit_code, 1) << empty.output;
  EXPECT_TRUE(contains(empty.output, "check: " + empty_log + " holds no events")) << empty.output;
}

TEST_F(LogTools, RunSummaryUsesTheEventsBeforeTheCorruptionOrFailsNamingFileAndOffset)
{
  Bytes bytes = sampleEvent("POSE", 0);
  append(bytes, sampleEvent("EXEC_STATUS", 1));
  const std::size_t cut_at = bytes.size();
  Bytes last = sampleEvent("POSE", 2);
  last.resize(last.size() / 2);
  append(bytes, last);
  const std::string log = writeLog("run.lcmlog", bytes);
  const ToolRun summary = run("ifar-run-summary", {log, "--goal", "0,0"});
  EXPECT_EQ(summary.exit_code, 0) << summary.output;
  EXPECT_TRUE(contains(summary.output, "arrived:")) << summary.output;
  EXPECT_TRUE(
      contains(summary.output, "warning: '" + log + "' is corrupt, summarised from the 2 events read"))
      << summary.output;
  EXPECT_TRUE(contains(summary.output, "byte " + std::to_string(cut_at) + ": event truncated"))
      << summary.output;

  const std::string huge = writeLog("huge.lcmlog", hugeClaimLog());
  const ToolRun failed = run("ifar-run-summary", {huge, "--goal", "0,0", "--json"});
  EXPECT_EQ(failed.exit_code, 2) << failed.output;
  EXPECT_TRUE(contains(failed.output, "error: '" + huge + "': no LCM event could be read")) << failed.output;
  EXPECT_TRUE(contains(failed.output, kHugeClaimProblem)) << failed.output;
}

TEST_F(LogTools, RenderGraphDrawsFromTheEventsBeforeTheCorruptionOrFailsNamingFileAndOffset)
{
  Bytes bytes = sampleEvent("DV_GRAPH", 0);
  const std::size_t bad_at = bytes.size();
  append(bytes, eventHeader(1, 2, 8, 1'000'000'000));  // claims 1 GB: liblcm tried to malloc it
  append(bytes, Bytes{'D', 'V', '_', 'G', 'R', 'A', 'P', 'H'});
  const std::string log = writeLog("graph.lcmlog", bytes);
  const std::string png = (directory_.path() / "graph.png").string();
  const ToolRun drawn = run("ifar-render-graph", {log, "-o", png});
  EXPECT_EQ(drawn.exit_code, 0) << drawn.output;
  EXPECT_TRUE(std::filesystem::exists(png));
  EXPECT_TRUE(contains(drawn.output, "warning: " + log + " is corrupt")) << drawn.output;
  EXPECT_TRUE(contains(drawn.output, "byte " + std::to_string(bad_at) + ": event truncated")) << drawn.output;

  const std::string huge = writeLog("huge.lcmlog", hugeClaimLog());
  const ToolRun failed = run("ifar-render-graph", {huge, "-o", png});
  EXPECT_EQ(failed.exit_code, 2) << failed.output;
  EXPECT_TRUE(contains(failed.output, "error: " + huge + ": no LCM event could be read")) << failed.output;
  EXPECT_TRUE(contains(failed.output, kHugeClaimProblem)) << failed.output;
}

/// The sample message of `channel` with the int32 at `offset` (from the fingerprint on) set to -1: an
/// array that claims a negative length, which makes LCM's generated decode throw std::length_error.
Bytes negativeLengthEvent(const std::string& channel, std::size_t offset, std::int64_t number)
{
  for (const auto& sample : lcmtypes_samples::allSampleMessages()) {
    if (sample.channel == channel) {
      Bytes message = sample.encoded;
      for (std::size_t index = 0; index < 4; ++index) {
        message.at(offset + index) = 0xff;
      }
      return eventBytes(number, 1'700'000'000'000'000 + number * 100'000, channel, message);
    }
  }
  ADD_FAILURE() << "no sample on " << channel;
  return {};
}

// A well-framed event whose message claims a negative array length: counted as undecodable, never a crash
// (log-info aborted on the std::length_error).
TEST_F(LogTools, AMessageClaimingANegativeArrayLengthIsUndecodableNotACrash)
{
  constexpr std::size_t kPacketSizeOffset = 8 + 8 + 4 + 4;  // fingerprint, utime, device time, port
  constexpr std::size_t kWaypointCountOffset = 8 + 8 + 8 + 8 + 1 + 8 + 8;  // ... utime, goal, sequence,
                                                                           // valid, length, cost
  const std::string packets =
      writeLog("negative.lcmlog", negativeLengthEvent("VELODYNE_PACKET", kPacketSizeOffset, 0));
  const ToolRun check = run("ifar-log-info", {"--check", packets});
  EXPECT_EQ(check.exit_code, 1) << check.output;
  EXPECT_TRUE(contains(check.output, "1 messages on 1 channels")) << check.output;

  Bytes bytes = sampleEvent("DV_GRAPH", 0);
  append(bytes, negativeLengthEvent("GLOBAL_PATH", kWaypointCountOffset, 1));
  const std::string log = writeLog("negative-path.lcmlog", bytes);
  const std::string png = (directory_.path() / "negative-path.png").string();
  const ToolRun drawn = run("ifar-render-graph", {log, "-o", png});
  EXPECT_EQ(drawn.exit_code, 0) << drawn.output;
  EXPECT_TRUE(contains(drawn.output, "1 messages did not decode and were skipped")) << drawn.output;
}

}  // namespace
}  // namespace ifar::lcm_log::test
