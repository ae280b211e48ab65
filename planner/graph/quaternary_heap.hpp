#pragma once
// A 4-ary min-heap on `priority` over a vector: half the levels of a binary heap, and the four children
// of a node share a cache line. Entry is any type with a `priority` member. Declared inline: A* pushes
// and pops in its innermost loop.

#include <algorithm>
#include <cstddef>
#include <vector>

namespace ifar::graph {

template <typename Entry>
inline void pushQuaternary(std::vector<Entry>& heap, const Entry& entry)
{
  std::size_t index = heap.size();
  heap.push_back(entry);
  while (index > 0) {
    const std::size_t parent = (index - 1) / 4;
    if (!(entry.priority < heap[parent].priority)) {
      break;
    }
    heap[index] = heap[parent];
    index = parent;
  }
  heap[index] = entry;
}

template <typename Entry>
inline Entry popQuaternary(std::vector<Entry>& heap)
{
  const Entry top = heap.front();
  const Entry last = heap.back();
  heap.pop_back();
  const std::size_t size = heap.size();
  if (size == 0) {
    return top;
  }
  std::size_t index = 0;
  while (true) {
    const std::size_t first = 4 * index + 1;
    if (first >= size) {
      break;
    }
    std::size_t best = first;
    const std::size_t end = std::min(first + 4, size);
    for (std::size_t child = first + 1; child < end; ++child) {
      if (heap[child].priority < heap[best].priority) {
        best = child;
      }
    }
    if (!(heap[best].priority < last.priority)) {
      break;
    }
    heap[index] = heap[best];
    index = best;
  }
  heap[index] = last;
  return top;
}

}  // namespace ifar::graph
