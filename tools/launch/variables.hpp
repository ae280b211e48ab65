#pragma once
// Launch-file arguments may name environment variables, so one launch file serves the demo, the system
// tests and a vehicle: `${NAME}` is the variable's value (an error when it is unset) and
// `${NAME:-fallback}` its value or the fallback when it is unset or empty. Any other `$` stays as it is.

#include <functional>
#include <optional>
#include <string>

namespace ifar::launch {

/// Looks a variable up; nullopt when it is not set.
using VariableLookup = std::function<std::optional<std::string>(const std::string& name)>;

struct Expansion {
  std::string text;   ///< the expanded text (valid when error is empty)
  std::string error;  ///< e.g. "variable 'WORLD' is not set", "unterminated '${'"
};

Expansion expandVariables(const std::string& text, const VariableLookup& lookup);

/// The process environment as a VariableLookup.
std::optional<std::string> environmentVariable(const std::string& name);

}  // namespace ifar::launch
