#pragma once
// LCM URLs as the stack uses them: LCM's default, and the kernel receive buffer asked for on udpm://.

#include <string>

namespace ifar::bus {

/// LCM's URL when none is configured.
inline constexpr const char* kLcmDefaultUrl = "udpm://239.255.76.67:7667?ttl=0";

/// A receive buffer that holds several seconds of the whole bus (about 1.1 MB/s with a VLP-16): every
/// LCM process on a udpm:// port receives all of its traffic and filters channels itself, so a daemon or
/// a logger held up by a busy CPU or disk for longer than the kernel's default buffer (about 200 kB, a
/// tenth of a second) loses messages, its own inputs among them.
inline constexpr long kReceiveBufferBytes = 4L * 1024L * 1024L;

/// `url` ("" = LCM's default) with a kernel receive buffer of `bytes` when it is a udpm:// URL that does
/// not set recv_buf_size itself; other providers, and `bytes` <= 0, leave it as it is (the empty URL then
/// stays empty). net.core.rmem_max caps the buffer (LCM warns when it does).
std::string withReceiveBuffer(const std::string& url, long bytes);

}  // namespace ifar::bus
