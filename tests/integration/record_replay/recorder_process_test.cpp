// ifar record as a process with the real lcm-logger on a private LCM URL: --channels records only the
// matching channel under the strftime-formatted name; the heartbeat "recorder" says ERROR when lcm-logger is
// stopped (its file stops growing while messages arrive), OK when it goes on, ERROR naming the signal when it
// is killed (and ifar record exits 1), and ERROR when the disk is full; a burst of messages published at
// once is recorded whole.

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bus/lcm_url.hpp"
#include "common/lcm_log/log_reader.hpp"
#include "ifar/heartbeat_t.hpp"
#include "lcmtypes/checked_decode.hpp"
#include "testing/child_process.hpp"
#include "testing/temporary_directory.hpp"
#include "tests/integration/record_replay/tool_test_support.hpp"

namespace ifar::record_replay_test {
namespace {

using test_support::ChildOptions;
using test_support::ChildProcess;

/// The recorder's heartbeats as the bus carries them, newest last.
std::vector<heartbeat_t> recorderBeats(const BusListener& listener, pid_t recorder)
{
  std::vector<heartbeat_t> beats;
  for (const Received& message : listener.received()) {
    heartbeat_t beat;
    if (message.channel == "HEARTBEAT" &&
        lcmtypes::decodeLcm(beat, message.data.data(), message.data.size()).ok() &&
        beat.process == "recorder" && beat.pid == recorder) {
      beats.push_back(beat);
    }
  }
  return beats;
}

/// How many messages `log` holds on `channel`; 0 when it cannot be read.
int countOn(const std::string& log, const std::string& channel)
{
  lcm_log::LogReader reader = lcm_log::LogReader::open(log);
  lcm_log::LogEvent event;
  int count = 0;
  while (reader.openError().empty() && reader.next(event)) {
    count += event.channel == channel ? 1 : 0;
  }
  return count;
}

class RecorderProcess : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return (directory_.path() / name).string(); }
  std::string output() const { return test_support::readText(path("record.out")); }

  /// Publishes `bytes` on `channel` every 20 ms while handling messages, until `done` (at most `seconds`).
  static bool publishUntil(BusListener& bus, const std::string& channel,
                           const std::vector<std::uint8_t>& bytes, double seconds,
                           const std::function<bool()>& done)
  {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < deadline) {
      if (done()) {
        return true;
      }
      bus.lcm().publish(channel, bytes.data(), static_cast<unsigned int>(bytes.size()));
      bus.spin(0.02);
    }
    return done();
  }

  /// True once the newest beat of the recorder has `level` and a message containing `part`.
  static std::function<bool()> beatSays(const BusListener& bus, pid_t recorder, std::int8_t level,
                                        const std::string& part)
  {
    return [&bus, recorder, level, part] {
      const std::vector<heartbeat_t> beats = recorderBeats(bus, recorder);
      return !beats.empty() && beats.back().health == level && contains(beats.back().message, part);
    };
  }

  /// Records with `queue_option` (ifar record's --queue-messages), publishes `burst` lidar-sized messages as
  /// fast as the test can once lcm-logger records, and returns how many of them the log holds.
  static int recordedOfABurst(const std::string& folder, const std::string& url,
                              const std::string& queue_option, int burst, std::string& output)
  {
    const std::string output_path = folder + ".out";
    BusListener bus(url, "HEARTBEAT");
    ChildProcess recorder({toolPath("ifar-record"), "--dir", folder, "--name", "burst.lcmlog", "--split-mb",
                           "0", "--lcm-url", url, "--queue-messages", queue_option},
                          ChildOptions{output_path, "", {}});
    const std::string log = folder + "/burst.lcmlog.00";
    // lcm-logger subscribes some time after it starts.
    const std::vector<std::uint8_t> probe = {1};
    publishUntil(bus, "PROBE", probe, 20.0, [&log] { return countOn(log, "PROBE") > 0; });
    std::vector<std::uint8_t> packet(1234, 0);
    for (int index = 0; index < burst; ++index) {
      packet[0] = static_cast<std::uint8_t>(index);
      bus.lcm().publish("BURST", packet.data(), static_cast<unsigned int>(packet.size()));
    }
    // Until lcm-logger has written what it kept: the count stays the same for half a second.
    int recorded = -1;
    for (int count = countOn(log, "BURST"), tries = 0; count != recorded && tries < 40; ++tries) {
      recorded = count;
      bus.spin(0.5);
      count = countOn(log, "BURST");
    }
    recorder.stop(SIGINT);
    output = test_support::readText(output_path);
    return countOn(log, "BURST");
  }

  test_support::TemporaryDirectory directory_{"recorder-process-test"};
};

