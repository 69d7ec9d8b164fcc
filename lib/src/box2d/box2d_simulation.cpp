// Scene -> b2World, and Box2D's bodies and contacts back into our types after each step.
#include "impulse2d/box2d/box2d_simulation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <box2d/box2d.h>

namespace impulse2d {
namespace {

/// Box2D clamps each friction impulse against the normal impulse of the iteration before the
/// last normal update, so a sliding point's stored pair misses the friction cone's edge by that
/// update: within this fraction of μ·normalImpulse the point counts as sliding.
constexpr double kSlidingTolerance = 1e-2;

// The one conversion point between our double vectors and Box2D's float ones.
b2Vec2 toBox2d(const Vec2& v) {
  return b2Vec2(float(v.x()), float(v.y()));
}
Vec2 fromBox2d(const b2Vec2& v) {
  return Vec2(v.x, v.y);
}

/// Box2D 2.4.1's b2PolygonShape::Set asserts, aborting the program, where it cannot make a
/// polygon; each of these refuses such a polygon first, naming Box2D's limit. Set welds
/// vertices closer than half the linear slop, so fewer than three may remain.
void refuseWeldedVertices(const std::vector<b2Vec2>& points, const std::string& bodyName) {
  const float weld = 0.5f * b2_linearSlop;
  for (size_t i = 0; i < points.size(); ++i) {
    for (size_t j = i + 1; j < points.size(); ++j) {
      const float apart = b2Distance(points[i], points[j]);
      if (apart >= weld) continue;
      throw std::invalid_argument("body '" + bodyName +
                                  "': Box2D welds polygon vertices closer than half its linear " +
                                  "slop (b2_linearSlop / 2 = " + std::to_string(weld) +
                                  " m); vertices " + std::to_string(i) + " and " +
                                  std::to_string(j) + " are " + std::to_string(apart) + " m apart");
    }
  }
}

/// The area of the polygon as Box2D's ComputeCentroid sums it, in floats from the first vertex;
/// Set asserts that it exceeds b2_epsilon.
void refuseThinPolygon(const std::vector<b2Vec2>& points, const std::string& bodyName) {
  float area = 0.0f;
  for (size_t i = 1; i + 1 < points.size(); ++i) {
    area += 0.5f * b2Cross(points[i] - points[0], points[i + 1] - points[0]);
  }
  if (std::isfinite(area) && area > b2_epsilon) return;
  std::ostringstream message;
  message << "body '" << bodyName << "': Box2D needs a polygon's area, in single precision, "
          << "finite and above b2_epsilon (" << b2_epsilon << " m²); it is " << area << " m²";
  throw std::invalid_argument(message.str());
}

b2PolygonShape polygonFor(const Shape& shape, const std::string& bodyName) {
  const int count = int(shape.vertices.size());
  if (count > b2_maxPolygonVertices) {
    throw std::invalid_argument("body '" + bodyName + "': Box2D polygons hold at most " +
                                std::to_string(b2_maxPolygonVertices) +
                                " vertices (b2_maxPolygonVertices), not " + std::to_string(count));
  }
  std::vector<b2Vec2> points;
  for (const Vec2& vertex : shape.vertices) points.push_back(toBox2d(vertex));
  refuseWeldedVertices(points, bodyName);
  refuseThinPolygon(points, bodyName);
  b2PolygonShape polygon;
  polygon.Set(points.data(), count);  // recomputes the convex hull
  if (polygon.m_count != count) {
    throw std::invalid_argument("body '" + bodyName + "': Box2D's convex hull of it has " +
                                std::to_string(polygon.m_count) + " of the " +
                                std::to_string(count) +
                                " vertices (it drops a vertex in line with its neighbours)");
  }
  return polygon;
}

void addFixture(b2Body& body, const BodyDef& def, float restitutionThreshold) {
  b2FixtureDef fixture;
  fixture.density = float(def.density);
  fixture.friction = float(def.friction);
  fixture.restitution = float(def.restitution);
  fixture.restitutionThreshold = restitutionThreshold;
  if (def.shape.type == ShapeType::Circle) {
    b2CircleShape circle;
    circle.m_radius = float(def.shape.radius);
    fixture.shape = &circle;
    body.CreateFixture(&fixture);
    return;
  }
  const b2PolygonShape polygon = polygonFor(def.shape, def.name);
  fixture.shape = &polygon;
  body.CreateFixture(&fixture);
}

/// Our body index, kept in Box2D's user data.
int indexOf(b2Fixture& fixture) {
  return int(fixture.GetBody()->GetUserData().pointer);
}

FrictionState frictionState(double normalImpulse, double tangentImpulse, double friction) {
  if (normalImpulse <= 0.0) return FrictionState::None;
  const double limit = friction * normalImpulse;
  return std::abs(tangentImpulse) >= (1.0 - kSlidingTolerance) * limit ? FrictionState::Dynamic
                                                                       : FrictionState::Static;
}

/// kg, kg m². Box2D sums a body's mass and rotational inertia in floats and asserts the inertia
/// about the centre of mass is positive: one past a float's 3.4e38 becomes infinite, then not a
/// number, and the assertion aborts the program. This bound keeps a factor of three below it.
constexpr double kLargestBox2dMass = 1e38;

void refuseBeyondSinglePrecisionMass(const Body& body) {
  if (body.isStatic() || (body.mass < kLargestBox2dMass && body.inertia < kLargestBox2dMass)) {
    return;
  }
  std::ostringstream message;
  message << "body '" << body.name << "': Box2D holds mass and rotational inertia in single "
          << "precision, below " << kLargestBox2dMass << "; this body's are " << body.mass
          << " kg and " << body.inertia << " kg m²";
  throw std::invalid_argument(message.str());
}

/// Box2D holds a body's state in floats, and asserts that each is finite: a state beyond a
/// float's 3.4e38 (a speed of 1e100 m/s is a valid double) stops before step 1.
void stopUnlessSinglePrecision(const b2BodyDef& body, const std::string& name) {
  if (!body.position.IsValid() || !body.linearVelocity.IsValid() || !std::isfinite(body.angle) ||
      !std::isfinite(body.angularVelocity)) {
    throw NonFiniteState(name, 0, kBox2dName);
  }
}

}  // namespace

struct Box2dSimulation::Box2dWorld {
  explicit Box2dWorld(const Vec2& gravity) : world(toBox2d(gravity)) {}
  b2World world;
  std::vector<b2Body*> bodies;  ///< in scene order: bodies[i] is our body i
};

double box2dPolygonSkin() {
  return b2_polygonRadius;
}
double box2dLinearSlop() {
  return b2_linearSlop;
}

Box2dSimulation::Box2dSimulation(const Scene& scene, const Box2dOptions& options)
    : settings_(scene.world),
      iterations_(scene.solverSettings.box2d),
      world_(std::make_unique<Box2dWorld>(scene.world.gravity)),
      bodies_(buildBodies(scene)) {
  settings_.substeps = 1;  // Box2D takes one step per dt, whatever the scene asks of our world
  world_->world.SetAllowSleeping(options.allowSleeping);
  world_->world.SetContinuousPhysics(options.continuousPhysics);
  const float restitutionThreshold =
      float(scene.solverSettings.sequential.targets.restitutionThreshold);
  for (size_t i = 0; i < scene.bodies.size(); ++i) {
    const BodyDef& def = scene.bodies[i];
    b2BodyDef bodyDef;
    bodyDef.type = def.type == BodyType::Static ? b2_staticBody : b2_dynamicBody;
    bodyDef.position = toBox2d(def.position);  // the origin: our shapes are centred on it
    bodyDef.angle = float(def.angle);
    bodyDef.linearVelocity = toBox2d(bodies_[i].velocity);
    bodyDef.angularVelocity = float(bodies_[i].angularVelocity);
    bodyDef.userData.pointer = i;
    stopUnlessSinglePrecision(bodyDef, bodies_[i].name);
    refuseBeyondSinglePrecisionMass(bodies_[i]);
    b2Body* body = world_->world.CreateBody(&bodyDef);
    addFixture(*body, def, restitutionThreshold);
    world_->bodies.push_back(body);
  }
}

Box2dSimulation::~Box2dSimulation() = default;

// The same loads World applies (body.h), at the step's start time; Box2D clears them after Step.
void Box2dSimulation::applyLoads() {
  const double time = double(stepCount_) * settings_.dt;
  for (size_t i = 0; i < bodies_.size(); ++i) {
    const AppliedLoad& load = bodies_[i].load;
    if (bodies_[i].isStatic() || load.isZero()) continue;
    b2Body& body = *world_->bodies[i];
    body.ApplyForce(toBox2d(load.forceAt(time)), body.GetWorldPoint(toBox2d(load.point)), true);
    body.ApplyTorque(float(load.torque), true);
  }
}

void Box2dSimulation::step() {
  applyLoads();
  const auto start = std::chrono::steady_clock::now();
  world_->world.Step(float(settings_.dt), iterations_.velocityIterations,
                     iterations_.positionIterations);
  engineStepMicroseconds_ =
      std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
  readBodies();
  stopAtNonFiniteBody(bodies_, settings_.gravity, stepCount_ + 1, kBox2dName);
  readContacts();
  ++stepCount_;
}

MassProperties Box2dSimulation::box2dMass(int body) const {
  const b2Body& b = *world_->bodies.at(body);
  // GetInertia is about the body origin; take the centre of mass's offset out again.
  const double offset = b.GetLocalCenter().LengthSquared();
  return {b.GetMass(), b.GetInertia() - b.GetMass() * offset};
}

void Box2dSimulation::readBodies() {
  for (size_t i = 0; i < bodies_.size(); ++i) {
    const b2Body& source = *world_->bodies[i];
    Body& body = bodies_[i];
    body.position = fromBox2d(source.GetWorldCenter());
    body.angle = source.GetAngle();
    body.velocity = fromBox2d(source.GetLinearVelocity());
    body.angularVelocity = source.GetAngularVelocity();
    body.updateCache();
  }
}

namespace {

/// One Box2D contact point in our terms. Box2D's tangent is the normal turned −90°, ours +90°
/// (contact.h), so the friction impulse changes sign.
ContactPoint contactPoint(const b2ManifoldPoint& source, const Vec2& point, double separation) {
  ContactPoint contact;
  contact.point = point;
  contact.penetration = -separation;
  contact.id = source.id.key;
  contact.normalImpulse = source.normalImpulse;
  contact.tangentImpulse = -source.tangentImpulse;
  return contact;
}

/// Box2D's normal points from fixture A to fixture B; ours from the lower body index to the
/// higher, as our world pairs them. Swapping A and B turns the normal and the tangent round, so
/// the impulses along them keep their signs.
Manifold manifoldOf(b2Contact& contact, const std::vector<Body>& bodies) {
  b2WorldManifold world;
  contact.GetWorldManifold(&world);
  Manifold manifold;
  manifold.bodyA = indexOf(*contact.GetFixtureA());
  manifold.bodyB = indexOf(*contact.GetFixtureB());
  manifold.normal = fromBox2d(world.normal).normalized();
  if (manifold.bodyA > manifold.bodyB) {
    std::swap(manifold.bodyA, manifold.bodyB);
    manifold.normal = -manifold.normal;
  }
  manifold.friction = contact.GetFriction();
  manifold.restitution = contact.GetRestitution();
  manifold.pointCount = contact.GetManifold()->pointCount;
  const Body& a = bodies[manifold.bodyA];
  const Body& b = bodies[manifold.bodyB];
  for (int i = 0; i < manifold.pointCount; ++i) {
    ContactPoint& point = manifold.points[i];
    point = contactPoint(contact.GetManifold()->points[i], fromBox2d(world.points[i]),
                         world.separations[i]);
    const Vec2 halfOverlap = 0.5 * point.penetration * manifold.normal;
    point.anchorA = a.toLocal(point.point + halfOverlap);
    point.anchorB = b.toLocal(point.point - halfOverlap);
    point.friction = frictionState(point.normalImpulse, point.tangentImpulse, manifold.friction);
  }
  return manifold;
}

}  // namespace

void Box2dSimulation::readContacts() {
  manifolds_.clear();
  for (b2Contact* contact = world_->world.GetContactList(); contact; contact = contact->GetNext()) {
    if (!contact->IsTouching() || !contact->IsEnabled()) continue;
    manifolds_.push_back(manifoldOf(*contact, bodies_));
  }
  std::sort(manifolds_.begin(), manifolds_.end(), [](const Manifold& x, const Manifold& y) {
    return std::make_pair(x.bodyA, x.bodyB) < std::make_pair(y.bodyA, y.bodyB);
  });
}

std::vector<std::string> simulationNames() {
  std::vector<std::string> names = solverNames();
  names.push_back(kBox2dName);
  return names;
}

std::unique_ptr<Simulation> makeSimulation(const Scene& scene) {
  if (scene.solver == kBox2dName) return std::make_unique<Box2dSimulation>(scene);
  const std::vector<std::string> names = simulationNames();
  if (std::find(names.begin(), names.end(), scene.solver) != names.end()) return buildWorld(scene);
  std::string known;
  for (const std::string& name : names) known += (known.empty() ? "" : ", ") + name;
  throw std::invalid_argument("unknown solver '" + scene.solver + "' (known: " + known + ")");
}

}  // namespace impulse2d
