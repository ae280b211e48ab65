#include "viz/world_picture.hpp"

#include <algorithm>
#include <cmath>

#include "sim/world/world_geometry.hpp"

namespace ifar::viz {

double defaultResolution(const sim::World& world)
{
  const geometry::Point extent = world.bounds_max - world.bounds_min;
  const double longest = std::max(extent.x(), extent.y()) + 2.0;
  return std::max(0.05, longest / 2000.0);
}

Canvas makeWorldCanvas(const sim::World& world, double metres_per_pixel, const WorldPictureStyle& style)
{
  const geometry::Point margin(style.margin_m, style.margin_m);
  // A band above the world keeps the legend off the map.
  const geometry::Point legend_band(0.0, kLegendBandPixels * metres_per_pixel);
  return Canvas(world.bounds_min - margin, world.bounds_max + margin + legend_band, metres_per_pixel,
                style.background);
}

void drawWorld(Canvas& canvas, const sim::World& world, const common::VehicleSettings& vehicle,
               const WorldPictureStyle& style)
{
  for (const auto& obstacle : world.obstacles) {
    canvas.drawPolygon(obstacle.outline, {style.wall, style.wall, 1});
  }
  const Color outline = Color::gray(20);
  for (const auto& object : world.objects) {
    const Color fill = sim::isPushable(object, vehicle) ? style.light_object : style.heavy_object;
    canvas.drawPolygon(sim::placedOutline(object), {fill, outline, 1});
  }
  // The start as the vehicle's footprint circle with a heading tick.
  // Markers stay visible on coarse pictures of large worlds.
  const double radius = std::max(0.5 * vehicle.width_m, 4.0 * canvas.metresPerPixel());
  const geometry::Point start = world.start.position();
  const geometry::Point ahead =
      start + 2.0 * radius * geometry::Point(std::cos(world.start.heading), std::sin(world.start.heading));
  canvas.drawCircle(start, radius, {style.start, Color::gray(0), 1});
  canvas.drawSegment(start, ahead, style.start, 2);
  const int text_px = 12;
  for (const auto& goal : world.goals) {
    canvas.drawCircle(goal.position, radius, {style.goal, Color::gray(0), 1});
    const geometry::Point label =
        goal.position + geometry::Point(radius * 1.5 + 2 * canvas.metresPerPixel(), 0.0);
    canvas.drawText(label, goal.name, style.goal, text_px);
  }
  canvas.drawLegend({{"wall / static", style.wall},
                     {"movable, pushable", style.light_object},
                     {"movable, too heavy", style.heavy_object},
                     {"start", style.start},
                     {"goal", style.goal}});
}

}  // namespace ifar::viz
