// libFuzzer entry: any bytes as a pcap file, every datagram then decoded as a VLP-16 packet.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "drivers/velodyne/packet_decoder.hpp"
#include "drivers/velodyne/pcap_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace ifar::velodyne;
  PcapReader reader(
      std::make_unique<std::istringstream>(std::string(reinterpret_cast<const char*>(data), size)));
  UdpDatagram datagram;
  std::vector<Point> points;
  // Each record consumes at least 16 bytes, so this bound is never the reason to stop on valid input.
  for (std::size_t record = 0; record <= size / 16 + 1; ++record) {
    const PcapRecord result = reader.next(datagram);
    if (result == PcapRecord::kEndOfFile || result == PcapRecord::kTruncatedFile) {
      return 0;
    }
    if (result == PcapRecord::kUdpDatagram) {
      if (datagram.payload.size() > size) {
        std::abort();
      }
      points.clear();
      decodePacket(datagram.payload, points);
    }
  }
  std::abort();  // the reader failed to finish: it must report the end within size / 16 records
}
