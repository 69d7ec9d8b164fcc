// One frame of a simulation: bodies by state, contact overlays, the heads-up line.
#include "impulse2d/render/frame.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "impulse2d/render/legend.h"

namespace impulse2d::render {

namespace {

bool validManifold(const Manifold& manifold, std::size_t bodyCount) {
  return manifold.bodyA >= 0 && manifold.bodyB >= 0 && std::size_t(manifold.bodyA) < bodyCount &&
         std::size_t(manifold.bodyB) < bodyCount;
}

/// Every point of the contact in dynamic friction (the whole face slips, not one point of a pair
/// sharing the load unevenly), or the surfaces slipping past each other faster than slidingSpeed.
bool slides(const Manifold& manifold, const std::vector<Body>& bodies,
            const RenderSettings& settings) {
  bool allDynamic = manifold.pointCount > 0;
  for (int i = 0; i < manifold.pointCount; ++i) {
    const ContactPoint& point = manifold.points[i];
    allDynamic = allDynamic && point.friction == FrictionState::Dynamic;
    const Vec2 relative = bodies[manifold.bodyB].velocityAt(point.point) -
                          bodies[manifold.bodyA].velocityAt(point.point);
    if (std::abs(relative.dot(manifold.tangent())) > settings.slidingSpeed) return true;
  }
  return allDynamic;
}

bool slow(const Body& body, const RenderSettings& settings) {
  return body.velocity.norm() < settings.restingSpeed &&
         std::abs(body.angularVelocity) < settings.restingAngularSpeed;
}

/// How far the body's local x axis reaches from the centre of mass to the body's edge.
double rotationMarkReach(const Shape& shape) {
  if (shape.type == ShapeType::Circle) return shape.radius;
  double reach = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < shape.normals.size(); ++i) {
    const Vec2& normal = shape.normals[i];
    if (normal.x() > 1e-9) reach = std::min(reach, normal.dot(shape.vertices[i]) / normal.x());
  }
  return std::isfinite(reach) ? reach : 0.0;
}

void drawBody(Canvas& canvas, const Camera& camera, const Body& body, Color fill,
              const RenderSettings& settings) {
  const Color outline = settings.colours.outline;
  const Vec2 centre = camera.toPixels(body.position);
  if (body.shape.type == ShapeType::Circle) {
    fillCircle(canvas, centre, camera.scale * body.shape.radius, fill, outline,
               settings.outlineWidth);
  } else {
    std::vector<Vec2> corners;
    corners.reserve(body.shape.vertices.size());
    for (const Vec2& vertex : body.shape.vertices) {
      corners.push_back(camera.toPixels(body.toWorld(vertex)));
    }
    fillConvexPolygon(canvas, corners, fill, outline, settings.outlineWidth);
  }
  if (settings.overlays.rotationMarks && !body.isStatic()) {
    const Vec2 edge = camera.toPixels(body.toWorld(Vec2(rotationMarkReach(body.shape), 0.0)));
    drawLine(canvas, centre, edge, settings.rotationMarkWidth, settings.colours.rotationMark);
  }
}

/// The gauge under a contact point: a bar filled to |λt| / (μ λn), in the static-friction
/// colour below the limit and the dynamic one on it.
void drawFrictionGauge(Canvas& canvas, const Vec2& at, double use, double textScale,
                       const RenderSettings& settings) {
  const Palette& colours = settings.colours;
  const Vec2 size(settings.gaugeLength * textScale, settings.gaugeThickness * textScale);
  const Vec2 corner = at + Vec2(-0.5 * size.x(), settings.contactPointRadius + 2.0);
  const bool onLimit = use >= 1.0 - settings.gaugeLimitTolerance;
  const std::vector<Vec2> box{corner, corner + Vec2(size.x(), 0.0), corner + size,
                              corner + Vec2(0.0, size.y())};
  fillConvexPolygon(canvas, box, colours.gaugeBackground, colours.outline, settings.outlineWidth);
  const double filled = std::min(use, 1.0) * size.x();
  if (filled > 0.0) {
    fillRectangle(canvas, corner, Vec2(filled, size.y()),
                  onLimit ? colours.dynamicFriction : colours.staticFriction);
  }
}

void drawContactPoint(Canvas& canvas, const Camera& camera, const Manifold& manifold,
                      const ContactPoint& point, const ForceScale& forces,
                      const RenderSettings& settings, DrawnKinds& drawn) {
  const Overlays& show = settings.overlays;
  const Palette& colours = settings.colours;
  const Vec2 at = camera.toPixels(point.point);
  const double perImpulse = forces.metresPerNewton / forces.dt;  // m per N s
  if (show.contactNormals) {
    const Vec2 direction(manifold.normal.x(), -manifold.normal.y());
    drawLine(canvas, at, at + settings.contactNormalLength * direction, settings.contactNormalWidth,
             colours.contactNormal);
  }
  if (show.normalImpulses) {
    drawn.normalForces |= drawWorldArrow(canvas, camera, point.point,
                                         perImpulse * point.normalImpulse * manifold.normal,
                                         colours.normalImpulse, settings);
  }
  if (show.frictionImpulses) {
    const bool dynamic = point.friction == FrictionState::Dynamic;
    const bool shown = drawWorldArrow(
        canvas, camera, point.point, perImpulse * point.tangentImpulse * manifold.tangent(),
        dynamic ? colours.dynamicFriction : colours.staticFriction, settings);
    (dynamic ? drawn.dynamicFriction : drawn.staticFriction) |= shown;
  }
  if (show.contactPoints) {
    fillCircle(canvas, at, settings.contactPointRadius, colours.contactPoint, colours.outline,
               settings.outlineWidth);
  }
}

/// One gauge per contact, under the middle of its points.
void drawContactGauge(Canvas& canvas, const Camera& camera, const Manifold& manifold,
                      const ForceScale& forces, const RenderSettings& settings, DrawnKinds& drawn) {
  double normal = 0.0;
  Vec2 middle = Vec2::Zero();
  for (int i = 0; i < manifold.pointCount; ++i) {
    normal += manifold.points[i].normalImpulse;
    middle += manifold.points[i].point / manifold.pointCount;
  }
  if (manifold.friction <= 0.0 || normal / forces.dt <= settings.gaugeMinimumNormalForce) return;
  drawFrictionGauge(canvas, camera.toPixels(middle), frictionUse(manifold),
                    frameTextScale(settings, canvas.width()), settings);
  drawn.gauges = true;
}

/// The weight (N) of the dynamic bodies standing on `base`: those whose centre is above its
/// bottom and within its width, itself included.
double columnWeight(const std::vector<Body>& bodies, const Body& base, double gravity) {
  double weight = 0.0;
  for (const Body& body : bodies) {
    if (body.isStatic() || body.position.y() < base.bounds.lower.y()) continue;
    if (body.position.x() < base.bounds.lower.x() || body.position.x() > base.bounds.upper.x()) {
      continue;
    }
    weight += body.mass * gravity;
  }
  return weight;
}

}  // namespace

