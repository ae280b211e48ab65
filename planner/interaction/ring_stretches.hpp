#pragma once
// Stretches of a ring of raster cells (FreeSpaceRaster::borderCells) that pass a test: how the push
// search tells the separate ways out of an object's surroundings apart.

#include <cstddef>
#include <vector>

namespace ifar::interaction {

/// Numbers the stretches of consecutive `ring` cells that pass `kept`: 1, 2, ... in order round it, 0 for
/// cells that fail. The walk starts after a failing cell, so no stretch is split where the ring closes; a
/// ring kept all round is one stretch. `count` is the number of stretches.
template <typename Kept>
std::vector<int> ringStretches(const std::vector<std::size_t>& ring, Kept&& kept, int& count)
{
  count = 0;
  std::vector<int> stretches(ring.size(), 0);
  std::size_t first = 0;
  while (first < ring.size() && kept(ring[first])) {
    ++first;
  }
  bool in_stretch = false;
  for (std::size_t step = 1; step <= ring.size(); ++step) {
    const std::size_t position = (first + step) % ring.size();
    if (!kept(ring[position])) {
      in_stretch = false;
      continue;
    }
    if (!in_stretch) {
      ++count;
      in_stretch = true;
    }
    stretches[position] = count;
  }
  return stretches;
}

}  // namespace ifar::interaction
