#include "sim/physics/physics_world.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <box2d/box2d.h>

#include "common/geometry/angle.hpp"
#include "sim/physics/convex_pieces.hpp"

namespace ifar::sim::physics {
namespace {

constexpr double kSlipSpeedFloor = 0.1;  // m/s: below it the slip ratio is taken relative to this

b2Vec2 toBox2d(const geometry::Point& point)
{
  return b2Vec2(static_cast<float>(point.x()), static_cast<float>(point.y()));
}

geometry::Vector fromBox2d(const b2Vec2& vector)
{
  return geometry::Vector(vector.x, vector.y);
}

double moveToward(double current, double target, double max_change)
{
  return current + std::clamp(target - current, -max_change, max_change);
}

/// Mean distance of the polygon's area from its origin: the lever arm of ground friction torque for a
/// uniform pressure distribution (sampled on a grid; exact enough for a friction limit).
double meanRadius(const geometry::Polygon& outline)
{
  if (outline.empty()) {
    return 0.0;
  }
  geometry::Point low = outline.front();
  geometry::Point high = outline.front();
  for (const auto& point : outline) {
    low = low.cwiseMin(point);
    high = high.cwiseMax(point);
  }
  constexpr int kSamples = 24;
  const auto pieces = convexPieces(outline, 3);
  double sum = 0.0;
  int inside = 0;
  for (int row = 0; row < kSamples; ++row) {
    for (int column = 0; column < kSamples; ++column) {
      const geometry::Point sample(low.x() + (column + 0.5) * (high.x() - low.x()) / kSamples,
                                   low.y() + (row + 0.5) * (high.y() - low.y()) / kSamples);
      const bool in_piece = std::any_of(pieces.begin(), pieces.end(), [&](const geometry::Polygon& piece) {
        return geometry::cross(piece[0], piece[1], sample) >= 0.0 &&
               geometry::cross(piece[1], piece[2], sample) >= 0.0 &&
               geometry::cross(piece[2], piece[0], sample) >= 0.0;
      });
      if (in_piece) {
        sum += sample.norm();
        ++inside;
      }
    }
  }
  return inside > 0 ? sum / inside : 0.0;
}

/// Sums the normal impulses on the bumper fixture, projected on the vehicle's forward axis.
class BumperContactListener : public b2ContactListener {
 public:
  void setBumper(const b2Fixture* bumper) { bumper_ = bumper; }
  void resetImpulse() { impulse_ = 0.0; }
  double impulse() const { return impulse_; }

  void PostSolve(b2Contact* contact, const b2ContactImpulse* impulse) override
  {
    const bool bumper_is_a = contact->GetFixtureA() == bumper_;
    if (!bumper_is_a && contact->GetFixtureB() != bumper_) {
      return;
    }
    b2WorldManifold manifold;
    contact->GetWorldManifold(&manifold);
    const b2Vec2 forward = bumper_->GetBody()->GetWorldVector(b2Vec2(1.0f, 0.0f));
    const double alignment = std::abs(b2Dot(manifold.normal, forward));
    for (int32 point = 0; point < impulse->count; ++point) {
      impulse_ += impulse->normalImpulses[point] * alignment;
    }
  }

 private:
  const b2Fixture* bumper_ = nullptr;
  double impulse_ = 0.0;
};

}  // namespace

struct PhysicsWorld::Implementation {
  PhysicsSettings settings;
  common::VehicleSettings vehicle_settings;
  b2World world{b2Vec2(0.0f, 0.0f)};
  BumperContactListener listener;
  b2Body* ground = nullptr;
  b2Body* vehicle = nullptr;
  std::vector<std::pair<std::int64_t, b2Body*>> objects;
  double time_seconds = 0.0;
  double command_linear = 0.0;
  double command_angular = 0.0;
  double reference_linear = 0.0;
  double reference_angular = 0.0;
  double bumper_force = 0.0;

