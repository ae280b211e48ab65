#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "sim/generators/generators.hpp"
#include "sim/world/world_geometry.hpp"
#include "viz/canvas.hpp"
#include "viz/world_picture.hpp"

namespace ifar::viz {
namespace {

/// Width and height from a PNG's IHDR chunk (big-endian at bytes 16..23), or -1 when not a PNG.
std::pair<int, int> pngSize(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  unsigned char header[24] = {};
  in.read(reinterpret_cast<char*>(header), sizeof(header));
  const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (!in || !std::equal(signature, signature + 8, header)) {
    return {-1, -1};
  }
  auto read32 = [&](int offset) {
    return (header[offset] << 24) | (header[offset + 1] << 16) | (header[offset + 2] << 8) |
           header[offset + 3];
  };
  return {read32(16), read32(20)};
}

Color colourAt(const Canvas& canvas, const geometry::Point& world)
{
  const auto pixel = canvas.toPixel(world);
  return canvas.pixel(static_cast<int>(pixel.column), static_cast<int>(pixel.row));
}

TEST(RenderCanvas, MapsWorldToPixelsWithYUp)
{
  const Canvas canvas(geometry::Point(-1, 2), geometry::Point(9, 7), 0.05);
  EXPECT_EQ(canvas.widthPixels(), 200);
  EXPECT_EQ(canvas.heightPixels(), 100);
  const auto bottom_left = canvas.toPixel(geometry::Point(-1, 2));
  EXPECT_DOUBLE_EQ(bottom_left.column, 0.0);
  EXPECT_DOUBLE_EQ(bottom_left.row, 100.0);
  const auto top_right = canvas.toPixel(geometry::Point(9, 7));
  EXPECT_DOUBLE_EQ(top_right.column, 200.0);
  EXPECT_DOUBLE_EQ(top_right.row, 0.0);
}

TEST(RenderCanvas, AResolutionTooFineForTheSizeIsCoarsenedToTheLongestSideAllowed)
{
  // A 330 m strip 3.3 m wide at 1 mm a pixel would be 330,000 pixels long.
  const Canvas canvas(geometry::Point(0, 0), geometry::Point(330, 3.3), 0.001);
  EXPECT_EQ(canvas.widthPixels(), Canvas::kMaxSidePixels);
  EXPECT_DOUBLE_EQ(canvas.metresPerPixel(), 330.0 / Canvas::kMaxSidePixels);
  EXPECT_EQ(canvas.heightPixels(), 164);                                    // the same scale both ways
  const Canvas small(geometry::Point(0, 0), geometry::Point(10, 5), 0.01);  // fits: as asked
  EXPECT_DOUBLE_EQ(small.metresPerPixel(), 0.01);
  EXPECT_EQ(small.widthPixels(), 1000);
}

TEST(RenderCanvas, DrawsFilledPolygonsSegmentsAndCircles)
{
  Canvas canvas(geometry::Point(0, 0), geometry::Point(10, 10), 0.1);
  const Color red{200, 0, 0};
  const Color blue{0, 0, 200};
  canvas.drawPolygon(
      {geometry::Point(1, 1), geometry::Point(4, 1), geometry::Point(4, 3), geometry::Point(1, 3)},
      {red, std::nullopt, 1});
  canvas.drawSegment(geometry::Point(6, 1), geometry::Point(6, 9), blue, 3);
  canvas.drawCircle(geometry::Point(8, 8), 0.5, {Color{0, 150, 0}, std::nullopt, 1});
  EXPECT_EQ(colourAt(canvas, geometry::Point(2.5, 2.0)), red);
  EXPECT_EQ(colourAt(canvas, geometry::Point(6.0, 5.0)), blue);
  EXPECT_EQ(colourAt(canvas, geometry::Point(8.0, 8.0)), (Color{0, 150, 0}));
  EXPECT_EQ(colourAt(canvas, geometry::Point(2.5, 5.0)), (Color{255, 255, 255}));
  EXPECT_EQ(colourAt(canvas, geometry::Point(2.5, 0.5)), (Color{255, 255, 255}));  // y up: below the box
}

TEST(RenderCanvas, WritePngReportsUnwritablePath)
{
  const Canvas canvas(geometry::Point(0, 0), geometry::Point(1, 1), 0.1);
  EXPECT_NE(canvas.writePng("/nonexistent-dir/x.png").find("/nonexistent-dir/x.png"), std::string::npos);
}

TEST(RenderWorldPicture, DemoRoomPngHasExpectedSizeAndColoursWhereThingsAre)
{
  const auto generated = sim::generateWorld(sim::WorldKind::DemoRoom, 1);
  ASSERT_TRUE(generated.ok()) << generated.error();
  const auto& world = generated.world();
  const WorldPictureStyle style;
  Canvas canvas = makeWorldCanvas(world, 0.05, style);
  drawWorld(canvas, world, common::VehicleSettings(), style);
  // 32 m + 2 x 1 m margin at 5 cm per pixel, plus the legend band on top.
  EXPECT_EQ(canvas.widthPixels(), 680);
  EXPECT_EQ(canvas.heightPixels(), 680 + kLegendBandPixels);

  // Inside the south wall (y 0..0.3), the light doorway box and a heavy box.
  EXPECT_EQ(colourAt(canvas, geometry::Point(16.0, 0.15)), style.wall);
  EXPECT_EQ(colourAt(canvas, world.objects.at(0).pose.position()), style.light_object);
  EXPECT_EQ(colourAt(canvas, world.objects.at(1).pose.position()), style.heavy_object);
  EXPECT_EQ(colourAt(canvas, world.goals.at(0).position), style.goal);
  EXPECT_EQ(colourAt(canvas, world.start.position()), style.start);
  EXPECT_EQ(colourAt(canvas, geometry::Point(16.0, 12.0)), style.background);

  const auto path = (std::filesystem::temp_directory_path() / "ifar_render_demo.png").string();
  ASSERT_EQ(canvas.writePng(path), "");
  EXPECT_EQ(pngSize(path), std::make_pair(680, 680 + kLegendBandPixels));
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace ifar::viz
