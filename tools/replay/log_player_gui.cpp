#include "tools/replay/log_player_gui.hpp"

namespace ifar::replay {

std::string javaRegexOfNames(const std::set<std::string>& names)
{
  std::string regex;
  for (const auto& name : names) {
    if (!regex.empty()) {
      regex += "|";
    }
    // \E cannot appear inside a quote: end the quote, write it escaped, start a new one.
    std::string quoted;
    for (std::size_t index = 0; index < name.size(); ++index) {
      if (name.compare(index, 2, "\\E") == 0) {
        quoted += "\\E\\\\E\\Q";
        ++index;
      } else {
        quoted += name[index];
      }
    }
    regex += "\\Q" + quoted + "\\E";
  }
  return regex.empty() ? regex : "^(" + regex + ")$";
}

std::vector<std::string> logPlayerArguments(const std::string& log, const std::set<std::string>& switched_off,
                                            const std::string& lcm_url, bool paused)
{
  std::vector<std::string> arguments;
  if (!lcm_url.empty()) {
    arguments.push_back("--lcm-url=" + lcm_url);
  }
  if (!switched_off.empty()) {
    arguments.push_back("--filter=" + javaRegexOfNames(switched_off));
  }
  if (paused) {
    arguments.emplace_back("--paused");
  }
  arguments.push_back(log);
  return arguments;
}

}  // namespace ifar::replay
