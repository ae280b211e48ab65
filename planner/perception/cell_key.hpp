#pragma once
// A grid cell's column and row packed into one hash key (each kept to its low 32 bits, so cells within
// 2^31 of the origin either way are distinct), for maps keyed by world cell.

#include <cstdint>

namespace ifar::perception {

inline std::uint64_t packCellKey(std::int64_t column, std::int64_t row)
{
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(column)) << 32U) |
         static_cast<std::uint64_t>(static_cast<std::uint32_t>(row));
}

}  // namespace ifar::perception
