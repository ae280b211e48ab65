#pragma once
// For the record, replay and echo process tests: a private LCM bus in the test process that keeps every
// message it receives (channel and bytes, in arrival order), the tools' paths, logs written event by event,
// and the children of a process.

#include <lcm/lcm.h>

#include <sys/types.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "common/lcm_log/log_writer.hpp"
#include "testing/child_process.hpp"

namespace ifar::record_replay_test {

struct Received {
  std::string channel;
  std::vector<std::uint8_t> data;
  bool operator==(const Received& other) const { return channel == other.channel && data == other.data; }
};

/// A URL of its own for each test (parallel tests must not hear each other).
inline std::string privateUrl(int port)
{
  return "udpm://239.255.76.67:" + std::to_string(port) + "?ttl=0";
}

inline std::string toolPath(const std::string& name)
{
  return std::string(IFAR_BINARY_DIR) + "/bin/" + name;
}

class BusListener {
 public:
  /// Subscribes to `channels` (an LCM regex) on `url` at once.
  BusListener(const std::string& url, const std::string& channels) : lcm_(url)
  {
    lcm_subscription_t* subscription =
        lcm_subscribe(lcm_.getUnderlyingLCM(), channels.c_str(), &BusListener::onMessage, this);
    // A replay at full speed sends faster than a test thread takes them; LCM keeps 30 by default.
    lcm_subscription_set_queue_capacity(subscription, 5000);
  }

  bool good() { return lcm_.good(); }
  lcm::LCM& lcm() { return lcm_; }

  /// Handles messages for `seconds`, or until `done()` says so.
  void spin(double seconds, const std::function<bool()>& done = {})
  {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < deadline && !(done && done())) {
      lcm_.handleTimeout(10);
    }
  }

  /// Handles messages until `child` exits (at most `seconds`), then for `drain_s` more: its exit code.
  std::optional<int> spinUntilExit(test_support::ChildProcess& child, double seconds, double drain_s = 0.3)
  {
    std::optional<int> exit_code;
    spin(seconds, [&] { return (exit_code = child.waitFor(0.0)).has_value(); });
    spin(drain_s);
    return exit_code;
  }

  const std::vector<Received>& received() const { return received_; }

 private:
  static void onMessage(const lcm_recv_buf_t* buffer, const char* channel, void* user)
  {
    auto* self = static_cast<BusListener*>(user);
    if (std::string(channel) == "LCM_SELF_TEST") {
      return;
    }
    const auto* bytes = static_cast<const std::uint8_t*>(buffer->data);
    self->received_.push_back(Received{channel, std::vector<std::uint8_t>(bytes, bytes + buffer->data_size)});
  }

  lcm::LCM lcm_;
  std::vector<Received> received_;
};

/// Writes `events` as a log, 5 ms apart from 1'700'000'000 s on.
inline bool writeLog(const std::string& path, const std::vector<Received>& events)
{
  lcm_log::LogWriter writer(path);
  std::int64_t time_us = 1'700'000'000'000'000;
  for (const Received& event : events) {
    if (!writer.write(event.channel, time_us, common::ByteView(event.data))) {
      return false;
    }
    time_us += 5'000;
  }
  return writer.openError().empty();
}

/// The children of process `parent`, from /proc.
inline std::vector<pid_t> childrenOf(pid_t parent)
{
  std::vector<pid_t> children;
  for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) {
      continue;
    }
    const std::string text = test_support::readText((entry.path() / "stat").string());
    // pid (comm) state ppid ...: the command name may hold spaces, so read after its closing parenthesis.
    const std::size_t close = text.rfind(')');
    if (close == std::string::npos) {
      continue;
    }
    std::istringstream fields(text.substr(close + 1));
    std::string state;
    pid_t ppid = 0;
    fields >> state >> ppid;
    if (ppid == parent) {
      children.push_back(static_cast<pid_t>(std::stoi(name)));
    }
  }
  return children;
}

inline bool contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

}  // namespace ifar::record_replay_test
