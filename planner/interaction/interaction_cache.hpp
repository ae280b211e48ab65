#pragma once
// Push plans per object, redone only when the object moved, its surroundings changed or its affordance
// (physics estimate) changed. The planner daemon keeps one cache and asks it every frame, within its
// per-frame budget; a cached answer costs a signature comparison.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>

#include "planner/interaction/convex_polygon.hpp"
#include "planner/interaction/interaction_planner.hpp"

namespace ifar::interaction {

class InteractionCache {
 public:
  /// Centroid shifts of the object and its surroundings within kShiftToleranceM or a cell, object area
  /// changes within a tenth or the raster's band, and changes of the surroundings' area within
  /// kAreaToleranceM2 reuse the plans. `outline_cell_m`: the side of the raster cells the outlines were
  /// traced on (0: exact outlines). Each side of a traced outline can move by a cell from one scan to the
  /// next with nothing moved (a return's range noise or the pose's jitter puts it over a cell border), so
  /// a centroid shift within a cell and an area change within half a cell along the outline are the
  /// raster's, not the object's.
  explicit InteractionCache(const InteractionSettings& settings, double outline_cell_m = 0.0);

  /// True when interactionsFor() would have to plan (unknown object, moved, new surroundings or physics).
  bool stale(std::int64_t object_id, const LocalScene& scene, std::size_t movable_index,
             const ObjectPhysics& physics) const;

  /// The object's interactions, planned now when stale(); `replanned` tells whether the answer is new.
  /// A replan that finds fewer pushes than the plans in hand is not taken while only the object's own
  /// outline changed (same physics, centroid within `keep_radius_m` of where those plans were found, the
  /// same static surroundings in the window those plans were found in): a part of the object hidden in one
  /// view and seen in the next must not make a push come and go frame by frame. Other movable objects are
  /// left out of that comparison: their outlines come and go with the view in the same way. The touch decides
  /// such a push (AFFORDANCE, then invalidate()). The reference stays valid until the next call for the same
  /// object or invalidate()/forget().
  const ObjectInteractions& interactionsFor(std::int64_t object_id, const LocalScene& scene,
                                            std::size_t movable_index, const ObjectPhysics& physics,
                                            bool& replanned);

  /// Forces a replan next time (e.g. AFFORDANCE said the estimate was wrong in a way physics misses).
  void invalidate(std::int64_t object_id);
  /// Drops the object (it left the map).
  void forget(std::int64_t object_id);
  std::size_t size() const { return entries_.size(); }

 private:
  /// What the plans depend on. The surroundings are summarised by the obstacle area inside the analysis
  /// window and its centroid, not by a polygon count: a scene built from a noisy raster splits its
  /// obstacles differently every frame while the area barely changes.
  struct Signature {
    geometry::Point object_centroid = geometry::Point::Zero();
    double object_area = 0.0;
    double object_perimeter = 0.0;
    double neighbour_area = 0.0;
    geometry::Point neighbour_centroid = geometry::Point::Zero();
    ObjectPhysics physics;
    /// The analysis window the surroundings were summarised in.
    Bounds window{geometry::Point::Zero(), geometry::Point::Zero()};
  };
  struct Entry {
    Signature signature;
    ObjectInteractions interactions;
    /// The view `interactions` were planned from (a kept view does not replace it), its surroundings
    /// summarised without other movable objects (only keepsPlans() reads it).
    Signature planned;
    bool valid = false;
  };

  /// Which obstacles a signature's surroundings summarise.
  enum class Neighbours { All, StaticOnly };

  /// The view's signature; its surroundings are summarised in `window`, by default the object's bounds
  /// grown by the connectivity window margin (which moves with the object's outline).
  Signature signatureOf(const LocalScene& scene, std::size_t movable_index, const ObjectPhysics& physics,
                        const std::optional<Bounds>& window = std::nullopt,
                        Neighbours neighbours = Neighbours::All) const;
  bool same(const Signature& first, const Signature& second) const;
  bool sameSurroundings(const Signature& first, const Signature& second) const;
  /// True when `entry` (valid) keeps its plans against `fresh`, planned from the view `signature` of
  /// object `movable_index` in `scene`.
  bool keepsPlans(const Entry& entry, const LocalScene& scene, std::size_t movable_index,
                  const Signature& signature, const ObjectInteractions& fresh) const;

  static constexpr double kShiftToleranceM = 0.1;
  static constexpr double kAreaToleranceM2 = 0.5;
  /// A view with fewer pushes keeps the plans in hand while the object stays this close (keepsPlans).
  static constexpr double kKeepRadiusM = 0.3;

  double shiftTolerance() const { return std::max(kShiftToleranceM, outline_cell_m_); }

  InteractionSettings settings_;
  double outline_cell_m_;
  std::map<std::int64_t, Entry> entries_;
};

}  // namespace ifar::interaction
