#pragma once
// Text for the JSON lines our commands print (--json): string literals with the escapes JSON requires.

#include <string>
#include <string_view>

namespace ifar::common {

/// `text` as a JSON string literal, quotes included: quote, backslash and control characters escaped.
std::string jsonString(std::string_view text);

}  // namespace ifar::common
