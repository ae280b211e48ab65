// libFuzzer entry: any bytes as a VLP-16 data packet. The decoder must never read outside the input,
// and a packet it accepts must give finite points no further than the largest encodable distance.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "drivers/velodyne/packet_decoder.hpp"
#include "drivers/velodyne/revolution_assembler.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace ifar::velodyne;
  const ifar::common::ByteView input(data, size);
  std::vector<Point> points;
  for (const AzimuthInterpolation interpolation :
       {AzimuthInterpolation::kPacketMeanStep, AzimuthInterpolation::kVlpGrabber}) {
    DecoderOptions options;
    options.interpolation = interpolation;
    options.keep_no_return = size % 2 == 0;
    points.clear();
    const DecodeResult result = decodePacket(input, points, options);
    if (result.info.status != PacketStatus::kOk && !points.empty()) {
      std::abort();
    }
    for (const Point& point : points) {
      if (!std::isfinite(point.x) || !std::isfinite(point.y) || !std::isfinite(point.z) ||
          point.distance > 131.072F || point.azimuth_degrees < 0.0F || point.azimuth_degrees >= 360.0F ||
          point.ring >= kLasers) {
        std::abort();
      }
    }
  }
  std::size_t revolutions = 0;
  RevolutionAssembler assembler([&revolutions](const Revolution&) { ++revolutions; });
  assembler.add(points, 0);
  assembler.flush();
  return 0;
}
