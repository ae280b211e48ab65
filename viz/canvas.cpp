#include "viz/canvas.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace ifar::viz {

struct Canvas::Image {
  cv::Mat pixels;  // BGR, 8 bit
};

namespace {

/// Sub-pixel precision for OpenCV's drawing calls (coordinates in 1/16 pixel).
constexpr int kShift = 4;
constexpr double kScale = 1 << kShift;

cv::Scalar bgr(Color color)
{
  return cv::Scalar(color.blue, color.green, color.red);
}

int pixelsFor(double extent, double metres_per_pixel)
{
  const double count = std::ceil(extent / metres_per_pixel - 1e-9);
  return std::max(1, static_cast<int>(count));
}

}  // namespace

Canvas::Canvas(const geometry::Point& world_min, const geometry::Point& world_max, double metres_per_pixel,
               Color background)
    : image_(std::make_unique<Image>()),
      world_min_(world_min),
      world_max_(world_max),
      metres_per_pixel_(metres_per_pixel > 0.0 && std::isfinite(metres_per_pixel) ? metres_per_pixel : 1.0)
{
  const double longest_side_m = std::max(world_max.x() - world_min.x(), world_max.y() - world_min.y());
  if (std::isfinite(longest_side_m)) {
    metres_per_pixel_ = std::max(metres_per_pixel_, longest_side_m / kMaxSidePixels);
  }
  const int width = pixelsFor(world_max.x() - world_min.x(), metres_per_pixel_);
  const int height = pixelsFor(world_max.y() - world_min.y(), metres_per_pixel_);
  image_->pixels = cv::Mat(height, width, CV_8UC3, bgr(background));
}

Canvas::~Canvas() = default;
Canvas::Canvas(Canvas&&) noexcept = default;
Canvas& Canvas::operator=(Canvas&&) noexcept = default;

int Canvas::widthPixels() const
{
  return image_->pixels.cols;
}
int Canvas::heightPixels() const
{
  return image_->pixels.rows;
}

PixelPoint Canvas::toPixel(const geometry::Point& world) const
{
  return {(world.x() - world_min_.x()) / metres_per_pixel_,
          (world_min_.y() + heightPixels() * metres_per_pixel_ - world.y()) / metres_per_pixel_};
}

namespace {

cv::Point fixedPoint(const PixelPoint& pixel)
{
  // Clamp far-away points so the fixed-point conversion cannot overflow.
  const double limit = 1e6;
  return {static_cast<int>(std::lround(std::clamp(pixel.column, -limit, limit) * kScale)),
          static_cast<int>(std::lround(std::clamp(pixel.row, -limit, limit) * kScale))};
}

}  // namespace

void Canvas::drawPolygon(const geometry::Polygon& polygon, const ShapeStyle& style)
{
  if (polygon.empty()) {
    return;
  }
  std::vector<cv::Point> points;
  points.reserve(polygon.size());
  for (const auto& vertex : polygon) {
    points.push_back(fixedPoint(toPixel(vertex)));
  }
  if (style.fill) {
    cv::fillPoly(image_->pixels, std::vector<std::vector<cv::Point>>{points}, bgr(*style.fill), cv::LINE_AA,
                 kShift);
  }
  if (style.outline) {
    cv::polylines(image_->pixels, std::vector<std::vector<cv::Point>>{points}, true, bgr(*style.outline),
                  std::max(1, style.outline_px), cv::LINE_AA, kShift);
  }
}

void Canvas::drawSegment(const geometry::Point& start, const geometry::Point& end, Color color,
                         int thickness_px)
{
  cv::line(image_->pixels, fixedPoint(toPixel(start)), fixedPoint(toPixel(end)), bgr(color),
           std::max(1, thickness_px), cv::LINE_AA, kShift);
}

void Canvas::drawPolyline(const std::vector<geometry::Point>& points, Color color, int thickness_px)
{
  if (points.size() < 2) {
    return;
  }
  std::vector<cv::Point> pixels;
  pixels.reserve(points.size());
  for (const auto& point : points) {
    pixels.push_back(fixedPoint(toPixel(point)));
  }
  cv::polylines(image_->pixels, std::vector<std::vector<cv::Point>>{pixels}, false, bgr(color),
                std::max(1, thickness_px), cv::LINE_AA, kShift);
}

void Canvas::drawCircle(const geometry::Point& centre, double radius_m, const ShapeStyle& style)
{
  const double radius_px = std::max(2.0, radius_m / metres_per_pixel_);
  const auto radius = static_cast<int>(std::lround(std::min(radius_px, 1e6) * kScale));
  const auto middle = fixedPoint(toPixel(centre));
  if (style.fill) {
    cv::circle(image_->pixels, middle, radius, bgr(*style.fill), cv::FILLED, cv::LINE_AA, kShift);
  }
  if (style.outline) {
    cv::circle(image_->pixels, middle, radius, bgr(*style.outline), std::max(1, style.outline_px),
               cv::LINE_AA, kShift);
  }
}

void Canvas::drawText(const geometry::Point& anchor, const std::string& text, Color color, int height_px)
{
  const PixelPoint pixel = toPixel(anchor);
  // Hershey simplex capitals are about 22 pixels tall at scale 1.
  const double scale = std::max(1, height_px) / 22.0;
  cv::putText(
      image_->pixels, text,
      cv::Point(static_cast<int>(std::lround(pixel.column)), static_cast<int>(std::lround(pixel.row))),
      cv::FONT_HERSHEY_SIMPLEX, scale, bgr(color), std::max(1, height_px / 12), cv::LINE_AA);
}

void Canvas::drawLegend(const std::vector<LegendEntry>& entries)
{
  if (entries.empty()) {
    return;
  }
  const int line = 18;
  const int swatch = 12;
  const double scale = 0.45;
  int text_width = 0;
  for (const auto& entry : entries) {
    int baseline = 0;
    text_width = std::max(text_width,
                          cv::getTextSize(entry.label, cv::FONT_HERSHEY_SIMPLEX, scale, 1, &baseline).width);
  }
  const cv::Rect box(6, 6, 8 + swatch + 6 + text_width + 8, 6 + line * static_cast<int>(entries.size()) + 2);
  cv::rectangle(image_->pixels, box, cv::Scalar(255, 255, 255), cv::FILLED);
  cv::rectangle(image_->pixels, box, cv::Scalar(90, 90, 90), 1);
  for (std::size_t index = 0; index < entries.size(); ++index) {
    const int top = box.y + 6 + line * static_cast<int>(index);
    cv::rectangle(image_->pixels, cv::Rect(box.x + 8, top, swatch, swatch), bgr(entries[index].color),
                  cv::FILLED);
    cv::putText(image_->pixels, entries[index].label, cv::Point(box.x + 8 + swatch + 6, top + swatch - 1),
                cv::FONT_HERSHEY_SIMPLEX, scale, cv::Scalar(20, 20, 20), 1, cv::LINE_AA);
  }
}

Color Canvas::pixel(int column, int row) const
{
  if (column < 0 || row < 0 || column >= widthPixels() || row >= heightPixels()) {
    return {};
  }
  const auto& value = image_->pixels.at<cv::Vec3b>(row, column);
  return {value[2], value[1], value[0]};
}

std::string Canvas::writePng(const std::string& path) const
{
  try {
    if (!cv::imwrite(path, image_->pixels)) {
      return path + ": could not write PNG";
    }
  } catch (const cv::Exception& error) {
    return path + ": could not write PNG (" + error.what() + ")";
  }
  return {};
}

}  // namespace ifar::viz
