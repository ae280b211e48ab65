#pragma once
// A raster canvas in world coordinates for PNG pictures of worlds, graphs, paths and trajectories.
// World metres map to pixels with a fixed resolution and y up; OpenCV stays inside canvas.cpp.
//
//   ifar::viz::Canvas canvas(world_min, world_max, 0.05);   // 5 cm per pixel
//   canvas.drawPolygon(wall, {Color::gray(60), Color::gray(60)});
//   canvas.drawPolyline(path, Color{220, 30, 30}, 2);
//   canvas.writePng("world.png");

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/geometry/point.hpp"
#include "common/geometry/polygon.hpp"

namespace ifar::viz {

struct Color {
  std::uint8_t red = 0;
  std::uint8_t green = 0;
  std::uint8_t blue = 0;

  static Color gray(std::uint8_t level) { return {level, level, level}; }
  bool operator==(const Color& other) const
  {
    return red == other.red && green == other.green && blue == other.blue;
  }
  bool operator!=(const Color& other) const { return !(*this == other); }
};

/// How a closed shape is drawn: optional fill, optional outline of `outline_px` pixels.
struct ShapeStyle {
  std::optional<Color> fill;
  std::optional<Color> outline;
  int outline_px = 1;
};

struct LegendEntry {
  std::string label;
  Color color;
};

struct PixelPoint {
  double column = 0.0;  // 0 at the left edge
  double row = 0.0;     // 0 at the top edge
};

class Canvas {
 public:
  /// Covers the world rectangle [world_min, world_max] at `metres_per_pixel` (> 0; width and height are
  /// ceil(extent / metres_per_pixel), at least 1), filled with `background`. A resolution that would make
  /// a side longer than kMaxSidePixels is coarsened to fit (metresPerPixel() tells what was used): a
  /// 330 m tunnel at 1 cm a pixel would take 2.7 GB.
  static constexpr int kMaxSidePixels = 16384;
  Canvas(const geometry::Point& world_min, const geometry::Point& world_max, double metres_per_pixel,
         Color background = Color{255, 255, 255});
  ~Canvas();
  Canvas(Canvas&&) noexcept;
  Canvas& operator=(Canvas&&) noexcept;
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;

  int widthPixels() const;
  int heightPixels() const;
  double metresPerPixel() const { return metres_per_pixel_; }

  /// World point to pixel coordinates (y flipped: world y up, rows down).
  PixelPoint toPixel(const geometry::Point& world) const;

  void drawPolygon(const geometry::Polygon& polygon, const ShapeStyle& style);
  void drawSegment(const geometry::Point& start, const geometry::Point& end, Color color,
                   int thickness_px = 1);
  void drawPolyline(const std::vector<geometry::Point>& points, Color color, int thickness_px = 1);
  /// A circle of `radius_m` metres, never smaller than 2 pixels so markers stay visible.
  void drawCircle(const geometry::Point& centre, double radius_m, const ShapeStyle& style);
  /// Text with its baseline starting at `anchor`; `height_px` is the approximate capital height.
  void drawText(const geometry::Point& anchor, const std::string& text, Color color, int height_px = 12);
  /// A boxed legend in the top-left corner, one coloured swatch and label per entry.
  void drawLegend(const std::vector<LegendEntry>& entries);

  /// The colour at a pixel (column, row); black outside the canvas.
  Color pixel(int column, int row) const;

  /// Writes a PNG. Returns an empty string on success, else the error naming the path.
  std::string writePng(const std::string& path) const;

 private:
  struct Image;
  std::unique_ptr<Image> image_;
  geometry::Point world_min_;
  geometry::Point world_max_;
  double metres_per_pixel_;
};

}  // namespace ifar::viz
