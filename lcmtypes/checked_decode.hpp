#pragma once
// Decoding a project LCM message from bytes nobody vouches for: the bus, a log file. LCM's generated
// decode resizes each array to the length the bytes claim before checking that they hold it. A negative
// length threw std::length_error, which ended the daemons and the log tools alike; a large one made it
// allocate and zero-fill gigabytes for a message of a few dozen bytes. So the claims are checked against
// the bytes first (lcm_wire, with the schema built from lcmtypes/*.lcm), and whatever the decode still
// throws is caught.

#include <climits>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <optional>
#include <string>
#include <utility>

#include "common/byte_order.hpp"
#include "common/lcm_wire/claim_check.hpp"
#include "lcmtypes/message_schema.hpp"

namespace ifar::lcmtypes {

struct DecodeResult {
  int bytes = -1;     ///< bytes the message took; -1 when it does not decode
  std::string error;  ///< why it does not decode, when known; empty otherwise
  bool ok() const { return bytes >= 0; }
};

/// Decodes `message` from `size` bytes at `data`; never throws what the decode throws, and refuses
/// bytes whose array or string lengths claim more than the bytes hold before the decode allocates.
template <typename Message>
DecodeResult decodeLcm(Message& message, const void* data, std::size_t size)
{
  DecodeResult result;
  if (size > static_cast<std::size_t>(INT_MAX)) {
    result.error = "larger than LCM's 2 GB limit";
    return result;
  }
  const auto* const bytes_start = static_cast<const std::uint8_t*>(data);
  if (size >= 8 && static_cast<std::int64_t>(common::readUint64Be(bytes_start)) != Message::getHash()) {
    result.error = std::string("not a ") + Message::getTypeName() + ": its type hash differs";
    return result;
  }
  static const lcm_wire::StructType* const type = messageSchema().find(Message::getTypeName());
  if (type != nullptr) {
    const common::ByteView bytes(bytes_start, size);
    if (std::optional<std::string> claim = lcm_wire::findUnbackedClaim(messageSchema(), *type, bytes)) {
      result.error = std::move(*claim);
      return result;
    }
  }
  try {
    result.bytes = message.decode(data, 0, static_cast<int>(size));
  } catch (const std::exception& error) {
    result.error = error.what();
  } catch (...) {
    result.error = "an exception that is not a std::exception";
  }
  if (result.bytes < 0 || !result.error.empty()) {
    result.bytes = -1;
  }
  return result;
}

}  // namespace ifar::lcmtypes
