#include "common/time.hpp"

#include <chrono>

namespace ifar::common {

std::int64_t nowMicroseconds()
{
  using std::chrono::duration_cast;
  using std::chrono::microseconds;
  return duration_cast<microseconds>(std::chrono::system_clock::now().time_since_epoch()).count();
}

std::int64_t monotonicMicroseconds()
{
  using std::chrono::duration_cast;
  using std::chrono::microseconds;
  return duration_cast<microseconds>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace ifar::common
