// Decoding throughput. Target: a VLP-16 in dual return sends 1508 packets/s; the decoder must do at least
// 100x that (150,000 packets/s) on one core.

#include <benchmark/benchmark.h>

#include <cstdint>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "drivers/velodyne/packet_decoder.hpp"
#include "drivers/velodyne/pcap_reader.hpp"

namespace ifar::velodyne {
namespace {

/// A packet with a return on every channel, distances and reflectivities varying, azimuths 0.4 degree apart.
std::vector<std::uint8_t> syntheticPacket(ReturnMode mode)
{
  std::vector<std::uint8_t> bytes(kDataPacketSize, 0);
  for (std::size_t block = 0; block < kBlocksPerPacket; ++block) {
    std::uint8_t* block_bytes = bytes.data() + block * kBlockSize;
    block_bytes[0] = kBlockMarkerFirst;
    block_bytes[1] = kBlockMarkerSecond;
    const std::size_t firing_block = mode == ReturnMode::kDual ? block / 2 : block;
    const auto azimuth = static_cast<std::uint16_t>((35800 + firing_block * 40) % 36000);
    block_bytes[2] = static_cast<std::uint8_t>(azimuth & 0xFF);
    block_bytes[3] = static_cast<std::uint8_t>(azimuth >> 8);
    for (std::size_t channel = 0; channel < kReturnsPerBlock; ++channel) {
      const auto distance = static_cast<std::uint16_t>(1000 + block * 97 + channel * 31);
      std::uint8_t* raw = block_bytes + kBlockReturnsOffset + channel * kReturnSize;
      raw[0] = static_cast<std::uint8_t>(distance & 0xFF);
      raw[1] = static_cast<std::uint8_t>(distance >> 8);
      raw[2] = static_cast<std::uint8_t>(channel * 5);
    }
  }
  bytes[kReturnModeOffset] = static_cast<std::uint8_t>(mode);
  bytes[kProductIdOffset] = static_cast<std::uint8_t>(ProductId::kVlp16);
  return bytes;
}

void decodeLoop(benchmark::State& state, ReturnMode mode)
{
  const std::vector<std::uint8_t> packet = syntheticPacket(mode);
  std::vector<Point> points;
  points.reserve(kBlocksPerPacket * kReturnsPerBlock);
  for ([[maybe_unused]] auto _ : state) {
    points.clear();
    const DecodeResult result = decodePacket(common::ByteView(packet), points);
    benchmark::DoNotOptimize(result);
    benchmark::DoNotOptimize(points.data());
  }
  state.SetItemsProcessed(state.iterations());  // items = packets
  state.counters["points_per_packet"] = static_cast<double>(points.size());
}

void BM_DecodeDualReturnPacket(benchmark::State& state)
{
  decodeLoop(state, ReturnMode::kDual);
}
BENCHMARK(BM_DecodeDualReturnPacket);

void BM_DecodeStrongestReturnPacket(benchmark::State& state)
{
  decodeLoop(state, ReturnMode::kStrongest);
}
BENCHMARK(BM_DecodeStrongestReturnPacket);

void BM_ValidatePacket(benchmark::State& state)
{
  const std::vector<std::uint8_t> packet = syntheticPacket(ReturnMode::kDual);
  for ([[maybe_unused]] auto _ : state) {
    benchmark::DoNotOptimize(inspectPacket(common::ByteView(packet)));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ValidatePacket);

/// The real capture read from memory and decoded (skipped when the shared data is absent).
void BM_ReadAndDecodeRealCapture(benchmark::State& state)
{
  std::ifstream file(std::string(IFAR_SHARED_DATA) + "/vlp16/vlp16_strongest_example.pcap", std::ios::binary);
  if (!file) {
    state.SkipWithError("real capture not found under IFAR_SHARED_DATA");
    return;
  }
  file.seekg(0, std::ios::end);
  std::string contents(static_cast<std::size_t>(file.tellg()), '\0');
  file.seekg(0, std::ios::beg);
  file.read(contents.data(), static_cast<std::streamsize>(contents.size()));
  std::vector<Point> points;
  std::int64_t packets = 0;
  for ([[maybe_unused]] auto _ : state) {
    PcapReader reader(std::make_unique<std::istringstream>(contents));
    UdpDatagram datagram;
    while (reader.next(datagram) == PcapRecord::kUdpDatagram) {
      points.clear();
      decodePacket(datagram.payload, points);
      ++packets;
    }
    benchmark::DoNotOptimize(points.data());
  }
  state.SetItemsProcessed(packets);
}
BENCHMARK(BM_ReadAndDecodeRealCapture);

}  // namespace
}  // namespace ifar::velodyne
