// libFuzzer entry: any bytes as a MovingAI .map file and as a .scen file (the readers take paths, so the
// bytes go to a scratch file). Bad input is an error value, never an exception, and a map the reader
// accepts holds no more cells than the file has bytes.

#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "common/grid_map/fuzz/scratch_folder.hpp"
#include "common/grid_map/readers.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace ifar::grid_map;
  const std::string path = fuzz::writeScratchFile("fuzz.map", reinterpret_cast<const char*>(data), size);
  const MapReadResult result = readMovingAiMap(path);
  if (result.ok() &&
      static_cast<std::size_t>(result.map.width()) * static_cast<std::size_t>(result.map.height()) > size) {
    std::abort();
  }
  if (!result.ok() && result.error.rfind(path, 0) != 0) {
    std::abort();  // every error names the file
  }
  const ScenarioReadResult scenarios = readMovingAiScenarios(path);
  if (scenarios.scenarios.size() > size / 9) {
    std::abort();  // a query takes at least nine fields
  }
  return 0;
}
