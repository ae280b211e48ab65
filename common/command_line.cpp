#include "common/command_line.hpp"

#include <sstream>
#include <string>

namespace ifar::common {

CLI::Validator atLeast(double minimum)
{
  std::ostringstream shown;
  shown << minimum;
  const std::string bound = shown.str();
  return CLI::Validator(
      [minimum, bound](std::string& text) -> std::string {
        double value = 0.0;
        if (!CLI::detail::lexical_cast(text, value)) {
          return "must be a number, got '" + text + "'";
        }
        if (!(value >= minimum)) {
          return "must be at least " + bound + ", got '" + text + "'";
        }
        return {};
      },
      "NUMBER >= " + bound);
}

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
