#pragma once
// The LCM adapter every daemon uses: one lcm::LCM, typed subscriptions whose handlers never throw into
// LCM's C code, periodic timers, and a clean exit on SIGINT/SIGTERM (taken through a signalfd, so no
// global state). Only daemons and tools include this; libraries stay free of LCM.

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <spdlog/spdlog.h>
#include <lcm/lcm-cpp.hpp>

#include "common/span.hpp"
#include "lcmtypes/checked_decode.hpp"

namespace ifar::bus {

/// The URL to use: `configured` when not empty, else LCM_DEFAULT_URL when set, else "" (LCM's default
/// udpm://239.255.76.67:7667?ttl=0).
std::string resolveLcmUrl(const std::string& configured);

/// A clock in microseconds that a test sets by hand (replaying a log on its own times).
using ManualClock = std::function<std::int64_t()>;

class RunLoop {
 public:
  /// Blocks SIGINT and SIGTERM for the calling thread (and threads it starts later) and connects to LCM.
  /// Throws std::runtime_error naming the URL when LCM cannot start. Without `manual_clock` the loop runs
  /// on the system's clocks: messages carry LCM's receive time, now() is the wall clock, timers follow the
  /// monotonic clock. With one, all three are its time, so a test replays inputs deterministically
  /// (deliverPending, then runDueTimers, at each time it sets).
  RunLoop(const std::string& url, std::shared_ptr<spdlog::logger> logger, ManualClock manual_clock = {});
  ~RunLoop();
  RunLoop(const RunLoop&) = delete;
  RunLoop& operator=(const RunLoop&) = delete;

  /// Calls handler(message, receive_utime) for each message on `channel` that decodes as Message.
  /// Undecodable messages and exceptions thrown by the handler are logged (rate limited) and counted.
  template <typename Message>
  void subscribe(const std::string& channel,
                 std::function<void(const Message&, std::int64_t receive_utime)> handler)
  {
    auto callback = [this, channel, handler = std::move(handler)](const lcm::ReceiveBuffer* buffer,
                                                                  const std::string& /*channel*/) {
      Message message;
      const lcmtypes::DecodeResult decoded = lcmtypes::decodeLcm(message, buffer->data, buffer->data_size);
      if (!decoded.ok()) {
        reportBadMessage(channel, "does not decode as " + std::string(Message::getTypeName()) +
                                      (decoded.error.empty() ? "" : ": " + decoded.error));
        return;
      }
      const std::int64_t receive_utime = manual_clock_ ? manual_clock_() : buffer->recv_utime;
      guard(channel, [&] {
        if (input_observer_) {
          input_observer_(channel,
                          common::ByteView(static_cast<const std::uint8_t*>(buffer->data), buffer->data_size),
                          receive_utime);
        }
        handler(message, receive_utime);
      });
    };
    subscribeRaw(channel, std::move(callback));
  }

  /// Called with every message a typed subscription decoded, just before its handler (a daemon's journal,
  /// bus/node_journal_publisher.hpp); empty: none. One at a time.
  using InputObserver =
      std::function<void(const std::string& channel, common::ByteView bytes, std::int64_t receive_utime)>;
  void observeInputs(InputObserver observer) { input_observer_ = std::move(observer); }

  /// Calls handler(bytes, size, receive_utime) for raw messages on `channel` (a regex, as LCM takes).
  void subscribeRaw(const std::string& channel,
                    std::function<void(const lcm::ReceiveBuffer*, const std::string&)> handler);

  template <typename Message>
  void publish(const std::string& channel, const Message& message)
  {
    if (lcm_.publish(channel, &message) != 0) {
      ++publish_errors_;
    }
  }

  /// Runs `callback` every `period_seconds` from the loop (first call one period after run() starts).
  void every(double period_seconds, std::function<void()> callback);

  /// Handles messages and timers until SIGINT/SIGTERM or stop(). Returns 0 on a signal or stop().
  int run();
  /// Handles what is pending for at most `timeout_ms` (for tests and custom loops).
  void spinOnce(int timeout_ms);
  /// Handles every message already waiting, without running timers (tests on a manual clock).
  void deliverPending();
  /// Runs the timers that are due now (spinOnce does this itself).
  void runDueTimers();
  /// Microseconds since the epoch on the wall clock, or the manual clock's time.
  std::int64_t now() const;
  /// Ends run() after the current handler.
  void stop() { stopping_ = true; }
  bool stopping() const { return stopping_; }

  lcm::LCM& lcm() { return lcm_; }
  spdlog::logger& logger() const { return *logger_; }
  std::int64_t handlerErrors() const { return handler_errors_; }
  std::int64_t badMessages() const { return bad_messages_; }
  std::int64_t publishErrors() const { return publish_errors_; }

 private:
  struct Timer {
    std::int64_t period_us;
    std::int64_t next_due_us;
    std::function<void()> callback;
  };
  void guard(const std::string& channel, const std::function<void()>& body);
  void reportBadMessage(const std::string& channel, const std::string& problem);
  /// The timers' clock: monotonic, or the manual clock.
  std::int64_t timerNow() const;
  int nextTimeoutMs() const;

  struct Subscribers;
  /// Blocks SIGINT/SIGTERM before LCM starts, so no thread LCM creates can take them with the default
  /// action; they are read from signal_fd_ instead.
  static bool blockTerminationSignals();
  bool signals_blocked_ = blockTerminationSignals();
  lcm::LCM lcm_;
  std::shared_ptr<spdlog::logger> logger_;
  ManualClock manual_clock_;
  InputObserver input_observer_;
  std::unique_ptr<Subscribers> subscribers_;  // owns the objects LCM calls back into
  int signal_fd_ = -1;
  bool stopping_ = false;
  std::vector<Timer> timers_;
  std::int64_t handler_errors_ = 0;
  std::int64_t bad_messages_ = 0;
  std::int64_t publish_errors_ = 0;
  std::int64_t last_error_log_us_ = 0;
};

}  // namespace ifar::bus
