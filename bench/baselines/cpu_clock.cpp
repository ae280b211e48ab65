#include "bench/baselines/cpu_clock.hpp"

#include <ctime>

namespace ifar::baselines {

double threadCpuMilliseconds()
{
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) * 1e3 + static_cast<double>(now.tv_nsec) * 1e-6;
}

}  // namespace ifar::baselines