  void buildWalls(const World& source);
  void buildObjects(const World& source);
  void buildVehicle(const World& source);
  void applyWheelForces();
};

void PhysicsWorld::Implementation::buildWalls(const World& source)
{
  b2BodyDef definition;
  definition.type = b2_staticBody;
  ground = world.CreateBody(&definition);
  // Walls are two-sided edges on the static ground body: any polygon (concave, thin) works as is.
  for (const auto& obstacle : source.obstacles) {
    const auto& outline = obstacle.outline;
    for (std::size_t index = 0; index < outline.size(); ++index) {
      const auto& start = outline[index];
      const auto& end = outline[(index + 1) % outline.size()];
      if ((end - start).squaredNorm() < 1e-8) {
        continue;
      }
      b2EdgeShape edge;
      edge.SetTwoSided(toBox2d(start), toBox2d(end));
      b2FixtureDef fixture;
      fixture.shape = &edge;
      fixture.friction = static_cast<float>(settings.surface_friction);
      ground->CreateFixture(&fixture);
    }
  }
}

void PhysicsWorld::Implementation::buildObjects(const World& source)
{
  for (const auto& object : source.objects) {
    // Box2D welds vertices closer than 2.5 mm and replaces a degenerate polygon by a 2 m box, so
    // slivers (under 1 cm^2 or with an edge under 5 mm) are left out.
    std::vector<geometry::Polygon> pieces;
    for (auto& piece : convexPieces(object.outline, b2_maxPolygonVertices, 1e-4)) {
      bool short_edge = false;
      for (std::size_t index = 0; index < piece.size(); ++index) {
        short_edge = short_edge || (piece[(index + 1) % piece.size()] - piece[index]).norm() < 0.005;
      }
      if (!short_edge) {
        pieces.push_back(std::move(piece));
      }
    }
    double total_area = 0.0;
    for (const auto& piece : pieces) {
      total_area += signedPolygonArea(piece);
    }
    if (pieces.empty() || total_area <= 0.0 || object.mass_kg <= 0.0) {
      throw std::invalid_argument("object '" + object.name + "' (id " + std::to_string(object.id) +
                                  "): needs a polygon with area and a positive mass");
    }
    b2BodyDef definition;
    definition.type = b2_dynamicBody;
    definition.position = b2Vec2(static_cast<float>(object.pose.x), static_cast<float>(object.pose.y));
    definition.angle = static_cast<float>(object.pose.heading);
    b2Body* body = world.CreateBody(&definition);
    const double density = object.mass_kg / total_area;
    for (const auto& piece : pieces) {
      std::vector<b2Vec2> vertices;
      vertices.reserve(piece.size());
      for (const auto& point : piece) {
        vertices.push_back(toBox2d(point));
      }
      b2PolygonShape shape;
      shape.Set(vertices.data(), static_cast<int32>(vertices.size()));
      b2FixtureDef fixture;
      fixture.shape = &shape;
      fixture.density = static_cast<float>(density);
      fixture.friction = static_cast<float>(settings.surface_friction);
      body->CreateFixture(&fixture);
    }
    // Ground friction as a friction joint to the static ground: it cancels motion up to mu m g (and the
    // matching torque), so a box stops as soon as nothing pushes it.
    const double friction_force = object.ground_friction * object.mass_kg * settings.gravity;
    b2FrictionJointDef joint;
    joint.Initialize(ground, body, body->GetWorldCenter());
    joint.maxForce = static_cast<float>(friction_force);
    joint.maxTorque = static_cast<float>(friction_force * meanRadius(object.outline));
    world.CreateJoint(&joint);
    objects.emplace_back(object.id, body);
  }
}

void PhysicsWorld::Implementation::buildVehicle(const World& source)
{
  b2BodyDef definition;
  definition.type = b2_dynamicBody;
  definition.position = b2Vec2(static_cast<float>(source.start.x), static_cast<float>(source.start.y));
  definition.angle = static_cast<float>(source.start.heading);
  definition.allowSleep = false;
  vehicle = world.CreateBody(&definition);
  const double half_length = 0.5 * vehicle_settings.length_m;
  const double half_width = 0.5 * vehicle_settings.width_m;
  const double bumper_depth = std::min(settings.bumper_depth_m, half_length);
  // Box2D mixes friction as sqrt(a b); choose the bumper's so bumper-object contacts get bumper_friction.
  const double bumper_fixture_friction =
      vehicle_settings.bumper_friction * vehicle_settings.bumper_friction / settings.surface_friction;

  b2PolygonShape chassis;
  chassis.SetAsBox(static_cast<float>(half_length - 0.5 * bumper_depth), static_cast<float>(half_width),
                   b2Vec2(static_cast<float>(-0.5 * bumper_depth), 0.0f), 0.0f);
  b2FixtureDef chassis_fixture;
  chassis_fixture.shape = &chassis;
  chassis_fixture.density = 1.0f;
  chassis_fixture.friction = static_cast<float>(settings.surface_friction);
  vehicle->CreateFixture(&chassis_fixture);

  b2PolygonShape bumper;
  const double bumper_half_width = 0.5 * std::min(vehicle_settings.bumper_width_m, vehicle_settings.width_m);
  bumper.SetAsBox(static_cast<float>(0.5 * bumper_depth), static_cast<float>(bumper_half_width),
                  b2Vec2(static_cast<float>(half_length - 0.5 * bumper_depth), 0.0f), 0.0f);
  b2FixtureDef bumper_fixture;
  bumper_fixture.shape = &bumper;
  bumper_fixture.density = 0.0f;
  bumper_fixture.friction = static_cast<float>(bumper_fixture_friction);
  listener.setBumper(vehicle->CreateFixture(&bumper_fixture));

  // Exact mass and inertia from vehicle.yaml, centred on the axle.
  b2MassData mass;
  mass.mass = static_cast<float>(vehicle_settings.mass_kg);
  mass.center = b2Vec2(0.0f, 0.0f);
  mass.I = static_cast<float>(vehicle_settings.mass_kg *
                              (vehicle_settings.length_m * vehicle_settings.length_m +
                               vehicle_settings.width_m * vehicle_settings.width_m) /
                              12.0);
  vehicle->SetMassData(&mass);
}

void PhysicsWorld::Implementation::applyWheelForces()
{
  const double step = settings.step_seconds;
  reference_linear =
      moveToward(reference_linear, command_linear, vehicle_settings.max_linear_acceleration * step);
  reference_angular =
      moveToward(reference_angular, command_angular, vehicle_settings.max_angular_acceleration * step);
  const double half_track = 0.5 * vehicle_settings.wheel_track_m;
  const common::RimSpeeds targets =
      common::rimSpeeds(reference_linear, reference_angular, vehicle_settings.wheel_track_m);
  const double wheel_targets[2] = {targets.left, targets.right};
  const double wheel_offsets[2] = {half_track, -half_track};  // left wheel at +y in the body frame
  const double normal_load = 0.5 * vehicle_settings.mass_kg * settings.gravity;
  const double traction_limit = vehicle_settings.traction_coefficient * normal_load;
  const double response = settings.wheel_response * 0.5 * vehicle_settings.mass_kg / step;
  const b2Vec2 forward = vehicle->GetWorldVector(b2Vec2(1.0f, 0.0f));
  const b2Vec2 left = vehicle->GetWorldVector(b2Vec2(0.0f, 1.0f));
  for (int wheel = 0; wheel < 2; ++wheel) {
    const b2Vec2 contact = vehicle->GetWorldPoint(b2Vec2(0.0f, static_cast<float>(wheel_offsets[wheel])));
    const b2Vec2 velocity = vehicle->GetLinearVelocityFromWorldPoint(contact);
    const double longitudinal_slip = wheel_targets[wheel] - b2Dot(velocity, forward);
    const double lateral_slip = -b2Dot(velocity, left);
    double longitudinal_force = response * longitudinal_slip;
    double lateral_force = response * lateral_slip;
    if (settings.slip_ratio_scale > 0.0) {
      // The tyre transmits force only by slipping: the slip ratio (relative to the faster of wheel and
      // ground, with a floor so that creeping does not divide by nothing) sets what it can carry.
      const double reference =
          std::max({std::abs(wheel_targets[wheel]), std::abs(static_cast<double>(b2Dot(velocity, forward))),
                    kSlipSpeedFloor});
      const double ratio = std::abs(longitudinal_slip) / reference;
      const double tyre = traction_limit * (1.0 - std::exp(-ratio / settings.slip_ratio_scale));
      longitudinal_force = std::clamp(longitudinal_force, -tyre, tyre);
    }
    // Friction circle: the tyre's total ground force is capped by traction x normal load.
    const double magnitude = std::hypot(longitudinal_force, lateral_force);
    if (magnitude > traction_limit) {
      longitudinal_force *= traction_limit / magnitude;
      lateral_force *= traction_limit / magnitude;
    }
    const b2Vec2 force =
        static_cast<float>(longitudinal_force) * forward + static_cast<float>(lateral_force) * left;
    vehicle->ApplyForce(force, contact, true);
  }
}

PhysicsWorld::PhysicsWorld(const World& world, const common::VehicleSettings& vehicle,
                           const PhysicsSettings& settings)
    : implementation_(std::make_unique<Implementation>())
{
  if (!(settings.step_seconds > 0.0) || !(settings.surface_friction > 0.0)) {
    throw std::invalid_argument("physics settings: step_seconds and surface_friction must be positive");
  }
  implementation_->settings = settings;
  implementation_->vehicle_settings = vehicle;
  implementation_->world.SetContactListener(&implementation_->listener);
  implementation_->buildWalls(world);
  implementation_->buildObjects(world);
  implementation_->buildVehicle(world);
}

PhysicsWorld::~PhysicsWorld() = default;
PhysicsWorld::PhysicsWorld(PhysicsWorld&&) noexcept = default;
PhysicsWorld& PhysicsWorld::operator=(PhysicsWorld&&) noexcept = default;

void PhysicsWorld::setVelocityCommand(double linear, double angular)
{
  const auto& vehicle = implementation_->vehicle_settings;
  implementation_->command_linear =
      std::isfinite(linear) ? std::clamp(linear, -vehicle.max_linear_velocity, vehicle.max_linear_velocity)
                            : 0.0;
  implementation_->command_angular =
      std::isfinite(angular)
          ? std::clamp(angular, -vehicle.max_angular_velocity, vehicle.max_angular_velocity)
          : 0.0;
}

void PhysicsWorld::setWheelSpeedCommand(const WheelSpeeds& wheels)
{
  const common::BodyVelocity body =
      common::bodyVelocity(wheels.left, wheels.right, 1.0, implementation_->vehicle_settings.wheel_track_m);
  setVelocityCommand(body.linear, body.angular);
}

void PhysicsWorld::step()
{
  auto& state = *implementation_;
  state.applyWheelForces();
  state.listener.resetImpulse();
  state.world.Step(static_cast<float>(state.settings.step_seconds), state.settings.velocity_iterations,
                   state.settings.position_iterations);
  state.bumper_force = state.listener.impulse() / state.settings.step_seconds;
  state.time_seconds += state.settings.step_seconds;
}

double PhysicsWorld::timeSeconds() const
{
  return implementation_->time_seconds;
}
const PhysicsSettings& PhysicsWorld::settings() const
{
  return implementation_->settings;
}
const common::VehicleSettings& PhysicsWorld::vehicleSettings() const
{
  return implementation_->vehicle_settings;
}

namespace {
BodyState stateOf(std::int64_t id, const b2Body& body)
{
  BodyState state;
  state.id = id;
  state.pose.x = body.GetPosition().x;
  state.pose.y = body.GetPosition().y;
  state.pose.heading = std::remainder(static_cast<double>(body.GetAngle()), 2.0 * geometry::kPi);
  state.linear_velocity = fromBox2d(body.GetLinearVelocity());
  state.angular_velocity = body.GetAngularVelocity();
  return state;
}
}  // namespace

BodyState PhysicsWorld::vehicleState() const
{
  return stateOf(0, *implementation_->vehicle);
}

std::vector<BodyState> PhysicsWorld::objectStates() const
{
  std::vector<BodyState> states;
  states.reserve(implementation_->objects.size());
  for (const auto& [id, body] : implementation_->objects) {
    states.push_back(stateOf(id, *body));
  }
  return states;
}

double PhysicsWorld::bumperForce() const
{
  return implementation_->bumper_force;
}

WheelSpeeds PhysicsWorld::wheelSpeeds() const
{
  const common::RimSpeeds rims =
      common::rimSpeeds(implementation_->reference_linear, implementation_->reference_angular,
                        implementation_->vehicle_settings.wheel_track_m);
  return {rims.left, rims.right};
}

}  // namespace ifar::sim::physics
