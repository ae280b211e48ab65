#include "testing/allocation_tracker.hpp"

#include <atomic>
#include <cstdlib>
#include <new>

namespace {

std::atomic<bool> tracking{false};
std::atomic<std::size_t> largest_allocation{0};

}  // namespace

namespace ifar::test_support {

void startTrackingAllocations()
{
  largest_allocation = 0;
  tracking = true;
}

std::size_t stopTrackingAllocations()
{
  tracking = false;
  return largest_allocation;
}

}  // namespace ifar::test_support

// Replacing the global operator new is the only way to see every allocation (std::string, std::vector,
// the file stream's buffer). The array and sized forms forward to these two by the standard's defaults.
void* operator new(std::size_t size)
{
  if (tracking.load(std::memory_order_relaxed)) {
    std::size_t largest = largest_allocation.load(std::memory_order_relaxed);
    while (size > largest && !largest_allocation.compare_exchange_weak(largest, size)) {
    }
  }
  // NOLINTNEXTLINE(cppcoreguidelines-no-malloc): a replacement operator new has nothing else to call
  if (void* memory = std::malloc(size == 0 ? 1 : size)) {
    return memory;
  }
  throw std::bad_alloc();
}

void operator delete(void* memory) noexcept
{
  std::free(memory);  // NOLINT(cppcoreguidelines-no-malloc): pairs with the malloc above
}

void operator delete(void* memory, std::size_t /*size*/) noexcept
{
  std::free(memory);  // NOLINT(cppcoreguidelines-no-malloc): pairs with the malloc above
}
