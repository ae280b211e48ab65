#include "tools/record/logger_command.hpp"

#include <sstream>

namespace ifar::record {

std::vector<std::string> loggerArguments(const LoggerRequest& request)
{
  std::vector<std::string> arguments = {"lcm-logger", "-s", "--channel=" + request.channels};
  if (request.rotate > 0) {
    // Always writes FILE.0, renaming older files out of the way and deleting the oldest.
    arguments.push_back("--rotate=" + std::to_string(request.rotate));
  } else {
    arguments.push_back("-i");
  }
  if (request.split_mb > 0.0) {
    std::ostringstream megabytes;
    megabytes << request.split_mb;
    arguments.push_back("--split-mb=" + megabytes.str());
  }
  arguments.push_back("--");
  arguments.push_back(request.file_pattern);
  return arguments;
}

}  // namespace ifar::record
