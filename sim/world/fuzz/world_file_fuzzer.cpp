// libFuzzer entry: any bytes as world YAML. Bad input is a failed WorldResult, never an exception, and a
// world that loads must survive its own round trip: formatWorld's text loads again to the same text.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "sim/world/world_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace ifar::sim;
  const WorldResult result = parseWorld(std::string(reinterpret_cast<const char*>(data), size), "fuzz.yaml");
  if (!result.ok()) {
    if (result.error().empty()) {
      std::abort();  // a failure must say why
    }
    return 0;
  }
  const std::string text = formatWorld(result.world());
  const WorldResult again = parseWorld(text, "formatted.yaml");
  if (!again.ok()) {
    std::fprintf(stderr, "formatted world does not load again: %s\n%s\n", again.error().c_str(),
                 text.c_str());
    std::abort();
  }
  if (formatWorld(again.world()) != text) {
    std::fprintf(stderr, "formatted world changes on a round trip:\n%s\n", text.c_str());
    std::abort();
  }
  return 0;
}
