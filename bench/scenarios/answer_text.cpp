#include "bench/scenarios/answer_text.hpp"

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace ifar::scenarios {

void AnswerWriter::number(double value)
{
  char token[64];
  std::snprintf(token, sizeof(token), "%a ", value);
  answer_ += token;
}

void AnswerWriter::integer(std::int64_t value)
{
  answer_ += std::to_string(value) + " ";
}

void AnswerWriter::text(std::string_view value)
{
  answer_ += std::to_string(value.size()) + ":";
  answer_ += value;
}

bool AnswerReader::token(std::string& value)
{
  const std::size_t end = rest_.find(' ');
  if (!ok_ || end == std::string_view::npos || end == 0) {
    ok_ = false;
    return false;
  }
  value = std::string(rest_.substr(0, end));
  rest_.remove_prefix(end + 1);
  return true;
}

bool AnswerReader::number(double& value)
{
  std::string word;
  if (!token(word)) {
    return false;
  }
  char* end = nullptr;
  const double parsed = std::strtod(word.c_str(), &end);
  if (end != word.c_str() + word.size()) {
    ok_ = false;
    return false;
  }
  value = parsed;
  return true;
}

bool AnswerReader::integer(std::int64_t& value)
{
  std::string word;
  if (!token(word)) {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  const long long parsed = std::strtoll(word.c_str(), &end, 10);
  if (end != word.c_str() + word.size() || errno != 0) {
    ok_ = false;
    return false;
  }
  value = parsed;
  return true;
}

bool AnswerReader::flag(bool& value)
{
  std::int64_t parsed = 0;
  if (!integer(parsed) || (parsed != 0 && parsed != 1)) {
    ok_ = false;
    return false;
  }
  value = parsed == 1;
  return true;
}

bool AnswerReader::field(int& value)
{
  std::int64_t parsed = 0;
  if (!integer(parsed) || parsed < std::numeric_limits<int>::min() ||
      parsed > std::numeric_limits<int>::max()) {
    ok_ = false;
    return false;
  }
  value = static_cast<int>(parsed);
  return true;
}

bool AnswerReader::text(std::string& value)
{
  const std::size_t colon = rest_.find(':');
  if (!ok_ || colon == std::string_view::npos || colon == 0) {
    ok_ = false;
    return false;
  }
  const std::string size_text(rest_.substr(0, colon));
  char* end = nullptr;
  errno = 0;
  const unsigned long long size = std::strtoull(size_text.c_str(), &end, 10);
  if (end != size_text.c_str() + size_text.size() || errno != 0 || size > rest_.size() - colon - 1) {
    ok_ = false;
    return false;
  }
  value = std::string(rest_.substr(colon + 1, size));
  rest_.remove_prefix(colon + 1 + size);
  return true;
}

}  // namespace ifar::scenarios
