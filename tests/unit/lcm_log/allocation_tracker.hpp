#pragma once
// The largest single allocation made between start and stop, for the test that the log reader never asks
// for what a corrupt header claims (liblcm 1.3.1 mallocs it). The global operator new is replaced in
// allocation_tracker.cpp, a file of its own so that the compiler does not inline it into callers and take
// its malloc/free pair for a mismatched new/delete.

#include <cstddef>

namespace ifar::lcm_log::test {

void startTrackingAllocations();
/// The largest size passed to operator new since startTrackingAllocations().
std::size_t stopTrackingAllocations();

}  // namespace ifar::lcm_log::test
