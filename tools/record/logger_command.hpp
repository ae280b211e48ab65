#pragma once
// The command line of lcm-logger 1.3.1 for `ifar record`. That version declares its long options
// --strftime and --increment as taking an argument although they take none, so `--strftime --channel=X`
// gave --strftime the channel option as its argument and recorded every channel, and a trailing --increment
// took the file name. The short forms -s and -i take none; every option with a value is one argument
// (--channel=REGEX), and "--" ends the options, so neither a regex nor a file name starting with '-' is
// read as an option.

#include <string>
#include <vector>

namespace ifar::record {

struct LoggerRequest {
  std::string file_pattern;  // path of the log, strftime-formatted by lcm-logger
  std::string channels = ".*";
  double split_mb = 0.0;  // 0: never start a new file
  int rotate = 0;         // 0: number the files (.00, .01, ...); N: keep N files, newest as FILE.0
};

/// lcm-logger's argv, program name first.
std::vector<std::string> loggerArguments(const LoggerRequest& request);

}  // namespace ifar::record
