#include "common/json_text.hpp"

#include <fmt/format.h>

namespace ifar::common {

std::string jsonString(std::string_view text)
{
  std::string out = "\"";
  for (const char character : text) {
    switch (character) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(character) < 0x20) {
          out += fmt::format("\\u{:04x}", static_cast<unsigned>(static_cast<unsigned char>(character)));
        } else {
          out += character;
        }
    }
  }
  out += '"';
  return out;
}

}  // namespace ifar::common
