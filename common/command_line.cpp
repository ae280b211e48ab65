#include "common/command_line.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
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

std::optional<std::vector<double>> parseCommaNumbers(const std::string& text, std::size_t minimum_count,
                                                     std::size_t maximum_count)
{
  std::vector<double> values;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    const std::string part =
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    char* end = nullptr;
    const double value = std::strtod(part.c_str(), &end);
    if (part.empty() || *end != '\0' || !std::isfinite(value)) {
      return std::nullopt;
    }
    values.push_back(value);
    if (comma == std::string::npos) {
      break;
    }
    start = comma + 1;
  }
  if (values.size() < minimum_count || values.size() > maximum_count) {
    return std::nullopt;
  }
  return values;
}

CLI::Option* addCoordinatesOption(CLI::App& app, const std::string& name, std::vector<double>& values,
                                  const std::string& form, std::size_t minimum_count,
                                  std::size_t maximum_count, const std::string& description)
{
  const auto parse = [minimum_count, maximum_count](const std::string& text) {
    return parseCommaNumbers(text, minimum_count, maximum_count);
  };
  return app
      .add_option_function<std::string>(
          name, [&values, parse](const std::string& text) { values = *parse(text); }, description)
      ->check(CLI::Validator(
          [parse, form](std::string& text) -> std::string {
            return parse(text) ? std::string()
                               : "expected " + form + " (numbers separated by commas), got '" + text + "'";
          },
          form, ""))
      ->type_name(form);
}

std::string commandName(const std::string& program)
{
  const std::size_t slash = program.rfind('/');
  std::string name = slash == std::string::npos ? program : program.substr(slash + 1);
  if (name.rfind("ifar-", 0) == 0) {
    name[4] = ' ';
  }
  return name;
}

std::string firstSentence(const std::string& description)
{
  std::string text = description;
  std::replace(text.begin(), text.end(), '\n', ' ');
  const std::size_t end = text.find(". ");
  if (end != std::string::npos) {
    text.resize(end);
  }
  if (!text.empty() && text.back() == '.') {
    text.pop_back();
  }
  return text;
}

std::optional<int> parseCommandLine(CLI::App& app, int argc, char** argv)
{
  if (argc > 0) {
    app.name(commandName(argv[0]));
  }
  if (argc == 2 && std::string(argv[1]) == "--describe") {
    std::cout << firstSentence(app.get_description()) << '\n';
    return 0;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int cli_code = app.exit(error);  // prints help to stdout or the error to stderr
    return cli_code == 0 ? 0 : kBadInputExitCode;
  }
  return std::nullopt;
}

}  // namespace ifar::common
