#include "drivers/can/frame.hpp"

#include <algorithm>

namespace ifar::can {

Frame makeFrame(std::uint32_t id, std::initializer_list<std::uint8_t> bytes)
{
  return makeFrame(id, common::ByteView(bytes.begin(), bytes.size()));
}

Frame makeFrame(std::uint32_t id, common::ByteView bytes, std::uint8_t flags)
{
  Frame frame;
  frame.id = id;
  frame.flags = flags;
  frame.dlc = static_cast<std::uint8_t>(std::min<std::size_t>(bytes.size(), kMaxDataLength));
  std::copy(bytes.begin(), bytes.begin() + frame.dlc, frame.data.begin());
  return frame;
}

bool sameContent(const Frame& left, const Frame& right)
{
  return left.id == right.id && left.flags == right.flags && left.dlc == right.dlc && left.data == right.data;
}

}  // namespace ifar::can
