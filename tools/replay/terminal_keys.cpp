#include "tools/replay/terminal_keys.hpp"

#include <unistd.h>

namespace ifar::replay {

TerminalKeys::TerminalKeys()
{
  if (isatty(fileDescriptor()) == 0 || tcgetattr(fileDescriptor(), &saved_) != 0) {
    return;
  }
  termios keys = saved_;
  keys.c_lflag &= ~static_cast<tcflag_t>(ICANON | ECHO);  // ISIG stays: Ctrl-C is still SIGINT
  keys.c_cc[VMIN] = 0;
  keys.c_cc[VTIME] = 0;
  active_ = tcsetattr(fileDescriptor(), TCSANOW, &keys) == 0;
}

TerminalKeys::~TerminalKeys()
{
  if (active_) {
    tcsetattr(fileDescriptor(), TCSANOW, &saved_);
  }
}

std::optional<char> TerminalKeys::read() const
{
  char key = 0;
  if (!active_ || ::read(fileDescriptor(), &key, 1) != 1) {
    return std::nullopt;
  }
  return key;
}

}  // namespace ifar::replay