std::vector<BodyState> classifyBodies(const std::vector<Body>& bodies,
                                      const std::vector<Manifold>& manifolds,
                                      const RenderSettings& settings) {
  std::vector<int> contacts(bodies.size(), 0);
  std::vector<bool> sliding(bodies.size(), false);
  for (const Manifold& manifold : manifolds) {
    if (!validManifold(manifold, bodies.size()) || manifold.pointCount == 0) continue;
    contacts[manifold.bodyA] += manifold.pointCount;
    contacts[manifold.bodyB] += manifold.pointCount;
    if (slides(manifold, bodies, settings))
      sliding[manifold.bodyA] = sliding[manifold.bodyB] = true;
  }
  std::vector<BodyState> states(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (bodies[i].isStatic()) {
      states[i] = BodyState::Static;
    } else if (bodies[i].asleep) {
      states[i] = BodyState::Sleeping;
    } else if (contacts[i] == 0) {
      states[i] = BodyState::Flying;
    } else if (sliding[i]) {
      states[i] = BodyState::Sliding;
    } else {
      states[i] = slow(bodies[i], settings) ? BodyState::Resting : BodyState::Touching;
    }
  }
  return states;
}

const char* nameOf(BodyState state) {
  switch (state) {
    case BodyState::Static:
      return "static";
    case BodyState::Flying:
      return "flying";
    case BodyState::Resting:
      return "resting";
    case BodyState::Touching:
      return "touching";
    case BodyState::Sliding:
      return "sliding";
    case BodyState::Sleeping:
      return "asleep";
  }
  return "static";
}

