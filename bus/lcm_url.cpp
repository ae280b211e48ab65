#include "bus/lcm_url.hpp"

#include <cstddef>

namespace ifar::bus {

std::string withReceiveBuffer(const std::string& url, long bytes)
{
  if (bytes <= 0) {
    return url;
  }
  std::string base = url.empty() ? std::string(kLcmDefaultUrl) : url;
  if (base.rfind("udpm://", 0) != 0) {
    return url;
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

}  // namespace ifar::bus
