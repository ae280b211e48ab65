// Linked against every ifar:: library (consumer/CMakeLists.txt); prints how many it linked.
#include <cstdio>

#include "common/command_line.hpp"

int main()
{
  const auto goal = ifar::common::parseCommaNumbers("8,26", 2, 2);
  std::printf("parsed %zu numbers, linked %d libraries\n", goal ? goal->size() : 0, IFAR_LIBRARY_COUNT);
  return goal ? 0 : 1;
}