double restingForceEstimate(const std::vector<Body>& bodies, const Vec2& gravity) {
  double heaviest = 0.0;
  for (const Body& body : bodies) {
    if (!body.isStatic()) heaviest = std::max(heaviest, columnWeight(bodies, body, gravity.norm()));
  }
  return 0.5 * heaviest;
}

ForceScale fitForceScale(const std::vector<Body>& bodies, const Vec2& gravity, double dt,
                         const Camera& camera, const RenderSettings& settings) {
  ForceScale forces;
  forces.dt = dt;
  forces.metresPerNewton = settings.forceScale;
  if (forces.metresPerNewton > 0.0) return forces;
  const double force = restingForceEstimate(bodies, gravity);
  const double length = settings.restingForceLength * camera.height / camera.scale;  // m
  forces.metresPerNewton = force > 0.0 ? length / force : length;  // weightless: 1 N is `length`
  return forces;
}

double frictionUse(const Manifold& manifold) {
  double normal = 0.0;
  double tangent = 0.0;
  for (int i = 0; i < manifold.pointCount; ++i) {
    normal += manifold.points[i].normalImpulse;
    tangent += manifold.points[i].tangentImpulse;
  }
  const double limit = manifold.friction * normal;
  return limit > 0.0 ? std::abs(tangent) / limit : 0.0;
}

Color colourOf(BodyState state, const Palette& palette) {
  switch (state) {
    case BodyState::Static:
      return palette.staticBody;
    case BodyState::Flying:
      return palette.flyingBody;
    case BodyState::Resting:
      return palette.restingBody;
    case BodyState::Touching:
      return palette.touchingBody;
    case BodyState::Sliding:
      return palette.slidingBody;
    case BodyState::Sleeping:
      return palette.sleepingBody;
  }
  return palette.staticBody;
}

double totalEnergy(const std::vector<Body>& bodies, const Vec2& gravity) {
  double energy = 0.0;
  for (const Body& body : bodies) {
    if (!body.isStatic()) energy += body.kineticEnergy() + body.potentialEnergy(gravity);
  }
  return energy;
}

FrameInfo describe(const Simulation& simulation, const std::string& scene) {
  FrameInfo info;
  info.scene = scene;
  info.solver = simulation.solverName();
  info.step = simulation.stepCount();
  info.time = double(simulation.stepCount()) * simulation.settings().dt;
  info.energy = totalEnergy(simulation.bodies(), simulation.settings().gravity);
  return info;
}

std::vector<std::string> headsUpLines(const FrameInfo& info) {
  char numbers[128];
  std::snprintf(numbers, sizeof numbers, "step %ld  t = %.3f s  E = %.2f J", info.step, info.time,
                info.energy);
  return {info.scene + "  " + info.solver, numbers};
}

double frameTextScale(const RenderSettings& settings, int frameWidth) {
  return std::max(settings.textScale, settings.frameTextPerPixel * frameWidth);
}

double headsUpHeight(const RenderSettings& settings, int frameWidth) {
  return textHeight(frameTextScale(settings, frameWidth)) + 2.0 * settings.textMargin;
}

bool drawWorldArrow(Canvas& canvas, const Camera& camera, const Vec2& at, const Vec2& vector,
                    Color color, const RenderSettings& settings) {
  Vec2 pixels = camera.toPixelVector(vector);
  const double length = pixels.norm();
  if (!(length >= settings.minArrowLength)) return false;
  if (length > settings.maxArrowLength) pixels *= settings.maxArrowLength / length;
  // Arrows thicken with the frame's text, so they stay visible on a thumbnail.
  const double thickness = frameTextScale(settings, canvas.width()) / settings.textScale;
  const Vec2 from = camera.toPixels(at);
  drawArrow(canvas, from, from + pixels, thickness * settings.arrowWidth,
            thickness * settings.arrowHeadLength, thickness * settings.arrowHeadWidth, color);
  return true;
}

