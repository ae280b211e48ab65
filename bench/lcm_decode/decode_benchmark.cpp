// LCM's generated decode against the checked decode (claim check first), on a VLP-16 data packet and
// on a DV_GRAPH of 2,000 vertices, 200 polygons of 12 points and 20,000 edges.

#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

#include "ifar/dv_graph_t.hpp"
#include "ifar/velodyne_packet_t.hpp"
#include "lcmtypes/checked_decode.hpp"

namespace {

template <typename Message>
std::vector<std::uint8_t> encode(const Message& message)
{
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(message.getEncodedSize()));
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

std::vector<std::uint8_t> packetBytes()
{
  ifar::velodyne_packet_t packet{};
  packet.port = 2368;
  packet.size = 1206;
  packet.data.assign(1206, 0x5a);
  return encode(packet);
}

std::vector<std::uint8_t> graphBytes()
{
  ifar::dv_graph_t graph{};
  graph.num_polygons = 200;
  graph.polygons.resize(200);
  for (auto& polygon : graph.polygons) {
    polygon.num_points = 12;
    polygon.x.assign(12, 1.0);
    polygon.y.assign(12, 2.0);
  }
  graph.num_vertices = 2000;
  graph.vertices.resize(2000);
  graph.num_edges = 20000;
  graph.edges.resize(20000);
  return encode(graph);
}

template <typename Message>
void decodeUnchecked(benchmark::State& state, const std::vector<std::uint8_t>& bytes)
{
  for ([[maybe_unused]] auto _ : state) {
    Message message;
    benchmark::DoNotOptimize(message.decode(bytes.data(), 0, static_cast<int>(bytes.size())));
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes.size()));
}

template <typename Message>
void decodeChecked(benchmark::State& state, const std::vector<std::uint8_t>& bytes)
{
  for ([[maybe_unused]] auto _ : state) {
    Message message;
    benchmark::DoNotOptimize(ifar::lcmtypes::decodeLcm(message, bytes.data(), bytes.size()).bytes);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes.size()));
}

void BM_VelodynePacketGeneratedDecode(benchmark::State& state)
{
  decodeUnchecked<ifar::velodyne_packet_t>(state, packetBytes());
}
void BM_VelodynePacketCheckedDecode(benchmark::State& state)
{
  decodeChecked<ifar::velodyne_packet_t>(state, packetBytes());
}
void BM_DvGraphGeneratedDecode(benchmark::State& state)
{
  decodeUnchecked<ifar::dv_graph_t>(state, graphBytes());
}
void BM_DvGraphCheckedDecode(benchmark::State& state)
{
  decodeChecked<ifar::dv_graph_t>(state, graphBytes());
}

}  // namespace

BENCHMARK(BM_VelodynePacketGeneratedDecode);
BENCHMARK(BM_VelodynePacketCheckedDecode);
BENCHMARK(BM_DvGraphGeneratedDecode)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DvGraphCheckedDecode)->Unit(benchmark::kMicrosecond);
