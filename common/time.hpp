#pragma once
// Microsecond time, the unit of every utime field on the bus.

#include <cstdint>

namespace ifar::common {

/// Microseconds since the Unix epoch, from the wall clock (what LCM messages carry in utime).
std::int64_t nowMicroseconds();

/// Microseconds from a monotonic clock with an arbitrary origin: for timeouts and durations only.
std::int64_t monotonicMicroseconds();

constexpr std::int64_t kMicrosecondsPerSecond = 1'000'000;

constexpr double microsecondsToSeconds(std::int64_t microseconds)
{
  return static_cast<double>(microseconds) * 1e-6;
}

constexpr std::int64_t secondsToMicroseconds(double seconds)
{
  return static_cast<std::int64_t>(seconds * 1e6);
}

}  // namespace ifar::common
