#pragma once
// The largest single allocation made between start and stop, for the tests that what a corrupt input
// claims is never allocated: the log reader's event lengths (liblcm 1.3.1 mallocs them) and the checked
// decode's array lengths (LCM's generated decode resizes to them). The global operator new is replaced in
// allocation_tracker.cpp, a file of its own so that the compiler does not inline it into callers and take
// its malloc/free pair for a mismatched new/delete.

#include <cstddef>

namespace ifar::test_support {

void startTrackingAllocations();
/// The largest size passed to operator new since startTrackingAllocations().
std::size_t stopTrackingAllocations();

}  // namespace ifar::test_support
