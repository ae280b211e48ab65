#pragma once
// Why an interaction plan exists or not. Expected outcomes are values, never exceptions.

namespace ifar::interaction {

enum class PlanStatus {
  Found,               ///< a push plan that clears the passage
  DegeneratePolygon,   ///< the object polygon is a sliver, has < 3 vertices or is not simple
  ObjectTooLarge,      ///< the object does not fit the local layer
  InvalidPhysics,      ///< friction or mass estimate is zero, negative or not finite
  NoStableContact,     ///< no edge of the object admits a stable push
  TooHeavy,            ///< pushing needs more force than the vehicle's traction delivers
  UnreachableContact,  ///< the vehicle cannot reach any stable contact edge from the start waypoint
  InvalidWaypoints,    ///< start or goal waypoint lies inside an obstacle, or they coincide
  ExpansionLimit,      ///< the search used its expansion budget
  TimeBudget,          ///< the search used its time budget
  Exhausted,           ///< every reachable state was searched: no stable push sequence clears it
};

/// Stable lower-case name for logs and messages, e.g. "unreachable_contact".
const char* toString(PlanStatus status);

}  // namespace ifar::interaction
