// Prints "type_name 0xFINGERPRINT" for every project LCM type: the lines of lcmtypes/fingerprints.txt.
// Run it only to add the line of a NEW type; a changed line means a deployed type was edited.

#include <cstdio>
#include <cstring>

#include "lcmtypes/samples/sample_messages.hpp"

int main(int argc, char** argv)
{
  if (argc > 1 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
    std::printf(
        "usage: ifar-lcm-fingerprints\n"
        "Prints one line per project LCM type: its name and LCM fingerprint (hash).\n"
        "lcmtypes/fingerprints.txt holds these lines for every deployed type.\n");
    return 0;
  }
  if (argc > 1) {
    std::fprintf(stderr, "ifar-lcm-fingerprints: takes no arguments, got '%s' (see --help)\n", argv[1]);
    return 2;
  }
  for (const auto& sample : ifar::lcmtypes_samples::allSampleMessages()) {
    std::printf("%s 0x%016llx\n", sample.type_name.c_str(),
                static_cast<unsigned long long>(sample.fingerprint));
  }
  return 0;
}
