// ifar-render-graph's drawing: a log holding an old and a new DV_GRAPH and a GLOBAL_PATH; the picture
// shows the newest graph with background red, movable green, edges and the path in their colours.

#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include "viz/graph_render.hpp"

namespace ifar::viz {
namespace {

polygon_t square(std::int64_t id, std::int8_t kind, double x0, double y0, double side)
{
  polygon_t polygon{};
  polygon.id = id;
  polygon.kind = kind;
  polygon.x = {x0, x0 + side, x0 + side, x0};
  polygon.y = {y0, y0, y0 + side, y0 + side};
  polygon.num_points = 4;
  return polygon;
}

dv_graph_t exampleGraph()
{
  dv_graph_t graph{};
  graph.sequence = 2;
  graph.polygons = {square(1, polygon_t::KIND_BACKGROUND, 0.0, 0.0, 2.0),
                    square(2, polygon_t::KIND_MOVABLE, 6.0, 0.0, 2.0)};
  graph.num_polygons = 2;
  const double corners[][2] = {{0.0, 4.0}, {8.0, 4.0}, {4.0, 8.0}};
  for (int index = 0; index < 3; ++index) {
    graph_vertex_t vertex{};
    vertex.id = index + 10;
    vertex.kind = graph_vertex_t::KIND_CORNER;
    vertex.x = corners[index][0];
    vertex.y = corners[index][1];
    vertex.polygon_id = -1;
    graph.vertices.push_back(vertex);
  }
  graph.num_vertices = 3;
  graph_edge_t edge{};
  edge.from_id = 10;
  edge.to_id = 11;  // horizontal at y = 4
  edge.kind = graph_edge_t::KIND_VISIBILITY;
  edge.cost = 8.0;
  edge.object_id = -1;
  graph.edges.push_back(edge);
  edge.to_id = 99;  // names no vertex: skipped, no crash
  graph.edges.push_back(edge);
  graph.num_edges = 2;
  return graph;
}

path_t examplePath()
{
  path_t path{};
  path.valid = true;
  for (const double y : {1.0, 7.0}) {
    waypoint_t waypoint{};
    waypoint.x = 4.0;  // vertical at x = 4, between the two squares
    waypoint.y = y;
    waypoint.kind = waypoint_t::KIND_FREE;
    waypoint.object_id = -1;
    waypoint.push_plan_index = -1;
    path.waypoints.push_back(waypoint);
  }
  path.num_waypoints = 2;
  return path;
}

template <typename Message>
void writeEvent(lcm::LogFile& log, const std::string& channel, const Message& message, std::int64_t number)
{
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(message.getEncodedSize()));
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  lcm::LogEvent event{};
  event.eventnum = number;
  event.timestamp = 1'000'000 + number;
  event.channel = channel;
  event.datalen = static_cast<std::int32_t>(bytes.size());
  event.data = bytes.data();
  ASSERT_EQ(log.writeEvent(&event), 0);
}

viz::Color at(const viz::Canvas& canvas, double x, double y)
{
  const viz::PixelPoint pixel = canvas.toPixel(geometry::Point(x, y));
  return canvas.pixel(static_cast<int>(pixel.column), static_cast<int>(pixel.row));
}

/// True when `color` is within one pixel of the world point (thin lines may fall on a pixel boundary).
bool colorNear(const viz::Canvas& canvas, double x, double y, viz::Color color)
{
  const viz::PixelPoint pixel = canvas.toPixel(geometry::Point(x, y));
  for (int row = -1; row <= 1; ++row) {
    for (int column = -1; column <= 1; ++column) {
      if (canvas.pixel(static_cast<int>(pixel.column) + column, static_cast<int>(pixel.row) + row) == color) {
        return true;
      }
    }
  }
  return false;
}

TEST(PlannerGraphRender, LastGraphAndPathOfALogAreDrawnInTheirColours)
{
  const std::string log_path = std::string(IFAR_BINARY_DIR) + "/graph_render_test.lcmlog";
  std::remove(log_path.c_str());
  {
    lcm::LogFile log(log_path, "w");
    ASSERT_TRUE(log.good());
    dv_graph_t old_graph{};
    old_graph.polygons = {square(1, polygon_t::KIND_MOVABLE, 0.0, 0.0, 2.0)};  // superseded below
    old_graph.num_polygons = 1;
    writeEvent(log, "DV_GRAPH", old_graph, 0);
    writeEvent(log, "DV_GRAPH", exampleGraph(), 1);
    writeEvent(log, "GLOBAL_PATH", examplePath(), 2);
    lcm::LogEvent junk{};
    junk.eventnum = 3;
    junk.timestamp = 1'000'003;
    junk.channel = "GLOBAL_PATH";
    std::uint8_t garbage[3] = {1, 2, 3};
    junk.datalen = 3;
    junk.data = garbage;
    ASSERT_EQ(log.writeEvent(&junk), 0);
  }
  const LastMessages last = readLastMessages(log_path, "DV_GRAPH", "GLOBAL_PATH");
  ASSERT_EQ(last.error, "");
  ASSERT_TRUE(last.graph.has_value());
  ASSERT_TRUE(last.path.has_value());
  EXPECT_EQ(last.graph->sequence, 2);
  EXPECT_EQ(last.undecodable, 1U);

  RenderOptions options;
  options.metres_per_pixel = 0.05;
  const viz::Canvas canvas = renderGraph(*last.graph, last.path, options);
  // Extent (0, 0)..(8, 8) plus 1 m margin at 5 cm a pixel. The legend covers the top-left corner.
  EXPECT_EQ(canvas.widthPixels(), 200);
  EXPECT_EQ(canvas.heightPixels(), 200);
  EXPECT_EQ(at(canvas, 1.0, 1.0), colors::kBackground);  // inside the background square
  EXPECT_EQ(at(canvas, 7.0, 1.0), colors::kMovable);     // inside the movable square
  EXPECT_TRUE(colorNear(canvas, 7.0, 4.0, colors::kVisibilityEdge));
  EXPECT_TRUE(colorNear(canvas, 4.0, 2.5, colors::kPath));
  EXPECT_FALSE(colorNear(canvas, 7.0, 4.5, colors::kVisibilityEdge));
  EXPECT_EQ(at(canvas, 6.0, 6.0), (viz::Color{255, 255, 255}));  // nothing drawn here

  const std::string png = std::string(IFAR_BINARY_DIR) + "/graph_render_test.png";
  EXPECT_EQ(canvas.writePng(png), "");
}

TEST(PlannerGraphRender, ClockwiseHolesAreClearedInsideTheirObstacle)
{
  dv_graph_t graph{};
  graph.polygons = {square(1, polygon_t::KIND_BACKGROUND, 0.0, 0.0, 4.0),
                    square(2, polygon_t::KIND_BACKGROUND, 1.0, 1.0, 2.0)};
  std::reverse(graph.polygons[1].x.begin(), graph.polygons[1].x.end());  // clockwise: a room inside walls
  std::reverse(graph.polygons[1].y.begin(), graph.polygons[1].y.end());
  graph.num_polygons = 2;
  RenderOptions options;
  options.margin_m = 4.0;  // keeps the legend away from the walls
  const viz::Canvas canvas = renderGraph(graph, std::nullopt, options);
  EXPECT_EQ(at(canvas, 2.0, 2.0), (viz::Color{255, 255, 255}));  // the free room
  EXPECT_EQ(at(canvas, 0.5, 0.5), colors::kBackground);          // the wall band
  EXPECT_EQ(at(canvas, 3.5, 2.0), colors::kBackground);
}

TEST(PlannerGraphRender, AWindowDrawsThatRectangleOnlyWithTheTruthOutlined)
{
  RenderOptions options;
  options.metres_per_pixel = 0.01;          // the legend covers the top-left 1.5 m x 1.1 m
  options.window = parseWindow("9,0,5,4");  // any two opposite corners
  ASSERT_TRUE(options.window.has_value());
  RunOverlay run;
  run.truth = {{{6.5, 0.5}, {8.5, 0.5}, {8.5, 2.5}, {6.5, 2.5}}};  // the object really is here
  const viz::Canvas canvas = renderGraph(exampleGraph(), examplePath(), options, run);
  EXPECT_EQ(canvas.widthPixels(), 400);
  EXPECT_EQ(canvas.heightPixels(), 400);
  EXPECT_EQ(at(canvas, 7.0, 1.0), colors::kMovable);
  EXPECT_TRUE(colorNear(canvas, 8.5, 1.5, colors::kTruth));   // its outline, beyond the perceived square
  EXPECT_FALSE(colorNear(canvas, 7.0, 1.5, colors::kTruth));  // outlines only
  EXPECT_LT(canvas.toPixel(geometry::Point(1.0, 1.0)).column, 0.0);  // the background square is left out
}

TEST(PlannerGraphRender, WindowTextIsFourNumbersMakingARectangle)
{
  const std::optional<Window> window = parseWindow("-1.5,2,3,4.25");
  ASSERT_TRUE(window.has_value());
  EXPECT_DOUBLE_EQ(window->low.x(), -1.5);
  EXPECT_DOUBLE_EQ(window->low.y(), 2.0);
  EXPECT_DOUBLE_EQ(window->high.x(), 3.0);
  EXPECT_DOUBLE_EQ(window->high.y(), 4.25);
  for (const char* bad :
       {"", "1,2,3", "1,2,3,x", "1,2,3,4,5", "1,2,3,4 ", "1;2;3;4", "nan,0,1,1", "0,0,0,5", "0,3,5,3"}) {
    EXPECT_FALSE(parseWindow(bad).has_value()) << "'" << bad << "'";
  }
}

TEST(PlannerGraphRender, MissingLogIsAnError)
{
  const LastMessages last = readLastMessages("/nonexistent/planner.lcmlog", "DV_GRAPH", "GLOBAL_PATH");
  EXPECT_NE(last.error.find("/nonexistent/planner.lcmlog"), std::string::npos);
  EXPECT_FALSE(last.graph.has_value());
}

}  // namespace
}  // namespace ifar::viz
