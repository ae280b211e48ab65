#pragma once
// Single key presses from a terminal on standard input, without Enter and without echo, for as long as
// the object lives (the terminal's settings are put back on destruction). Ctrl-C still sends SIGINT.

#include <optional>

#include <termios.h>

namespace ifar::replay {

class TerminalKeys {
 public:
  /// Takes the keys of standard input when it is a terminal; active() is false otherwise.
  TerminalKeys();
  ~TerminalKeys();
  TerminalKeys(const TerminalKeys&) = delete;
  TerminalKeys& operator=(const TerminalKeys&) = delete;

  bool active() const { return active_; }
  /// The file descriptor to poll for a key (standard input).
  static int fileDescriptor() { return 0; }
  /// The next key pressed, if one is waiting.
  std::optional<char> read() const;

 private:
  bool active_ = false;
  termios saved_{};
};

}  // namespace ifar::replay
