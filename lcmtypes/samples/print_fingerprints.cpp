// Prints "type_name 0xFINGERPRINT" for every project LCM type: the lines of lcmtypes/fingerprints.txt.
// Run it only to add the line of a NEW type; a changed line means a deployed type was edited.

#include <cstdio>

#include <CLI/CLI.hpp>

#include "common/command_line.hpp"
#include "lcmtypes/samples/sample_messages.hpp"

int main(int argc, char** argv)
{
  CLI::App app{
      "Prints one line per project LCM type: its name and LCM fingerprint (hash). lcmtypes/fingerprints.txt "
      "holds these lines for every deployed type"};
  if (const auto exit_code = ifar::common::parseCommandLine(app, argc, argv)) {
    return *exit_code;
  }
  for (const auto& sample : ifar::lcmtypes_samples::allSampleMessages()) {
    std::printf("%s 0x%016llx\n", sample.type_name.c_str(),
                static_cast<unsigned long long>(sample.fingerprint));
  }
  return 0;
}
