#pragma once
// CPU time of the calling thread. The comparison runs on shared, loaded machines, so search times and
// the sampling planners' time cap are measured in the planner thread's CPU time, not wall time.

namespace ifar::baselines {

/// Milliseconds of CPU time the calling thread has used (CLOCK_THREAD_CPUTIME_ID).
double threadCpuMilliseconds();

}  // namespace ifar::baselines
