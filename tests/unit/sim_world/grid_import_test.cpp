#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "common/geometry/polygon.hpp"
#include "common/grid_map/readers.hpp"
#include "sim/importers/grid_importer.hpp"

namespace ifar::sim {
namespace {

std::size_t cellsCovered(const std::vector<CellRectangle>& rectangles)
{
  std::size_t cells = 0;
  for (const auto& rectangle : rectangles) {
    cells += static_cast<std::size_t>(rectangle.x1 - rectangle.x0) *
             static_cast<std::size_t>(rectangle.y1 - rectangle.y0);
  }
  return cells;
}

TEST(SimWorldGridImport, MergesBlockedCellsIntoRectangles)
{
  // ##.
  // ##.
  // #..
  grid_map::GridMap map(3, 3, 0.5, geometry::Point(10, 20));
  for (const auto& [x, y] : {std::pair{0, 0}, {1, 0}, {0, 1}, {1, 1}, {0, 2}}) {
    map.set(x, y, grid_map::Cell::Blocked);
  }
  const auto rectangles = blockedRectangles(map, grid_map::UnknownPolicy::AsFree);
  ASSERT_EQ(rectangles.size(), 2u);
  EXPECT_EQ(cellsCovered(rectangles), 5u);

  GridImportSettings settings;
  const auto result = worldFromGrid(map, "tiny.map", settings);
  ASSERT_TRUE(result.ok()) << result.error();
  const auto& world = result.world();
  EXPECT_EQ(world.name, "tiny");
  EXPECT_EQ(world.obstacles.size(), 2u + 4u);  // two merged blocks and the rim
  EXPECT_DOUBLE_EQ(geometry::area(world.obstacles[0].outline) + geometry::area(world.obstacles[1].outline),
                   5 * 0.25);
  // The start is the free cell nearest the centre: (2, 1) or (1, 2) are nearest; scan order picks (2, 1).
  EXPECT_DOUBLE_EQ(world.start.x, 10 + 2.5 * 0.5);
  EXPECT_DOUBLE_EQ(world.start.y, 20 + 1.5 * 0.5);
  EXPECT_DOUBLE_EQ(world.bounds_min.x(), 9.5);
  EXPECT_DOUBLE_EQ(world.bounds_max.y(), 22.0);
}

TEST(SimWorldGridImport, StartInBlockedCellIsRejected)
{
  grid_map::GridMap map(2, 1, 1.0, geometry::Point(0, 0));
  map.set(0, 0, grid_map::Cell::Blocked);
  GridImportSettings settings;
  settings.start = geometry::Pose2{0.5, 0.5, 0.0};
  const auto result = worldFromGrid(map, "two.map", settings);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error(), "two.map: start: lies inside obstacle 'cells_0'");
}

TEST(SimWorldGridImport, MalformedMapNamesFileAndLine)
{
  const auto path = std::filesystem::temp_directory_path() / "ifar_bad_grid.map";
  {
    std::ofstream out(path);
    out << "type octile\nheight 2\nwidth 3\nmap\n..@\n.X.\n";
  }
  const auto result = importGridMapFile(path.string(), GridImportSettings());
  ASSERT_FALSE(result.ok());
  EXPECT_NE(result.error().find(path.string()), std::string::npos) << result.error();
  EXPECT_NE(result.error().find(":6"), std::string::npos) << result.error();
  std::filesystem::remove(path);
}

TEST(SimWorldGridImport, MalformedPgmNamesTheFile)
{
  const auto directory = std::filesystem::temp_directory_path() / "ifar_bad_pgm";
  std::filesystem::create_directories(directory);
  {
    std::ofstream yaml(directory / "map.yaml");
    yaml << "image: map.pgm\nresolution: 0.1\norigin: [0.0, 0.0, 0.0]\nnegate: 0\n"
            "occupied_thresh: 0.65\nfree_thresh: 0.196\n";
    std::ofstream pgm(directory / "map.pgm", std::ios::binary);
    pgm << "P5\n4 4\n255\n" << std::string(5, '\xff');  // 16 pixels promised, 5 given
  }
  const auto result = importGridMapFile((directory / "map.yaml").string(), GridImportSettings());
  ASSERT_FALSE(result.ok());
  EXPECT_NE(result.error().find("map.pgm"), std::string::npos) << result.error();
  std::filesystem::remove_all(directory);
}

TEST(SimWorldGridImport, AcrossTheCapeMovingAiMap)
{
  const std::string path = std::string(IFAR_SHARED_DATA) + "/gppc/AcrosstheCape.map";
  if (!std::filesystem::exists(path)) {
    GTEST_SKIP() << "shared data file " << path << " is absent; skipping real-data test";
  }
  const auto result = importGridMapFile(path, GridImportSettings());
  ASSERT_TRUE(result.ok()) << result.error();
  const auto& world = result.world();
  double blocked_area = 0.0;
  for (std::size_t index = 0; index + 4 < world.obstacles.size(); ++index) {
    blocked_area += geometry::area(world.obstacles[index].outline);
  }
  const auto read = grid_map::readGridMapFile(path);
  EXPECT_DOUBLE_EQ(blocked_area, static_cast<double>(read.map.count(grid_map::Cell::Blocked)));
  EXPECT_DOUBLE_EQ(world.bounds_max.x() - world.bounds_min.x(), 770.0);  // 768 cells and the rim
  EXPECT_LT(world.obstacles.size(), read.map.count(grid_map::Cell::Blocked) / 4) << "cells were merged";
}

TEST(SimWorldGridImport, WillowGarageMapServerMap)
{
  const std::string path = std::string(IFAR_SHARED_DATA) + "/maps/willow-full.yaml";
  if (!std::filesystem::exists(path)) {
    GTEST_SKIP() << "shared data file " << path << " is absent; skipping real-data test";
  }
  const auto result = importGridMapFile(path, GridImportSettings());
  ASSERT_TRUE(result.ok()) << result.error();
  const auto& world = result.world();
  EXPECT_NEAR(world.bounds_max.x() - world.bounds_min.x(), 58.4 + 0.2, 1e-9);
  EXPECT_NEAR(world.bounds_max.y() - world.bounds_min.y(), 52.6 + 0.2, 1e-9);
  EXPECT_GT(world.obstacles.size(), 100u);
}

}  // namespace
}  // namespace ifar::sim