TEST_F(RecorderProcess, ChannelsRecordsOnlyTheMatchingChannelUnderItsStrftimeName)
{
  const std::string url = privateUrl(7851);
  BusListener bus(url, "HEARTBEAT");
  ChildProcess recorder({toolPath("ifar-record"), "--dir", path("logs"), "--name", "kept-%Y.lcmlog",
                         "--split-mb", "0", "--channels", "KEEP_ME", "--lcm-url", url},
                        ChildOptions{path("record.out"), "", {}});
  const pid_t recorder_pid = recorder.pid();
  char year[8];
  const std::time_t now = std::time(nullptr);
  std::strftime(year, sizeof(year), "%Y", std::localtime(&now));
  const std::string log = path("logs") + "/kept-" + year + ".lcmlog.00";
  std::map<std::string, int> recorded;
  const auto countRecorded = [&] {
    recorded.clear();
    lcm_log::LogReader reader = lcm_log::LogReader::open(log);
    lcm_log::LogEvent event;
    while (reader.openError().empty() && reader.next(event)) {
      ++recorded[event.channel];
    }
    return recorded["KEEP_ME"] >= 20;
  };
  // Both channels in turn until lcm-logger (subscribed some time after it started) has 20 of the kept one.
  const std::vector<std::uint8_t> payload = {1, 2, 3};
  bool enough = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (!enough && std::chrono::steady_clock::now() < deadline) {
    bus.lcm().publish("KEEP_ME", payload.data(), 3);
    bus.lcm().publish("DROP_ME", payload.data(), 3);
    bus.spin(0.02);
    // And the recorder's own heartbeat on the bus, which is no match either.
    enough = countRecorded() && !recorderBeats(bus, recorder_pid).empty();
  }
  EXPECT_EQ(recorder.stop(SIGINT), 0) << output();
  countRecorded();
  EXPECT_GE(recorded["KEEP_ME"], 20) << output();
  EXPECT_EQ(recorded.size(), 1U) << "channels recorded: " << recorded.size() << "\n" << output();
  EXPECT_EQ(recorded.count("DROP_ME"), 0U);
  EXPECT_EQ(recorded.count("HEARTBEAT"), 0U);
  EXPECT_TRUE(contains(output(), "Opening log file \"" + log + "\"")) << output();
}

TEST_F(RecorderProcess, HeartbeatSaysErrorWhenTheLoggerStopsWritingOkWhenItGoesOnAndErrorWhenKilled)
{
  const std::string url = privateUrl(7852);
  BusListener bus(url, "HEARTBEAT");
  ChildProcess recorder(
      {toolPath("ifar-record"), "--dir", path("logs"), "--stall-seconds", "1", "--lcm-url", url},
      ChildOptions{path("record.out"), "", {}});
  const pid_t recorder_pid = recorder.pid();
  const std::vector<std::uint8_t> payload(200, 7);
  ASSERT_TRUE(
      publishUntil(bus, "SOME_DATA", payload, 10.0, beatSays(bus, recorder_pid, heartbeat_t::HEALTH_OK, "")))
      << output();
  const std::vector<pid_t> children = childrenOf(recorder_pid);
  ASSERT_EQ(children.size(), 1U) << output();
  const pid_t logger = children.front();
  bus.spin(1.2);  // lcm-logger has subscribed by now: its file grows with the data

  kill(logger, SIGSTOP);
  EXPECT_TRUE(publishUntil(bus, "SOME_DATA", payload, 5.0,
                           beatSays(bus, recorder_pid, heartbeat_t::HEALTH_ERROR, "has not grown for")))
      << output();
  kill(logger, SIGCONT);
  EXPECT_TRUE(
      publishUntil(bus, "SOME_DATA", payload, 5.0, beatSays(bus, recorder_pid, heartbeat_t::HEALTH_OK, "")))
      << output();

  kill(logger, SIGKILL);
  EXPECT_TRUE(publishUntil(bus, "SOME_DATA", payload, 3.0,
                           beatSays(bus, recorder_pid, heartbeat_t::HEALTH_ERROR,
                                    "lcm-logger killed by signal 9 (Killed): nothing is recorded")))
      << output();
  EXPECT_EQ(recorder.waitFor(3.0), 1) << output();
  const std::vector<heartbeat_t> beats = recorderBeats(bus, recorder_pid);
  ASSERT_GE(beats.size(), 3U);
  for (std::size_t index = 1; index < beats.size(); ++index) {
    EXPECT_EQ(beats[index].sequence, beats[index - 1].sequence + 1);
  }
}

