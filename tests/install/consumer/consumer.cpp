// Encodes a goal_t and decodes it again with ifar's checked decode; prints what it decoded.
#include <cstdio>
#include <vector>

#include "ifar/goal_t.hpp"
#include "lcmtypes/checked_decode.hpp"

int main()
{
  ifar::goal_t sent{};
  sent.goal_id = 7;
  sent.x = 8.0;
  sent.y = 26.0;
  std::vector<unsigned char> bytes(static_cast<std::size_t>(sent.getEncodedSize()));
  sent.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  ifar::goal_t received{};
  const ifar::lcmtypes::DecodeResult result = ifar::lcmtypes::decodeLcm(received, bytes.data(), bytes.size());
  std::printf("decoded %d bytes: goal %lld at %.1f,%.1f\n", result.bytes,
              static_cast<long long>(received.goal_id), received.x, received.y);
  return result.ok() ? 0 : 1;
}
