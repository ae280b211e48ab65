#include "common/input_silence.hpp"

#include <array>
#include <cctype>
#include <cstdio>
#include <utility>

#include "common/time.hpp"

namespace ifar::common {

InputSilence::InputSilence(std::int64_t start_us, double limit_s)
    : start_us_(start_us), limit_us_(secondsToMicroseconds(limit_s))
{
}

std::size_t InputSilence::watch(std::string name)
{
  inputs_.push_back(Input{std::move(name), start_us_, false});
  return inputs_.size() - 1;
}

void InputSilence::arrived(std::size_t input, std::int64_t now_us)
{
  if (input < inputs_.size()) {
    inputs_[input].last_us = now_us;
    inputs_[input].ever = true;
  }
}

std::string withoutDurations(const std::string& text)
{
  std::string result;
  std::size_t index = 0;
  while (index < text.size()) {
    std::size_t end = index;
    while (end < text.size() &&
           (std::isdigit(static_cast<unsigned char>(text[end])) != 0 || text[end] == '.')) {
      ++end;
    }
    const bool number = end > index && std::isdigit(static_cast<unsigned char>(text[index])) != 0;
    if (number && text.compare(end, 2, " s") == 0 &&
        (end + 2 == text.size() || std::isalnum(static_cast<unsigned char>(text[end + 2])) == 0)) {
      result += "N s";
      index = end + 2;
    } else if (end > index) {
      result.append(text, index, end - index);
      index = end;
    } else {
      result += text[index++];
    }
  }
  return result;
}

std::string InputSilence::problem(std::int64_t now_us) const
{
  std::string text;
  for (const Input& input : inputs_) {
    const std::int64_t silent_us = now_us - input.last_us;
    if (silent_us <= limit_us_) {
      continue;
    }
    if (!text.empty()) {
      text += ", ";
    }
    std::array<char, 32> seconds{};
    std::snprintf(seconds.data(), seconds.size(), "%.1f", microsecondsToSeconds(silent_us));
    text += "no " + input.name + " for " + seconds.data() + " s";
    if (!input.ever) {
      text += " (none since start)";
    }
  }
  return text;
}

}  // namespace ifar::common
