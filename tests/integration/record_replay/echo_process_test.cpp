// ifar echo as a process: the exact JSON and text of known messages from a log, --count, what does not
// decode skipped and counted, a corrupt log stopped at its offset with exit code 2; and live from a private
// LCM URL.

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lcmtypes/samples/sample_messages.hpp"
#include "testing/child_process.hpp"
#include "testing/temporary_directory.hpp"
#include "tests/integration/record_replay/tool_test_support.hpp"

namespace ifar::record_replay_test {
namespace {

using test_support::ChildOptions;
using test_support::ChildProcess;

const char* const kPoseMessage =
    "\"message\":{\"utime\":1763800000123456,\"position\":[10.5,-4.25,0.125],"
    "\"orientation\":[0.9238795325112867,0,0,0.3826834323650898],\"velocity\":[0.5,0.25,0],"
    "\"angular_velocity\":[0,0,0.3]}}";
const char* const kGoalMessage =
    "\"message\":{\"utime\":1763800000123456,\"goal_id\":5,\"x\":14.75,\"y\":9.5,\"cancel\":false}}";

std::vector<std::string> linesOf(const std::string& text)
{
  std::vector<std::string> lines;
  std::size_t start = 0;
  std::size_t end = 0;
  while ((end = text.find('\n', start)) != std::string::npos) {
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

std::vector<std::uint8_t> sampleBytes(const std::string& channel)
{
  for (const auto& sample : lcmtypes_samples::allSampleMessages()) {
    if (sample.channel == channel) {
      return sample.encoded;
    }
  }
  return {};
}

class EchoProcess : public ::testing::Test {
 protected:
  void SetUp() override
  {
    for (const auto& sample : lcmtypes_samples::allSampleMessages()) {
      events_.push_back(Received{sample.channel, sample.encoded});
    }
    events_.push_back(Received{"POSE", {1, 2, 3, 4, 5, 6, 7, 8, 9}});  // no project type
    ASSERT_TRUE(writeLog(path("samples.lcmlog"), events_));
  }

  std::string path(const std::string& name) const { return (directory_.path() / name).string(); }

  /// Runs ifar echo to its end: its exit code; `output` gets what it printed.
  int echo(const std::vector<std::string>& arguments, std::string& output) const
  {
    std::vector<std::string> command = {toolPath("ifar-echo")};
    command.insert(command.end(), arguments.begin(), arguments.end());
    const int exit_code = test_support::runToEnd(command, ChildOptions{path("echo.out"), "", {}}, 30.0);
    output = test_support::readText(path("echo.out"));
    return exit_code;
  }

  /// The receive time of the event of `channel` in the log (5 ms apart from 1'700'000'000 s on).
  std::string receiveTimeOf(const std::string& channel) const
  {
    for (std::size_t index = 0; index < events_.size(); ++index) {
      if (events_[index].channel == channel) {
        return std::to_string(1'700'000'000'000'000 + 5'000 * static_cast<std::int64_t>(index));
      }
    }
    return "";
  }

  std::vector<Received> events_;
  test_support::TemporaryDirectory directory_{"echo-process-test"};
};

TEST_F(EchoProcess, APoseFromALogAsJsonIsExactAndTheUndecodableOneIsCountedAndSkipped)
{
  std::string output;
  EXPECT_EQ(echo({"POSE", "--log", path("samples.lcmlog"), "--json"}, output), 0) << output;
  const std::vector<std::string> lines = linesOf(output);
  ASSERT_EQ(lines.size(), 3U) << output;
  EXPECT_EQ(lines[0], "{\"channel\":\"POSE\",\"type\":\"pose_t\",\"receive_utime\":" + receiveTimeOf("POSE") +
                          "," + kPoseMessage);
  EXPECT_EQ(lines[1],
            "ifar echo: skipping a message on POSE: not a project type (unknown fingerprint) (1 skipped so "
            "far)");
  EXPECT_EQ(lines[2], "ifar echo: 1 messages shown, 1 skipped");
}

TEST_F(EchoProcess, NestedStructsFromALogAsTextAreExact)
{
  std::string output;
  EXPECT_EQ(echo({"DETECTED_OBJECTS", "--log", path("samples.lcmlog")}, output), 0) << output;
  const std::string time = receiveTimeOf("DETECTED_OBJECTS");
  EXPECT_EQ(output, "--- DETECTED_OBJECTS object_polygons_t received " + time.substr(0, 10) + "." +
                        time.substr(10) +
                        "\n"
                        "  utime: 1763800000123456\n"
                        "  num_polygons: 1\n"
                        "  polygons:\n"
                        "    - id: 7\n"
                        "      kind: 1\n"
                        "      num_points: 4\n"
                        "      x: [3.5, 4.75, 6, 7.25]\n"
                        "      y: [2, 1.25, 0.5, -0.25]\n");
}

TEST_F(EchoProcess, ARegexOfChannelsAndCountStopAfterThatMany)
{
  std::string output;
  EXPECT_EQ(echo({".*", "--log", path("samples.lcmlog"), "--json", "--count", "3"}, output), 0) << output;
  const std::vector<std::string> lines = linesOf(output);
  ASSERT_EQ(lines.size(), 3U) << output;
  EXPECT_EQ(lines[0].rfind("{\"channel\":\"AFFORDANCE\",\"type\":\"affordance_t\",", 0), 0U) << lines[0];
  EXPECT_EQ(lines[1].rfind("{\"channel\":\"BLOCKED_PASSAGE\",\"type\":\"blocked_passage_t\",", 0), 0U)
      << lines[1];
  EXPECT_EQ(lines[2].rfind("{\"channel\":\"CAN_STATUS\",\"type\":\"can_bus_status_t\",", 0), 0U) << lines[2];
}

TEST_F(EchoProcess, ACorruptLogStopsWithExitTwoNamingTheOffset)
{
  std::string bytes = test_support::readText(path("samples.lcmlog"));
  bytes.append(40, '\x11');
  std::ofstream(path("garbage.lcmlog"), std::ios::binary) << bytes;
  std::string output;
  EXPECT_EQ(echo({"SIM_GROUND_TRUTH", "--log", path("garbage.lcmlog"), "--json"}, output), 2) << output;
  // The last event is followed by garbage: it is not shown, and the error names where the garbage starts.
  EXPECT_TRUE(contains(output, "ifar echo: error: '" + path("garbage.lcmlog") + "' is corrupt at byte " +
                                   std::to_string(bytes.size() - 40) + ": bad sync word 0x11111111"))
      << output;
  EXPECT_EQ(linesOf(output).size(), 2U) << output;  // the SIM_GROUND_TRUTH sample, and the error
}

TEST_F(EchoProcess, LiveFromAPrivateUrlItPrintsTheGoalsItHearsAndSkipsWhatIsNoProjectType)
{
  const std::string url = privateUrl(7861);
  BusListener bus(url, "NOTHING");
  ChildProcess child({toolPath("ifar-echo"), "GOAL", "--json", "--count", "2", "--lcm-url", url},
                     ChildOptions{path("live.out"), "", {}});
  const std::vector<std::uint8_t> goal = sampleBytes("GOAL");
  const std::vector<std::uint8_t> garbage = {9, 9, 9, 9, 9, 9, 9, 9, 9};
  std::optional<int> exit_code;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(15);
  while (!exit_code && std::chrono::steady_clock::now() < deadline) {
    bus.lcm().publish("GOAL", garbage.data(), static_cast<unsigned int>(garbage.size()));
    bus.lcm().publish("GOAL", goal.data(), static_cast<unsigned int>(goal.size()));
    bus.spin(0.05);
    exit_code = child.waitFor(0.0);
  }
  const std::string output = test_support::readText(path("live.out"));
  EXPECT_EQ(exit_code, 0) << output;
  std::vector<std::string> goals;
  for (const std::string& line : linesOf(output)) {
    if (line.rfind('{', 0) == 0) {
      goals.push_back(line);
    }
  }
  ASSERT_EQ(goals.size(), 2U) << output;
  for (const std::string& line : goals) {
    EXPECT_EQ(line.rfind("{\"channel\":\"GOAL\",\"type\":\"goal_t\",\"receive_utime\":", 0), 0U) << line;
    EXPECT_EQ(line.substr(line.size() - std::string(kGoalMessage).size()), kGoalMessage) << line;
  }
  EXPECT_TRUE(
      contains(output, "ifar echo: skipping a message on GOAL: not a project type (unknown fingerprint)"))
      << output;
}

}  // namespace
}  // namespace ifar::record_replay_test
