#include "drivers/can/socketcan_bus.hpp"

#include <linux/can.h>
#include <linux/can/error.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>

#include "drivers/can/error_frame.hpp"

namespace ifar::can {
namespace {

std::string errnoText(int error_number)
{
  return std::string(std::strerror(error_number));
}

std::int64_t clockMicroseconds(clockid_t clock)
{
  timespec now{};
  clock_gettime(clock, &now);
  return static_cast<std::int64_t>(now.tv_sec) * 1'000'000 + now.tv_nsec / 1000;
}

std::int64_t wallClockMicroseconds()
{
  return clockMicroseconds(CLOCK_REALTIME);
}

// Timeouts run on the monotonic clock, so a wall-clock step cannot stretch or cut them.
std::int64_t monotonicMicroseconds()
{
  return clockMicroseconds(CLOCK_MONOTONIC);
}

// Converts the kernel's can_id (flags in the top bits) into our id and flags.
void splitKernelId(canid_t kernel_id, Frame& frame)
{
  frame.flags = 0;
  if ((kernel_id & CAN_ERR_FLAG) != 0) {
    frame.flags |= kFlagError;
    frame.id = kernel_id & CAN_ERR_MASK;
    return;
  }
  if ((kernel_id & CAN_EFF_FLAG) != 0) {
    frame.flags |= kFlagExtended;
    frame.id = kernel_id & CAN_EFF_MASK;
  } else {
    frame.id = kernel_id & CAN_SFF_MASK;
  }
  if ((kernel_id & CAN_RTR_FLAG) != 0) {
    frame.flags |= kFlagRemote;
  }
}

canid_t kernelId(const Frame& frame)
{
  if (frame.error()) {
    return (frame.id & CAN_ERR_MASK) | CAN_ERR_FLAG;
  }
  canid_t id = frame.extended() ? ((frame.id & CAN_EFF_MASK) | CAN_EFF_FLAG) : (frame.id & CAN_SFF_MASK);
  if (frame.remote()) {
    id |= CAN_RTR_FLAG;
  }
  return id;
}

}  // namespace

SocketCanOpenResult SocketCanBus::open(const std::string& interface_name)
{
  SocketCanOpenResult result;
  if (interface_name.empty() || interface_name.size() >= IFNAMSIZ) {
    result.error = "SocketCAN interface name '" + interface_name + "' is empty or longer than " +
                   std::to_string(IFNAMSIZ - 1) + " characters";
    return result;
  }
  const int socket_fd = ::socket(PF_CAN, SOCK_RAW | SOCK_NONBLOCK | SOCK_CLOEXEC, CAN_RAW);
  if (socket_fd < 0) {
    const int error_number = errno;
    if (error_number == EAFNOSUPPORT || error_number == EPROTONOSUPPORT) {
      result.error = "cannot open SocketCAN interface '" + interface_name +
                     "': this kernel has no SocketCAN support (socket(PF_CAN, SOCK_RAW, CAN_RAW): " +
                     errnoText(error_number) +
                     "); load the can and can-raw modules or use the LCM bridge (bus: lcm)";
    } else {
      result.error = "cannot open a CAN_RAW socket for '" + interface_name + "': " + errnoText(error_number);
    }
    return result;
  }
  // Owned from here: the constructor takes the descriptor, the destructor closes it on every path.
  std::unique_ptr<SocketCanBus> bus(new SocketCanBus(socket_fd, interface_name));

  ifreq request{};
  std::memcpy(request.ifr_name, interface_name.c_str(), interface_name.size() + 1);
  if (::ioctl(socket_fd, SIOCGIFINDEX, &request) < 0) {
    result.error = "no CAN interface named '" + interface_name + "': " + errnoText(errno);
    return result;
  }
  const int enable = 1;
  const can_err_mask_t error_mask = CAN_ERR_MASK;
  if (::setsockopt(socket_fd, SOL_CAN_RAW, CAN_RAW_ERR_FILTER, &error_mask, sizeof(error_mask)) < 0) {
    result.error = "'" + interface_name + "': cannot enable error frames: " + errnoText(errno);
    return result;
  }
  if (::setsockopt(socket_fd, SOL_SOCKET, SO_TIMESTAMP, &enable, sizeof(enable)) < 0) {
    result.error = "'" + interface_name + "': cannot enable receive timestamps: " + errnoText(errno);
    return result;
  }
  // FD frames enabled so an FD-capable interface cannot fail our reads; classic frames then may arrive
  // either CAN_MTU or CANFD_MTU sized. Kernels without FD support refuse this, which is fine.
  (void)::setsockopt(socket_fd, SOL_CAN_RAW, CAN_RAW_FD_FRAMES, &enable, sizeof(enable));

  sockaddr_can address{};
  address.can_family = AF_CAN;
  address.can_ifindex = request.ifr_ifindex;
  if (::bind(socket_fd, reinterpret_cast<const sockaddr*>(&address), sizeof(address)) < 0) {
    result.error = "cannot bind to CAN interface '" + interface_name + "': " + errnoText(errno);
    return result;
  }
  result.bus = std::move(bus);
  return result;
}

SocketCanBus::SocketCanBus(int socket_fd, std::string interface_name)
    : socket_fd_(socket_fd), interface_name_(std::move(interface_name))
{
}

SocketCanBus::~SocketCanBus()
{
  if (socket_fd_ >= 0) {
    ::close(socket_fd_);
  }
}

SendResult SocketCanBus::send(const Frame& frame)
{
  if (frame.dlc > kMaxDataLength) {
    ++counters_.write_errors;
    return {IoStatus::kError, interface_name_ + ": dlc " + std::to_string(frame.dlc) + " > 8"};
  }
  can_frame raw{};
  raw.can_id = kernelId(frame);
  raw.can_dlc = frame.dlc;
  std::memcpy(raw.data, frame.data.data(), kMaxDataLength);
  const ssize_t written = ::write(socket_fd_, &raw, sizeof(raw));
  if (written != static_cast<ssize_t>(sizeof(raw))) {
    const int error_number = errno;
    ++counters_.write_errors;
    if (error_number == ENETDOWN) {
      state_ = BusState::kBusOff;  // an interface that went down (or bus-off without restart)
    }
    return {IoStatus::kError, interface_name_ + ": write failed: " +
                                  (written < 0 ? errnoText(error_number) : std::string("short write"))};
  }
  ++counters_.frames_sent;
  return {};
}

ReceiveResult SocketCanBus::receive(std::chrono::microseconds timeout)
{
  const std::int64_t deadline_us = monotonicMicroseconds() + timeout.count();
  while (true) {
    canfd_frame raw{};
    iovec vector{&raw, sizeof(raw)};
    alignas(cmsghdr) char control[CMSG_SPACE(sizeof(timeval))];
    msghdr message{};
    message.msg_iov = &vector;
    message.msg_iovlen = 1;
    message.msg_control = control;
    message.msg_controllen = sizeof(control);
    const ssize_t received = ::recvmsg(socket_fd_, &message, 0);
    if (received < 0) {
      const int error_number = errno;
      if (error_number == EINTR) {
        continue;
      }
      if (error_number != EAGAIN && error_number != EWOULDBLOCK) {
        return {IoStatus::kError, {}, interface_name_ + ": read failed: " + errnoText(error_number)};
      }
      const std::int64_t remaining_us = deadline_us - monotonicMicroseconds();
      if (remaining_us <= 0) {
        return {IoStatus::kTimeout, {}, {}};
      }
      pollfd descriptor{socket_fd_, POLLIN, 0};
      const int timeout_ms = static_cast<int>((remaining_us + 999) / 1000);
      if (::poll(&descriptor, 1, timeout_ms) < 0 && errno != EINTR) {
        return {IoStatus::kError, {}, interface_name_ + ": poll failed: " + errnoText(errno)};
      }
      continue;
    }
    // A classic frame comes as CAN_MTU bytes, or as CANFD_MTU when FD frames are enabled.
    const bool classic_size = received == static_cast<ssize_t>(CAN_MTU);
    const bool fd_size = received == static_cast<ssize_t>(CANFD_MTU);
    if ((!classic_size && !fd_size) || raw.len > kMaxDataLength) {
      ++counters_.bad_frames;
      continue;
    }
    Frame frame;
    splitKernelId(raw.can_id, frame);
    frame.dlc = raw.len;
    std::memcpy(frame.data.data(), raw.data, frame.dlc);
    frame.timestamp_us = 0;
    for (cmsghdr* header = CMSG_FIRSTHDR(&message); header != nullptr;
         header = CMSG_NXTHDR(&message, header)) {
      if (header->cmsg_level == SOL_SOCKET && header->cmsg_type == SCM_TIMESTAMP) {
        timeval stamp{};
        std::memcpy(&stamp, CMSG_DATA(header), sizeof(stamp));
        frame.timestamp_us = static_cast<std::int64_t>(stamp.tv_sec) * 1'000'000 + stamp.tv_usec;
      }
    }
    if (frame.timestamp_us == 0) {
      frame.timestamp_us = wallClockMicroseconds();
    }
    if (frame.error()) {
      ++counters_.error_frames;
      if (const auto next = stateAfterErrorFrame(frame, state_)) {
        state_ = *next;
      }
    } else {
      ++counters_.frames_received;
    }
    return {IoStatus::kOk, frame, {}};
  }
}

void SocketCanBus::setFilters(const std::vector<Filter>& filters)
{
  std::vector<can_filter> kernel_filters;
  kernel_filters.reserve(filters.size());
  for (const Filter& filter : filters) {
    can_filter kernel_filter{};
    if (filter.extended) {
      kernel_filter.can_id = (filter.id & CAN_EFF_MASK) | CAN_EFF_FLAG;
      kernel_filter.can_mask = (filter.mask & CAN_EFF_MASK) | CAN_EFF_FLAG;
    } else {
      kernel_filter.can_id = filter.id & CAN_SFF_MASK;
      kernel_filter.can_mask = (filter.mask & CAN_SFF_MASK) | CAN_EFF_FLAG;
    }
    kernel_filters.push_back(kernel_filter);
  }
  if (kernel_filters.empty()) {
    // The default filter: everything.
    can_filter all{};
    kernel_filters.push_back(all);
  }
  (void)::setsockopt(socket_fd_, SOL_CAN_RAW, CAN_RAW_FILTER, kernel_filters.data(),
                     static_cast<socklen_t>(kernel_filters.size() * sizeof(can_filter)));
}

bool SocketCanBus::setReceiveOwnFrames(bool enabled)
{
  const int value = enabled ? 1 : 0;
  return ::setsockopt(socket_fd_, SOL_CAN_RAW, CAN_RAW_RECV_OWN_MSGS, &value, sizeof(value)) == 0;
}

}  // namespace ifar::can
