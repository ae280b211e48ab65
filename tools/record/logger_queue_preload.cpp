// Loaded into lcm-logger by `ifar record` (LD_PRELOAD): lcm-logger subscribes with LCM's default queue of
// 30 messages, and LCM drops every message that arrives while 30 wait for the logger's main thread. A
// driver that was kept off the CPU for a moment publishes its backlog at once; in such a burst lcm-logger
// 1.3.1 lost 428 of 500 lidar-sized messages that the daemons (queue 200) took, and a log with holes no
// longer replays. This wraps lcm_subscribe to give each subscription the capacity in
// IFAR_LOGGER_QUEUE_MESSAGES (LCM's own setting, the one the daemons' run loops use); without that
// variable, or with one that is not a whole number from 1 to 10,000,000, the subscription is left as LCM
// made it.

#include <dlfcn.h>
#include <lcm/lcm.h>

#include <cerrno>
#include <cstdlib>

namespace {

constexpr long kMostMessages = 10'000'000;

/// The capacity the recorder asked for, or 0 when none (or none usable) was.
int requestedCapacity()
{
  const char* text = std::getenv("IFAR_LOGGER_QUEUE_MESSAGES");
  if (text == nullptr || *text == '\0') {
    return 0;
  }
  char* end = nullptr;
  errno = 0;
  const long value = std::strtol(text, &end, 10);
  if (errno != 0 || *end != '\0' || value < 1 || value > kMostMessages) {
    return 0;
  }
  return static_cast<int>(value);
}

}  // namespace

extern "C" lcm_subscription_t* lcm_subscribe(lcm_t* lcm, const char* channel, lcm_msg_handler_t handler,
                                             void* userdata)
{
  using Subscribe = lcm_subscription_t* (*)(lcm_t*, const char*, lcm_msg_handler_t, void*);
  // The next definition after this library: liblcm's.
  const auto subscribe = reinterpret_cast<Subscribe>(dlsym(RTLD_NEXT, "lcm_subscribe"));
  if (subscribe == nullptr) {
    return nullptr;
  }
  lcm_subscription_t* subscription = subscribe(lcm, channel, handler, userdata);
  const int capacity = requestedCapacity();
  if (subscription != nullptr && capacity > 0) {
    lcm_subscription_set_queue_capacity(subscription, capacity);
  }
  return subscription;
}
