#include "bus/run_loop.hpp"

#include <poll.h>
#include <signal.h>
#include <sys/signalfd.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

#include "bus/lcm_url.hpp"
#include "common/signals.hpp"
#include "common/time.hpp"

namespace ifar::bus {
namespace {

constexpr std::int64_t kErrorLogIntervalUs = 1'000'000;
// Messages waiting per subscription before LCM drops more: about 0.27 s of VLP-16 packets (754/s). A loop
// stalled that long loses nothing; one that falls behind for good still works on inputs younger than the
// executive's staleness limits (0.5 s for obstacle points), instead of on an ever older backlog.
constexpr int kSubscriptionQueueCapacity = 200;

// Carries a handler through LCM's C callback (the C++ member-function template trips UBSan's vptr check).
class RawSubscriber {
 public:
  explicit RawSubscriber(std::function<void(const lcm::ReceiveBuffer*, const std::string&)> handler)
      : handler_(std::move(handler))
  {
  }
  static void dispatch(const lcm_recv_buf_t* buffer, const char* channel, void* user)
  {
    const lcm::ReceiveBuffer receive{buffer->data, buffer->data_size, buffer->recv_utime};
    static_cast<RawSubscriber*>(user)->handler_(&receive, channel);
  }

 private:
  std::function<void(const lcm::ReceiveBuffer*, const std::string&)> handler_;
};

sigset_t terminationSignals()
{
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  return signals;
}

}  // namespace

std::string resolveLcmUrl(const std::string& configured)
{
  if (!configured.empty()) {
    return configured;
  }
  const char* environment = std::getenv("LCM_DEFAULT_URL");
  return environment != nullptr ? std::string(environment) : std::string();
}

struct RunLoop::Subscribers {
  std::vector<std::unique_ptr<RawSubscriber>> list;
};

RunLoop::RunLoop(const std::string& url, std::shared_ptr<spdlog::logger> logger, ManualClock manual_clock)
    : lcm_(withReceiveBuffer(resolveLcmUrl(url), kReceiveBufferBytes)),
      logger_(std::move(logger)),
      manual_clock_(std::move(manual_clock)),
      subscribers_(std::make_unique<Subscribers>())
{
  if (!lcm_.good()) {
    throw std::runtime_error("cannot start LCM on URL '" +
                             (resolveLcmUrl(url).empty() ? std::string("(default)") : resolveLcmUrl(url)) +
                             "' (is multicast routed? see docs/deploy.md)");
  }
  if (!signals_blocked_) {
    throw std::runtime_error("cannot block SIGINT/SIGTERM for the run loop");
  }
  // Signals (blocked since before LCM started) become readable events on a file descriptor.
  const sigset_t signals = terminationSignals();
  signal_fd_ = signalfd(-1, &signals, SFD_NONBLOCK | SFD_CLOEXEC);
  if (signal_fd_ < 0) {
    throw std::runtime_error("cannot create a signalfd for SIGINT/SIGTERM");
  }
}

bool RunLoop::blockTerminationSignals()
{
  const sigset_t signals = terminationSignals();
  common::restoreDefaultActions(signals);
  return pthread_sigmask(SIG_BLOCK, &signals, nullptr) == 0;
}

RunLoop::~RunLoop()
{
  if (signal_fd_ >= 0) {
    close(signal_fd_);
  }
}

void RunLoop::subscribeRaw(const std::string& channel,
                           std::function<void(const lcm::ReceiveBuffer*, const std::string&)> handler)
{
  auto subscriber = std::make_unique<RawSubscriber>(std::move(handler));
  lcm_subscription_t* subscription =
      lcm_subscribe(lcm_.getUnderlyingLCM(), channel.c_str(), &RawSubscriber::dispatch, subscriber.get());
  if (subscription == nullptr) {
    throw std::runtime_error("cannot subscribe to channel '" + channel + "'");
  }
  // LCM's own limit, 30 waiting messages, is 40 ms of VLP-16 packets: a loop not scheduled for that long
  // on a busy machine would lose packets.
  lcm_subscription_set_queue_capacity(subscription, kSubscriptionQueueCapacity);
  subscribers_->list.push_back(std::move(subscriber));
}

void RunLoop::guard(const std::string& channel, const std::function<void()>& body)
{
  // Nothing may unwind into LCM's C code: every exception is caught, counted and logged.
  std::string problem;
  try {
    body();
    return;
  } catch (const std::exception& error) {
    problem = error.what();
  } catch (...) {
    problem = "an exception that is not a std::exception";
  }
  ++handler_errors_;
  const std::int64_t now = common::monotonicMicroseconds();
  if (now - last_error_log_us_ >= kErrorLogIntervalUs) {
    last_error_log_us_ = now;
    logger_->error("handler for {} failed: {} ({} handler errors so far)", channel, problem, handler_errors_);
  }
}

void RunLoop::reportBadMessage(const std::string& channel, const std::string& problem)
{
  ++bad_messages_;
  const std::int64_t now = common::monotonicMicroseconds();
  if (now - last_error_log_us_ >= kErrorLogIntervalUs) {
    last_error_log_us_ = now;
    logger_->warn("skipping a message on {}: {} ({} bad messages so far)", channel, problem, bad_messages_);
  }
}

void RunLoop::every(double period_seconds, std::function<void()> callback)
{
  const std::int64_t period_us = std::max<std::int64_t>(1, common::secondsToMicroseconds(period_seconds));
  timers_.push_back(Timer{period_us, timerNow() + period_us, std::move(callback)});
}

std::int64_t RunLoop::now() const
{
  return manual_clock_ ? manual_clock_() : common::nowMicroseconds();
}

std::int64_t RunLoop::timerNow() const
{
  return manual_clock_ ? manual_clock_() : common::monotonicMicroseconds();
}

void RunLoop::runDueTimers()
{
  const std::int64_t now = timerNow();
  for (auto& timer : timers_) {
    if (now >= timer.next_due_us) {
      // Skip missed periods instead of bursting to catch up after a stall.
      timer.next_due_us += timer.period_us * (1 + (now - timer.next_due_us) / timer.period_us);
      guard("timer", timer.callback);
    }
  }
}

int RunLoop::nextTimeoutMs() const
{
  std::int64_t timeout_us = 100'000;
  const std::int64_t now = timerNow();
  for (const auto& timer : timers_) {
    timeout_us = std::min(timeout_us, std::max<std::int64_t>(0, timer.next_due_us - now));
  }
  return static_cast<int>((timeout_us + 999) / 1000);
}

void RunLoop::spinOnce(int timeout_ms)
{
  pollfd descriptors[2] = {{lcm_.getFileno(), POLLIN, 0}, {signal_fd_, POLLIN, 0}};
  const int ready = poll(descriptors, 2, timeout_ms);
  if (ready > 0) {
    if ((descriptors[1].revents & POLLIN) != 0) {
      signalfd_siginfo info{};
      if (read(signal_fd_, &info, sizeof(info)) == static_cast<ssize_t>(sizeof(info))) {
        logger_->info("received signal {}, shutting down", info.ssi_signo);
        stopping_ = true;
      }
    }
    if ((descriptors[0].revents & POLLIN) != 0) {
      lcm_.handleTimeout(0);
    }
  }
  runDueTimers();
}

void RunLoop::deliverPending()
{
  while (lcm_.handleTimeout(0) > 0) {
  }
}

int RunLoop::run()
{
  while (!stopping_) {
    spinOnce(nextTimeoutMs());
  }
  return 0;
}

}  // namespace ifar::bus
