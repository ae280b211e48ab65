#include "tools/launch/variables.hpp"

#include <cctype>
#include <cstdlib>

namespace ifar::launch {

namespace {

bool isVariableName(const std::string& name)
{
  if (name.empty() || std::isdigit(static_cast<unsigned char>(name.front())) != 0) {
    return false;
  }
  for (const char character : name) {
    if (std::isalnum(static_cast<unsigned char>(character)) == 0 && character != '_') {
      return false;
    }
  }
  return true;
}

}  // namespace

Expansion expandVariables(const std::string& text, const VariableLookup& lookup)
{
  Expansion result;
  std::size_t position = 0;
  while (position < text.size()) {
    const std::size_t start = text.find("${", position);
    if (start == std::string::npos) {
      result.text += text.substr(position);
      break;
    }
    result.text += text.substr(position, start - position);
    const std::size_t end = text.find('}', start + 2);
    if (end == std::string::npos) {
      result.error = "unterminated '${' in '" + text + "'";
      return result;
    }
    const std::string body = text.substr(start + 2, end - start - 2);
    const std::size_t separator = body.find(":-");
    const std::string name = body.substr(0, separator);
    if (!isVariableName(name)) {
      result.error = "'${" + body + "}' does not name a variable (letters, digits and _)";
      return result;
    }
    const std::optional<std::string> value = lookup(name);
    if (separator != std::string::npos) {
      result.text += value && !value->empty() ? *value : body.substr(separator + 2);
    } else if (value) {
      result.text += *value;
    } else {
      result.error = "variable '" + name + "' is not set (write ${";
      result.error += name + ":-fallback} for a default)";
      return result;
    }
    position = end + 1;
  }
  return result;
}

std::optional<std::string> environmentVariable(const std::string& name)
{
  const char* value =
      std::getenv(name.c_str());  // NOLINT(concurrency-mt-unsafe): read before any thread starts
  if (value == nullptr) {
    return std::nullopt;
  }
  return std::string(value);
}

}  // namespace ifar::launch