DrawnKinds drawScene(Canvas& canvas, const Camera& camera, const std::vector<Body>& bodies,
                     const std::vector<Manifold>& manifolds, const ForceScale& forces,
                     const RenderSettings& settings) {
  DrawnKinds drawn;
  const std::vector<BodyState> states = classifyBodies(bodies, manifolds, settings);
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    drawBody(canvas, camera, bodies[i], colourOf(states[i], settings.colours), settings);
    drawn.states[std::size_t(states[i])] = true;
  }
  for (const Manifold& manifold : manifolds) {
    for (int i = 0; i < manifold.pointCount; ++i) {
      drawContactPoint(canvas, camera, manifold, manifold.points[i], forces, settings, drawn);
    }
    if (settings.overlays.frictionGauges) {
      drawContactGauge(canvas, camera, manifold, forces, settings, drawn);
    }
  }
  if (!settings.overlays.velocities) return drawn;
  for (const Body& body : bodies) {
    if (body.isStatic()) continue;
    drawn.velocities |=
        drawWorldArrow(canvas, camera, body.position, settings.velocityScale * body.velocity,
                       settings.colours.velocity, settings);
  }
  return drawn;
}

void drawHeadsUp(Canvas& canvas, const std::vector<std::string>& lines,
                 const RenderSettings& settings) {
  const double lineHeight = headsUpHeight(settings, canvas.width());
  const double textScale = frameTextScale(settings, canvas.width());
  const double room = canvas.width() - 2.0 * settings.textMargin;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const double top = double(i) * lineHeight;
    fillRectangle(canvas, Vec2(0.0, top), Vec2(canvas.width(), lineHeight),
                  settings.colours.labelBackground);
    // A line too long for the image is drawn smaller rather than cut off.
    const double width = textWidth(lines[i], textScale);
    const double scale = width > room ? textScale * room / width : textScale;
    drawText(canvas, lines[i], Vec2(settings.textMargin, top + settings.textMargin), scale,
             settings.colours.text);
  }
}

FrameRenderer::FrameRenderer(const Camera& camera, std::string scene,
                             const RenderSettings& settings)
    : camera_(camera), scene_(std::move(scene)), settings_(settings) {}

// A world with substeps reports the last substep's impulses, taken over dt / substeps.
void FrameRenderer::fitForces(const Simulation& simulation) {
  const WorldSettings& world = simulation.settings();
  forces_ = fitForceScale(simulation.bodies(), world.gravity,
                          world.dt / std::max(1, world.substeps), camera_, settings_);
}

const Canvas& FrameRenderer::draw(const Simulation& simulation) {
  if (forces_.metresPerNewton <= 0.0) fitForces(simulation);
  return draw(simulation.bodies(), simulation.manifolds(),
              headsUpLines(describe(simulation, scene_)));
}

const Canvas& FrameRenderer::draw(const std::vector<Body>& bodies,
                                  const std::vector<Manifold>& manifolds,
                                  const std::vector<std::string>& headsUp) {
  if (forces_.metresPerNewton <= 0.0)
    forces_ = fitForceScale(bodies, Vec2::Zero(), forces_.dt, camera_, settings_);
  const int legend = settings_.overlays.legend ? legendHeight(settings_, camera_.width) : 0;
  canvas_.reset(camera_.width, camera_.height + legend, settings_.colours.background);
  const DrawnKinds drawn = drawScene(canvas_, camera_, bodies, manifolds, forces_, settings_);
  if (settings_.overlays.headsUp) drawHeadsUp(canvas_, headsUp, settings_);
  if (legend > 0) drawLegend(canvas_, camera_.height, drawn, forces_, camera_, settings_);
  return canvas_;
}

}  // namespace impulse2d::render
