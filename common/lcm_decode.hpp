#pragma once
// Decoding an LCM message from bytes nobody vouches for: the bus, a log file. LCM's generated decode
// resizes each array to the length the bytes claim before checking that they hold it, so a negative
// length throws std::length_error (an impossible one std::bad_alloc); uncaught, that ended the daemons
// and the log tools alike. Header only, and no LCM include: any type with LCM's decode() works.

#include <climits>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>

namespace ifar::common {

struct DecodeResult {
  int bytes = -1;     ///< bytes the message took; -1 when it does not decode
  std::string error;  ///< what the decode threw, when it threw; empty otherwise
  bool ok() const { return bytes >= 0; }
};

/// Decodes `message` from `size` bytes at `data`; never throws what the decode throws.
template <typename Message>
DecodeResult decodeLcm(Message& message, const void* data, std::size_t size)
{
  DecodeResult result;
  if (size > static_cast<std::size_t>(INT_MAX)) {
    result.error = "larger than LCM's 2 GB limit";
    return result;
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

}  // namespace ifar::common
