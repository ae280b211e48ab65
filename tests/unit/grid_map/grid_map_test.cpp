#include <cstdio>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "common/geometry/polygon.hpp"
#include "common/grid_map/boundaries.hpp"
#include "common/grid_map/readers.hpp"

namespace ifar::grid_map {
namespace {

/// A file in the test's temporary directory, removed when the object goes.
class TemporaryFile {
 public:
  TemporaryFile(const std::string& name, const std::string& contents)
      : path_(::testing::TempDir() + "/" + name)
  {
    std::ofstream(path_, std::ios::binary) << contents;
  }
  ~TemporaryFile() { std::remove(path_.c_str()); }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

GridMap fromRows(const std::vector<std::string>& rows)
{
  GridMap map(static_cast<int>(rows.front().size()), static_cast<int>(rows.size()), 1.0,
              geometry::Point::Zero());
  for (std::size_t y = 0; y < rows.size(); ++y) {
    for (std::size_t x = 0; x < rows[y].size(); ++x) {
      if (rows[y][x] == '@') {
        map.set(static_cast<int>(x), static_cast<int>(y), Cell::Blocked);
      }
    }
  }
  return map;
}

TEST(MovingAiMap, ReadsCellsAndSize)
{
  const TemporaryFile file("small.map", "type octile\nheight 2\nwidth 3\nmap\n.@T\nS.W\n");
  const auto result = readMovingAiMap(file.path());
  ASSERT_TRUE(result.ok()) << result.error;
  EXPECT_EQ(result.map.width(), 3);
  EXPECT_EQ(result.map.height(), 2);
  EXPECT_EQ(result.map.at(0, 0), Cell::Free);
  EXPECT_EQ(result.map.at(1, 0), Cell::Blocked);
  EXPECT_EQ(result.map.at(2, 0), Cell::Blocked);
  EXPECT_EQ(result.map.at(0, 1), Cell::Free);
  EXPECT_EQ(result.map.at(2, 1), Cell::Blocked);
  EXPECT_TRUE(result.map.blocked(-1, 0));  // outside counts as blocked
  EXPECT_EQ(result.map.count(Cell::Blocked), 3u);
}

TEST(MovingAiMap, ShortRowNamesFileAndLine)
{
  const TemporaryFile file("short.map", "type octile\nheight 2\nwidth 3\nmap\n...\n..\n");
  const auto result = readMovingAiMap(file.path());
  EXPECT_FALSE(result.ok());
  EXPECT_EQ(result.error, file.path() + ":6: row has 2 cells, expected 3");
}

TEST(MovingAiMap, UnknownCharacterIsAnError)
{
  const TemporaryFile file("bad.map", "type octile\nheight 1\nwidth 3\nmap\n.x.\n");
  const auto result = readMovingAiMap(file.path());
  EXPECT_EQ(result.error, file.path() + ":5: column 2: unknown cell character 'x'");
}

TEST(MovingAiMap, MissingHeaderIsAnError)
{
  const TemporaryFile file("header.map", "type octile\nwidth 3\n");
  EXPECT_NE(readMovingAiMap(file.path()).error.find(":2: expected 'height <number>'"), std::string::npos);
  EXPECT_EQ(readMovingAiMap("/nonexistent.map").error, "/nonexistent.map: cannot open");
}

TEST(MovingAiScenarios, ReadsQueries)
{
  const TemporaryFile file("a.scen", "version 1\n1\ta.map\t768\t768\t283\t492\t286\t497\t5.830951895\n");
  const auto result = readMovingAiScenarios(file.path());
  ASSERT_TRUE(result.ok()) << result.error;
  ASSERT_EQ(result.scenarios.size(), 1u);
  EXPECT_EQ(result.scenarios[0].map_name, "a.map");
  EXPECT_EQ(result.scenarios[0].start, geometry::Point(283, 492));
  EXPECT_EQ(result.scenarios[0].goal, geometry::Point(286, 497));
  EXPECT_DOUBLE_EQ(result.scenarios[0].optimal_length, 5.830951895);
}

TEST(MovingAiScenarios, BadLineNamed)
{
  const TemporaryFile file("b.scen", "version 1\n1\ta.map\t768\t768\t283\n");
  EXPECT_EQ(readMovingAiScenarios(file.path()).error.rfind(file.path() + ":2: expected", 0), 0u);
}

TEST(MapServer, ReadsPgmAndFlipsRows)
{
  // 3 x 2 image: top row black (occupied), white, grey; bottom row white, white, black.
  std::string pgm = "P5\n# comment\n3 2\n255\n";
  pgm += std::string{'\x00', '\xff', '\xcd', '\xff', '\xff', '\x00'};
  const TemporaryFile image("tiny.pgm", pgm);
  const TemporaryFile yaml("tiny.yaml",
                           "image: tiny.pgm\nresolution: 0.5\norigin: [1.0, 2.0, 0.0]\nnegate: 0\n"
                           "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  const auto result = readMapServer(yaml.path());
  ASSERT_TRUE(result.ok()) << result.error;
  const GridMap& map = result.map;
  EXPECT_EQ(map.width(), 3);
  EXPECT_EQ(map.height(), 2);
  EXPECT_DOUBLE_EQ(map.resolution(), 0.5);
  // Image row 0 (top) is y = 1.
  EXPECT_EQ(map.at(0, 1), Cell::Blocked);
  EXPECT_EQ(map.at(1, 1), Cell::Free);
  EXPECT_EQ(map.at(2, 1), Cell::Unknown);
  EXPECT_EQ(map.at(2, 0), Cell::Blocked);
  EXPECT_EQ(map.cornerToWorld(1, 1), geometry::Point(1.5, 2.5));
  EXPECT_EQ(map.cellAt(geometry::Point(1.1, 2.9)), (CellIndex{0, 1}));
}

TEST(MapServer, UnknownKeyAndMissingImageNamed)
{
  const TemporaryFile yaml("bad.yaml", "image: none.pgm\nresolution: 0.1\norigin: [0, 0, 0]\ncolour: red\n");
  EXPECT_EQ(readMapServer(yaml.path()).error, yaml.path() + ": key 'colour': unknown key");
  const TemporaryFile missing("missing.yaml", "image: none.pgm\nresolution: 0.1\norigin: [0, 0, 0]\n");
  EXPECT_NE(readMapServer(missing.path()).error.find("none.pgm: cannot open"), std::string::npos);
  const TemporaryFile bad_resolution("res.yaml", "image: none.pgm\nresolution: -1\norigin: [0, 0, 0]\n");
  EXPECT_EQ(readMapServer(bad_resolution.path()).error,
            bad_resolution.path() + ": key 'resolution': missing or not a positive number");
}

TEST(BoundedInput, AHeaderClaimingMoreCellsThanTheFileHoldsIsRefusedBeforeAllocating)
{
  const TemporaryFile map("huge.map", "type octile\nheight 20000\nwidth 20000\nmap\n....\n");
  EXPECT_EQ(readMovingAiMap(map.path()).error,
            map.path() + ": the header says 20000 x 20000 cells but only 5 bytes follow it");
  std::string pgm = "P5\n20000 20000\n255\n";
  pgm += std::string(16, '\xff');
  const TemporaryFile image("huge.pgm", pgm);
  const TemporaryFile yaml("huge.yaml", "image: huge.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n");
  EXPECT_EQ(readMapServer(yaml.path()).error,
            image.path() + ": the header says 20000 x 20000 cells but only 16 bytes follow it");
}

TEST(BoundedInput, TheCellLimitIsConfigurable)
{
  const TemporaryFile map("four.map", "type octile\nheight 2\nwidth 2\nmap\n..\n..\n");
  EXPECT_TRUE(readMovingAiMap(map.path()).ok());
  const TemporaryFile huge("claims.map", "type octile\nheight 100000\nwidth 100000\nmap\n....\n");
  EXPECT_EQ(readMovingAiMap(huge.path()).error,
            huge.path() + ": 100000 x 100000 cells exceed the limit of 400000000");
  MapReadLimits limits;
  limits.max_cells = 3;
  EXPECT_EQ(readMovingAiMap(map.path(), limits).error, map.path() + ": 2 x 2 cells exceed the limit of 3");
}

TEST(BoundedInput, ADeviceAsImageIsRefused)
{
  const TemporaryFile yaml("zero.yaml", "image: /dev/zero\nresolution: 0.05\norigin: [0, 0, 0]\n");
  EXPECT_EQ(readMapServer(yaml.path()).error, "/dev/zero: not a regular file (image of " + yaml.path() + ")");
  EXPECT_EQ(readMovingAiMap("/dev/zero").error, "/dev/zero: not a regular file");
}

TEST(MapServer, WillowGarage)
{
  const std::string path = std::string(IFAR_SHARED_DATA) + "/maps/willow-full.yaml";
  if (!std::ifstream(path)) {
    GTEST_SKIP() << "shared data absent: " << path;
  }
  const auto result = readMapServer(path);
  ASSERT_TRUE(result.ok()) << result.error;
  EXPECT_EQ(result.map.width(), 584);
  EXPECT_EQ(result.map.height(), 526);
  EXPECT_DOUBLE_EQ(result.map.resolution(), 0.1);
  EXPECT_GT(result.map.count(Cell::Blocked), 1000u);
  EXPECT_GT(result.map.count(Cell::Free), 10000u);
}

TEST(Boundaries, SingleBlockedCell)
{
  const GridMap map = fromRows({"...", ".@.", "..."});
  const auto loops = blockedBoundaries(map);
  ASSERT_EQ(loops.size(), 2u);
  // One loop is the map's rim (clockwise: blocked outside on the left), one the cell (counter-clockwise).
  const double first = geometry::signedArea(loops[0]);
  const double second = geometry::signedArea(loops[1]);
  EXPECT_DOUBLE_EQ(std::min(first, second), -9.0);
  EXPECT_DOUBLE_EQ(std::max(first, second), 1.0);
  const auto& cell = first > 0 ? loops[0] : loops[1];
  EXPECT_EQ(cell.size(), 4u);
}

TEST(Boundaries, DiagonalTouchJoinsOneLoop)
{
  const GridMap map = fromRows({"....", ".@..", "..@.", "...."});
  const auto loops = blockedBoundaries(map);
  ASSERT_EQ(loops.size(), 2u);
  const auto& joined = geometry::signedArea(loops[0]) > 0 ? loops[0] : loops[1];
  EXPECT_EQ(joined.size(), 8u);  // the touching corner (2, 2) appears twice
  EXPECT_EQ(std::count(joined.begin(), joined.end(), geometry::Point(2, 2)), 2);
  EXPECT_DOUBLE_EQ(geometry::signedArea(joined), 2.0);
}

TEST(Boundaries, CollinearSidesMerged)
{
  const GridMap map = fromRows({".....", ".@@@.", "....."});
  const auto loops = blockedBoundaries(map);
  ASSERT_EQ(loops.size(), 2u);
  EXPECT_EQ(loops[0].size(), 4u);
  EXPECT_EQ(loops[1].size(), 4u);
}

TEST(GridMap, InflationBlocksCellsWithinRadius)
{
  const GridMap map = fromRows({".....", ".....", "..@..", ".....", "....."});
  const GridMap inflated = map.inflated(1.0);
  EXPECT_EQ(inflated.at(1, 2), Cell::Blocked);  // centre 0.5 from the square
  EXPECT_EQ(inflated.at(1, 1), Cell::Blocked);  // corner gap sqrt(0.5) < 1
  EXPECT_EQ(inflated.at(0, 2), Cell::Free);     // 1.5 away
  EXPECT_EQ(inflated.count(Cell::Blocked), 9u);
  EXPECT_EQ(map.inflated(0.0).count(Cell::Blocked), 1u);
}

}  // namespace
}  // namespace ifar::grid_map
