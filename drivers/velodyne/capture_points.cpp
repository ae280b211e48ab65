#include "drivers/velodyne/capture_points.hpp"

#include <vector>

#include "common/command_line.hpp"
#include "drivers/velodyne/packet_decoder.hpp"
#include "drivers/velodyne/pcap_reader.hpp"
#include "drivers/velodyne/point_file.hpp"

namespace ifar::velodyne {

std::string nothingToPublishMessage(const std::string& pcap_path, const CaptureCounts& counts,
                                    const PacketForwarder& forwarder, std::uint16_t data_port)
{
  const std::int64_t refused = forwarder.monitor().counts().bad_packets;
  std::string message = "'" + pcap_path + "' gave no packet to publish: " + std::to_string(counts.records) +
                        " records read, " + std::to_string(counts.skipped) + " of them not UDP to port " +
                        std::to_string(data_port) + ", " + std::to_string(refused) + " refused";
  if (refused > 0) {
    message += " (" + forwarder.monitor().badSummary() + ")";
  }
  return message;
}

int writeCapturePoints(const std::string& pcap_path, const std::string& out_path,
                       const DriverSettings& settings, const std::shared_ptr<spdlog::logger>& logger)
{
  PcapReader reader = PcapReader::open(pcap_path);
  if (reader.error() != PcapError::kNone) {
    logger->error("cannot read '{}': {}", pcap_path, reader.errorText());
    return common::kBadInputExitCode;
  }
  PointFileWriter writer(out_path);
  if (!writer.error().empty()) {
    logger->error("{}", writer.error());
    return common::kOutputFailedExitCode;
  }
  PacketForwarder forwarder(settings, logger);
  CaptureCounts counts;
  UdpDatagram datagram;
  std::vector<Point> points;
  for (PcapRecord record = reader.next(datagram); record != PcapRecord::kEndOfFile;
       record = reader.next(datagram)) {
    if (record == PcapRecord::kTruncatedFile) {
      logger->warn("'{}' ends inside a record: the points stop there", pcap_path);
      break;
    }
    ++counts.records;
    if (record != PcapRecord::kUdpDatagram || datagram.destination_port != settings.data_port) {
      ++counts.skipped;
      continue;
    }
    // The forwarder decides as the driver would; its packet carries the product byte the decoder expects.
    const std::optional<ForwardedPacket> forwarded =
        forwarder.onDatagram(datagram.destination_port, datagram.payload, datagram.capture_time_us);
    if (!forwarded) {
      continue;
    }
    ++counts.published;
    points.clear();
    const DecodeResult result = decodePacket(common::ByteView(forwarded->packet.data), points);
    writer.add(points, result.info.device_time_past_hour);
  }
  if (!writer.finish()) {
    logger->error("{}", writer.error());
    return common::kOutputFailedExitCode;
  }
  if (counts.published == 0) {
    logger->error("{}", nothingToPublishMessage(pcap_path, counts, forwarder, settings.data_port));
    return 1;
  }
  logger->info("wrote {} points of {} packets from '{}' to '{}' ({} bad packets skipped)", writer.points(),
               counts.published, pcap_path, out_path, forwarder.monitor().counts().bad_packets);
  return 0;
}

}  // namespace ifar::velodyne
