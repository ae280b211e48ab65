#include "sim/importers/svg_number.hpp"

#include <cctype>
#include <charconv>

namespace ifar::sim {
namespace {

bool digitAt(const std::string& text, std::size_t index)
{
  return index < text.size() && std::isdigit(static_cast<unsigned char>(text[index])) != 0;
}

}  // namespace

void skipSvgSeparators(const std::string& text, std::size_t& position)
{
  while (position < text.size() &&
         (std::isspace(static_cast<unsigned char>(text[position])) != 0 || text[position] == ',')) {
    ++position;
  }
}

bool readSvgNumber(const std::string& text, std::size_t& position, double& value)
{
  skipSvgSeparators(text, position);
  std::size_t end = position;
  if (end < text.size() && (text[end] == '-' || text[end] == '+')) {
    ++end;
  }
  bool digits = false;
  while (digitAt(text, end)) {
    ++end;
    digits = true;
  }
  if (end < text.size() && text[end] == '.') {
    ++end;
    while (digitAt(text, end)) {
      ++end;
      digits = true;
    }
  }
  if (!digits) {
    return false;
  }
  if (end < text.size() && (text[end] == 'e' || text[end] == 'E')) {
    std::size_t exponent = end + 1;
    if (exponent < text.size() && (text[exponent] == '-' || text[exponent] == '+')) {
      ++exponent;
    }
    if (digitAt(text, exponent)) {  // "1e" without digits is the number 1 followed by a letter
      end = exponent;
      while (digitAt(text, end)) {
        ++end;
      }
    }
  }
  std::size_t begin = position;
  if (text[begin] == '+') {
    ++begin;  // from_chars does not take a plus sign
  }
  const auto parsed = std::from_chars(text.data() + begin, text.data() + end, value);
  if (parsed.ec != std::errc() || parsed.ptr != text.data() + end) {
    return false;
  }
  position = end;
  return true;
}

std::optional<std::vector<double>> parseSvgNumberList(const std::string& text)
{
  std::vector<double> numbers;
  std::size_t position = 0;
  while (true) {
    skipSvgSeparators(text, position);
    if (position >= text.size()) {
      return numbers;
    }
    double value = 0.0;
    if (!readSvgNumber(text, position, value)) {
      return std::nullopt;
    }
    numbers.push_back(value);
  }
}

}  // namespace ifar::sim
