#include "common/command_line.hpp"

namespace ifar::common {

std::optional<int> parseCommandLine(CLI::App& app, int argc, char** argv)
{
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int cli_code = app.exit(error);  // prints help to stdout or the error to stderr
    return cli_code == 0 ? 0 : kBadInputExitCode;
  }
  return std::nullopt;
}

}  // namespace ifar::common
