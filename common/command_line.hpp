#pragma once
// Command-line parsing with one exit-code convention for every ifar program: --help and --version exit
// 0; any parse error (unknown option, missing or malformed value, a file that must exist but does not)
// prints CLI11's message and exits 2, "bad input". CLI11 alone exits with its own codes (104-114).
// One usage style: every program's help says "Usage: ifar NAME ...", however it was started (ifar NAME
// runs ifar-NAME by its full path). `ifar-NAME --describe` prints the first sentence of its description
// alone: `ifar --help` lists the subcommands with it.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace ifar::common {

// The exit codes every ifar command uses for the same outcome (docs/cli.md): 0 done, 1 ran and the answer
// is no (not arrived, no path, a check that found problems; a daemon's failure while running), 2 bad input
// (command line, configuration, an input file), 3 an output that could not be written, 4 / 5 a start / goal
// inside an obstacle.
inline constexpr int kBadInputExitCode = 2;
inline constexpr int kOutputFailedExitCode = 3;

/// An option check "a number, at least `minimum`" whose message says so in words ("--seed: must be at
/// least 0, got '-1'"); CLI11's NonNegativeNumber prints its range up to 1.8e308.
CLI::Validator atLeast(double minimum);

/// A position as every ifar command writes one, "X,Y" in metres (a pose "X,Y,HEADING"): `minimum_count` to
/// `maximum_count` finite numbers separated by commas. nullopt for anything else ("3", "1 2", "nan,2").
std::optional<std::vector<double>> parseCommaNumbers(const std::string& text, std::size_t minimum_count,
                                                     std::size_t maximum_count);

/// An option, or a positional when `name` has no dashes, taking one such value written `form` ("X,Y"):
/// a malformed one is a command-line error "--goal: expected X,Y (numbers separated by commas), got '3'"
/// (exit 2). `values` is left empty when the option is not given.
CLI::Option* addCoordinatesOption(CLI::App& app, const std::string& name, std::vector<double>& values,
                                  const std::string& form, std::size_t minimum_count,
                                  std::size_t maximum_count, const std::string& description);

/// "ifar run" for a program started as /any/path/ifar-run; other names as they are, without the path.
std::string commandName(const std::string& program);

/// The first sentence of a description, on one line: "Headless runner: ... (faster than real time)".
std::string firstSentence(const std::string& description);

/// Parses argv into `app`. Empty when the program goes on; else the code to exit with, after CLI11 printed
/// the help text or the error.
std::optional<int> parseCommandLine(CLI::App& app, int argc, char** argv);

}  // namespace ifar::common
