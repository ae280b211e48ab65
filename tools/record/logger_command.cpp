#include "tools/record/logger_command.hpp"

#include <cstddef>
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

std::string loggerUrl(const std::string& url, long bytes)
{
  std::string base = url.empty() ? std::string(kLcmDefaultUrl) : url;
  if (base.rfind("udpm://", 0) != 0 || bytes <= 0) {
    return base;
  }
  const std::size_t query = base.find('?');
  if (query != std::string::npos && (base.find("?recv_buf_size=", query) != std::string::npos ||
                                     base.find("&recv_buf_size=", query) != std::string::npos)) {
    return base;
  }
  if (query == std::string::npos) {
    base += '?';
  } else if (base.back() != '?' && base.back() != '&') {
    base += '&';
  }
  return base + "recv_buf_size=" + std::to_string(bytes);
}

}  // namespace ifar::record