TEST_F(RecorderProcess, ABurstOfMessagesIsRecordedWhole)
{
  // Packets of a VLP-16's size at once, as a driver publishes its backlog after it was held up: LCM's own
  // queue of 30 for lcm-logger loses most of them, the recorder's loses none. At most as many as the
  // kernel's receive buffer holds (net.core.rmem_max caps the 4 MB the recorder asks for, and the kernel
  // doubles it; a datagram takes up to 4 kB of it), so that only LCM's queue can lose any.
  std::istringstream rmem_max(test_support::readText("/proc/sys/net/core/rmem_max"));
  long buffer_cap = 212992;  // Linux's default when the file cannot be read
  rmem_max >> buffer_cap;
  const long buffer_bytes = 2 * std::min(buffer_cap, bus::kReceiveBufferBytes);
  const int burst = static_cast<int>(std::clamp(buffer_bytes / 4096, 100L, 1500L));
  std::string output;
  EXPECT_EQ(recordedOfABurst(path("queued"), privateUrl(7855), "5000", burst, output), burst) << output;
  EXPECT_TRUE(contains(output, "queue of 5000 messages")) << output;
  EXPECT_LT(recordedOfABurst(path("default"), privateUrl(7856), "0", burst, output), burst) << output;
  EXPECT_TRUE(contains(output, "queue of 30 messages")) << output;
}

TEST_F(RecorderProcess, HeartbeatSaysErrorWhenTheDiskIsFull)
{
  if (geteuid() != 0 || !std::filesystem::exists("/usr/bin/unshare")) {
    GTEST_SKIP() << "a full disk needs a private tmpfs: root and unshare (util-linux)";
  }
  const std::string url = privateUrl(7853);
  BusListener bus(url, "HEARTBEAT");
  std::filesystem::create_directories(path("full"));
  // A 64 kB file system of the recorder's own (a private mount namespace: nothing outside sees it).
  ChildProcess recorder(
      {"/usr/bin/unshare", "-m", "/bin/sh", "-c",
       "mount -t tmpfs -o size=64k tmpfs \"$0\" && exec \"$1\" --dir \"$0\" --lcm-url \"$2\"", path("full"),
       toolPath("ifar-record"), url},
      ChildOptions{path("record.out"), "", {}});
  const pid_t recorder_pid = recorder.pid();  // unshare and sh exec into ifar-record
  const std::vector<std::uint8_t> payload(2000, 1);
  EXPECT_TRUE(publishUntil(bus, "BULK", payload, 15.0, [&] {
    for (const heartbeat_t& beat : recorderBeats(bus, recorder_pid)) {
      if (beat.health == heartbeat_t::HEALTH_ERROR) {
        return true;
      }
    }
    return false;
  })) << output();
  const std::vector<heartbeat_t> beats = recorderBeats(bus, recorder_pid);
  ASSERT_FALSE(beats.empty()) << output();
  // lcm-logger 1.3.1 ends on a failed write; a logger that kept running would show as a file not growing.
  EXPECT_TRUE(contains(beats.back().message, "lcm-logger exited with code 1: nothing is recorded") ||
              contains(beats.back().message, "has not grown for"))
      << beats.back().message;
  EXPECT_TRUE(contains(output(), "No space left on device")) << output();
  EXPECT_EQ(recorder.waitFor(5.0), 1) << output();
}

}  // namespace
}  // namespace ifar::record_replay_test
