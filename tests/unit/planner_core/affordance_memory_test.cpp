#include "planner/core/affordance_memory.hpp"

#include <vector>

#include <gtest/gtest.h>

namespace ifar::planner {
namespace {

using geometry::Point;

TrackedObject objectAt(std::int64_t id, const Point& centroid)
{
  TrackedObject object;
  object.id = id;
  object.centroid = centroid;
  return object;
}

TEST(AffordanceMemory, ALostUnpushableObjectIsRecognisedWhereItWas)
{
  AffordanceMemory memory(1.0);
  interaction::ObjectPhysics physics;
  physics.ground_friction = 2.5;
  memory.learned(4, false, physics, std::nullopt);
  memory.seen({objectAt(4, Point(10.0, 5.0))});
  memory.dropped(4);
  EXPECT_EQ(memory.lostObjects(), 1U);

  EXPECT_FALSE(memory.inherit(9, Point(12.0, 5.0))) << "2 m away: another object";
  const std::optional<LearnedAffordance> inherited = memory.inherit(10, Point(10.4, 5.3));
  ASSERT_TRUE(inherited);
  EXPECT_FALSE(inherited->pushable);
  EXPECT_DOUBLE_EQ(inherited->physics.ground_friction, 2.5);
  EXPECT_EQ(memory.lostObjects(), 0U);
  EXPECT_FALSE(memory.inherit(10, Point(10.4, 5.3))) << "already known under its new id";

  // Lost again under the new id, found again under a third.
  memory.seen({objectAt(10, Point(10.5, 5.0))});
  memory.dropped(10);
  EXPECT_TRUE(memory.inherit(11, Point(10.5, 5.1)));
}

TEST(AffordanceMemory, NothingLearnedNothingInherited)
{
  AffordanceMemory memory(1.0);
  memory.seen({objectAt(1, Point(0.0, 0.0))});
  memory.dropped(1);
  EXPECT_EQ(memory.lostObjects(), 0U);
  EXPECT_FALSE(memory.inherit(2, Point(0.0, 0.0)));
}

TEST(AffordanceMemory, UnpushableStaysUnpushableAndTheNearestLostObjectIsTaken)
{
  AffordanceMemory memory(1.0);
  interaction::ObjectPhysics light;
  light.ground_friction = 0.3;
  interaction::ObjectPhysics heavy;
  heavy.ground_friction = 1.5;
  memory.learned(1, false, heavy, Point(0.0, 0.0));
  memory.learned(1, true, light, std::nullopt);  // a later estimate does not make it pushable again
  memory.learned(2, true, light, std::nullopt);
  memory.seen({objectAt(2, Point(1.2, 0.0))});  // object 1 keeps where it was when learned
  memory.dropped(1);
  memory.dropped(2);
  const std::optional<LearnedAffordance> nearest = memory.inherit(3, Point(0.8, 0.0));
  ASSERT_TRUE(nearest);
  EXPECT_TRUE(nearest->pushable);  // object 2, 0.4 m away, not object 1 at 0.8 m
  const std::optional<LearnedAffordance> other = memory.inherit(4, Point(0.1, 0.0));
  ASSERT_TRUE(other);
  EXPECT_FALSE(other->pushable);
}

}  // namespace
}  // namespace ifar::planner
