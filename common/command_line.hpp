#pragma once
// Command-line parsing with one exit-code convention for every ifar program: --help and --version exit
// 0; any parse error (unknown option, missing or malformed value, a file that must exist but does not)
// prints CLI11's message and exits 2, "bad input". CLI11 alone exits with its own codes (104-114).

#include <optional>

#include <CLI/CLI.hpp>

namespace ifar::common {

inline constexpr int kBadInputExitCode = 2;

/// An option check "a number, at least `minimum`" whose message says so in words ("--seed: must be at
/// least 0, got '-1'"); CLI11's NonNegativeNumber prints its range up to 1.8e308.
CLI::Validator atLeast(double minimum);

/// Parses argv into `app`. Empty when the program goes on; else the code to exit with, after CLI11 printed
/// the help text or the error.
std::optional<int> parseCommandLine(CLI::App& app, int argc, char** argv);

}  // namespace ifar::common
