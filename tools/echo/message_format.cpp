#include "tools/echo/message_format.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "common/json_text.hpp"

namespace ifar::echo {
namespace {

using Kind = Value::Kind;

std::string numberText(const Value& value)
{
  if (std::isnan(value.real)) {
    return "nan";
  }
  if (std::isinf(value.real)) {
    return value.real > 0 ? "inf" : "-inf";
  }
  std::array<char, 40> text{};
  const auto result = value.kind == Kind::kFloat
                          ? std::to_chars(text.begin(), text.end(), static_cast<float>(value.real))
                          : std::to_chars(text.begin(), text.end(), value.real);
  return std::string(text.data(), result.ptr);
}

std::string hexText(const std::string& bytes)
{
  static const char kDigits[] = "0123456789abcdef";
  std::string text;
  text.reserve(2 * bytes.size());
  for (const char byte : bytes) {
    const auto bits = static_cast<unsigned char>(byte);
    text += kDigits[bits >> 4U];
    text += kDigits[bits & 0x0FU];
  }
  return text;
}

std::string membersInline(const Members& members, bool json);

/// A value as one piece of text; JSON's spelling when `json`.
std::string inlineText(const Value& value, bool json)
{
  switch (value.kind) {
    case Kind::kInteger:
      return std::to_string(value.integer);
    case Kind::kDouble:
    case Kind::kFloat:
      return json && !std::isfinite(value.real) ? "null" : numberText(value);
    case Kind::kBoolean:
      return value.boolean ? "true" : "false";
    case Kind::kString:
      return common::jsonString(value.text);
    case Kind::kBytes:
      return json ? "\"" + hexText(value.text) + "\"" : hexText(value.text);
    case Kind::kList: {
      std::string text = "[";
      for (std::size_t index = 0; index < value.elements.size(); ++index) {
        text += (index == 0 ? "" : json ? "," : ", ") + inlineText(value.elements[index], json);
      }
      return text + "]";
    }
    case Kind::kStruct:
      return membersInline(value.members, json);
  }
  return "";
}

/// {"name":value,...}
std::string membersInline(const Members& members, bool json)
{
  std::string text = "{";
  for (std::size_t index = 0; index < members.size(); ++index) {
    const auto& [name, member] = members[index];
    text += (index == 0 ? "" : json ? "," : ", ") + common::jsonString(name) + ":" + inlineText(member, json);
  }
  return text + "}";
}

bool holdsStructs(const Value& value)
{
  return value.kind == Kind::kStruct ||
         (value.kind == Kind::kList && !value.elements.empty() && holdsStructs(value.elements.front()));
}

void appendMembers(std::string& text, const Members& members, const std::string& indent);

/// One member as text lines: scalars and lists of them on the member's line, structs below it.
void appendMember(std::string& text, const std::string& name, const Value& value, const std::string& indent)
{
  if (!holdsStructs(value)) {
    text += indent + name + ": " + inlineText(value, false) + "\n";
    return;
  }
  text += indent + name + ":\n";
  if (value.kind == Kind::kStruct) {
    appendMembers(text, value.members, indent + "  ");
    return;
  }
  for (const Value& element : value.elements) {
    std::string block;
    if (element.kind == Kind::kStruct) {
      appendMembers(block, element.members, indent + "    ");
    } else {
      appendMember(block, "-", element, indent + "    ");
    }
    // The element's first line starts with "- " in place of its indent's last two spaces.
    if (block.size() >= indent.size() + 4) {
      block.replace(indent.size() + 2, 2, "- ");
    }
    text += block;
  }
}

void appendMembers(std::string& text, const Members& members, const std::string& indent)
{
  for (const auto& [name, value] : members) {
    appendMember(text, name, value, indent);
  }
}

std::string utimeText(std::int64_t utime)
{
  std::array<char, 48> text{};
  const std::int64_t seconds = utime / 1'000'000;
  const std::int64_t micros = utime % 1'000'000;
  std::snprintf(text.data(), text.size(), "%s%lld.%06lld", utime < 0 ? "-" : "",
                static_cast<long long>(seconds < 0 ? -seconds : seconds),
                static_cast<long long>(micros < 0 ? -micros : micros));
  return text.data();
}

}  // namespace

std::string jsonObject(const Members& members)
{
  return membersInline(members, true);
}

std::string jsonLine(const MessageOrigin& origin, const Members& members)
{
  return "{\"channel\":" + common::jsonString(origin.channel) +
         ",\"type\":" + common::jsonString(origin.type_name) +
         ",\"receive_utime\":" + std::to_string(origin.receive_utime) +
         ",\"message\":" + jsonObject(members) + "}";
}

std::string textBlock(const MessageOrigin& origin, const Members& members)
{
  std::string text = "--- " + origin.channel + " " + origin.type_name + " received " +
                     utimeText(origin.receive_utime) + "\n";
  appendMembers(text, members, "  ");
  return text;
}

}  // namespace ifar::echo
