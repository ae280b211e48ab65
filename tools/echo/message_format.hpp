#pragma once
// Decoded messages as text for people and as JSON lines for programs. Both print every member in the order
// of its definition; numbers with the fewest digits that read back to the same value (a float with a
// float's digits), byte arrays as one string of hex digits, strings quoted with JSON's escapes. JSON has no
// NaN or infinity: those are null there (nan, inf, -inf in the text).

#include <cstdint>
#include <string>

#include "tools/echo/message_value.hpp"

namespace ifar::echo {

/// Where and when a message was seen: its channel, its type, and the time it was received (for a log,
/// the event's timestamp, which is lcm-logger's receive time), microseconds since the epoch.
struct MessageOrigin {
  std::string channel;
  std::string type_name;
  std::int64_t receive_utime = 0;
};

/// The members as one JSON object: {"utime":...,...}.
std::string jsonObject(const Members& members);

/// One line of JSON, without the newline: {"channel":...,"type":...,"receive_utime":...,"message":{...}}.
std::string jsonLine(const MessageOrigin& origin, const Members& members);

/// A header line "--- CHANNEL type_t received 1763800000.123456" and then a line for each member (nested
/// structs indented two spaces, each element of an array of structs starting with "- "), each line
/// ending in a newline.
std::string textBlock(const MessageOrigin& origin, const Members& members);

}  // namespace ifar::echo
