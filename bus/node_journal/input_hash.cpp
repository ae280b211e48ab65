#include "bus/node_journal/input_hash.hpp"

#include <cstring>

namespace ifar::node_journal {

std::int32_t inputHash(common::ByteView bytes)
{
  constexpr std::uint32_t kOffsetBasis = 2166136261U;
  constexpr std::uint32_t kPrime = 16777619U;
  std::uint32_t hash = kOffsetBasis;
  for (const std::uint8_t byte : bytes) {
    hash = (hash ^ byte) * kPrime;
  }
  std::int32_t as_signed = 0;
  std::memcpy(&as_signed, &hash, sizeof hash);
  return as_signed;
}

}  // namespace ifar::node_journal
