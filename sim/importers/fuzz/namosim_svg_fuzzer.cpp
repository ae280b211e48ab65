// libFuzzer entry: any bytes as a namosim scenario SVG, imported with the default settings (the robot
// gives the scale) and with a fixed scale. Bad input is a failed WorldResult, never an exception.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "sim/importers/namosim_svg_importer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace ifar::sim;
  const std::string text(reinterpret_cast<const char*>(data), size);
  NamosimImportSettings settings;
  for (int pass = 0; pass < 2; ++pass) {
    const NamosimImport result = parseNamosimSvg(text, "fuzz.svg", settings);
    if (!result.world.ok() && result.world.error().empty()) {
      std::abort();  // a failure must say why
    }
    if (result.world.ok() && !(result.metres_per_unit > 0.0)) {
      std::abort();
    }
    settings.metres_per_unit = 0.01;  // true size
    settings.curve_tolerance_m = 0.05;
  }
  return 0;
}
