#pragma once
// A picture of a simulator world: walls, movable objects (pushable and too heavy in different colours),
// the vehicle's start and the goals, with a legend.

#include <string>

#include "common/vehicle.hpp"
#include "sim/world/world.hpp"
#include "viz/canvas.hpp"

namespace ifar::viz {

struct WorldPictureStyle {
  Color background{255, 255, 255};
  Color wall{70, 70, 70};
  Color light_object{245, 150, 30};  // the vehicle can push it
  Color heavy_object{150, 25, 35};   // sliding it needs more than the vehicle's push
  Color start{30, 160, 60};
  Color goal{30, 90, 220};
  double margin_m = 1.0;  // space around the world's bounds
};

/// Pixels above the world reserved for the legend.
constexpr int kLegendBandPixels = 110;

/// The resolution ifar-render uses when none is given: 5 cm per pixel, coarser for large worlds so the
/// longer side stays within about 2000 pixels.
double defaultResolution(const sim::World& world);

/// A canvas covering the world's bounds plus the margin, and the legend band above them.
Canvas makeWorldCanvas(const sim::World& world, double metres_per_pixel, const WorldPictureStyle& style);

/// Draws the world onto a canvas made by makeWorldCanvas.
void drawWorld(Canvas& canvas, const sim::World& world, const common::VehicleSettings& vehicle,
               const WorldPictureStyle& style);

}  // namespace ifar::viz
