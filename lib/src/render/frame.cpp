// One frame of a simulation: bodies by state, contact overlays, the heads-up line.
#include "impulse2d/render/frame.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace impulse2d::render {

namespace {

bool validManifold(const Manifold& manifold, std::size_t bodyCount) {
  return manifold.bodyA >= 0 && manifold.bodyB >= 0 && std::size_t(manifold.bodyA) < bodyCount &&
         std::size_t(manifold.bodyB) < bodyCount;
}

/// Dynamic friction, or the surfaces slipping past each other faster than slidingSpeed.
bool slides(const Manifold& manifold, const ContactPoint& point, const std::vector<Body>& bodies,
            const RenderSettings& settings) {
  if (point.friction == FrictionState::Dynamic) return true;
  const Vec2 relative = bodies[manifold.bodyB].velocityAt(point.point) -
                        bodies[manifold.bodyA].velocityAt(point.point);
  return std::abs(relative.dot(manifold.tangent())) > settings.slidingSpeed;
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

void drawContactPoint(Canvas& canvas, const Camera& camera, const Manifold& manifold,
                      const ContactPoint& point, const RenderSettings& settings) {
  const Overlays& show = settings.overlays;
  const Palette& colours = settings.colours;
  const Vec2 at = camera.toPixels(point.point);
  if (show.contactNormals) {
    const Vec2 direction(manifold.normal.x(), -manifold.normal.y());
    drawLine(canvas, at, at + settings.contactNormalLength * direction, settings.contactNormalWidth,
             colours.contactNormal);
  }
  if (show.normalImpulses) {
    drawWorldArrow(canvas, camera, point.point,
                   settings.impulseScale * point.normalImpulse * manifold.normal,
                   colours.normalImpulse, settings);
  }
  if (show.frictionImpulses) {
    const Color friction =
        point.friction == FrictionState::Dynamic ? colours.dynamicFriction : colours.staticFriction;
    drawWorldArrow(canvas, camera, point.point,
                   settings.impulseScale * point.tangentImpulse * manifold.tangent(), friction,
                   settings);
  }
  if (show.contactPoints) {
    fillCircle(canvas, at, settings.contactPointRadius, colours.contactPoint, colours.outline,
               settings.outlineWidth);
  }
}

}  // namespace

std::vector<BodyState> classifyBodies(const std::vector<Body>& bodies,
                                      const std::vector<Manifold>& manifolds,
                                      const RenderSettings& settings) {
  std::vector<int> contacts(bodies.size(), 0);
  std::vector<bool> sliding(bodies.size(), false);
  for (const Manifold& manifold : manifolds) {
    if (!validManifold(manifold, bodies.size())) continue;
    for (int i = 0; i < manifold.pointCount; ++i) {
      contacts[manifold.bodyA] += 1;
      contacts[manifold.bodyB] += 1;
      if (slides(manifold, manifold.points[i], bodies, settings)) {
        sliding[manifold.bodyA] = sliding[manifold.bodyB] = true;
      }
    }
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

std::string headsUpLine(const FrameInfo& info) {
  char numbers[128];
  std::snprintf(numbers, sizeof numbers, "step %ld  t = %.3f s  E = %.2f J", info.step, info.time,
                info.energy);
  return info.scene + "  " + info.solver + "  " + numbers;
}

double headsUpHeight(const RenderSettings& settings) {
  return textHeight(settings.textScale) + 2.0 * settings.textMargin;
}

void drawWorldArrow(Canvas& canvas, const Camera& camera, const Vec2& at, const Vec2& vector,
                    Color color, const RenderSettings& settings) {
  Vec2 pixels = camera.toPixelVector(vector);
  const double length = pixels.norm();
  if (length < settings.minArrowLength) return;
  if (length > settings.maxArrowLength) pixels *= settings.maxArrowLength / length;
  const Vec2 from = camera.toPixels(at);
  drawArrow(canvas, from, from + pixels, settings.arrowWidth, settings.arrowHeadLength,
            settings.arrowHeadWidth, color);
}

void drawScene(Canvas& canvas, const Camera& camera, const std::vector<Body>& bodies,
               const std::vector<Manifold>& manifolds, const RenderSettings& settings) {
  const std::vector<BodyState> states = classifyBodies(bodies, manifolds, settings);
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    drawBody(canvas, camera, bodies[i], colourOf(states[i], settings.colours), settings);
  }
  for (const Manifold& manifold : manifolds) {
    for (int i = 0; i < manifold.pointCount; ++i) {
      drawContactPoint(canvas, camera, manifold, manifold.points[i], settings);
    }
  }
  if (!settings.overlays.velocities) return;
  for (const Body& body : bodies) {
    if (body.isStatic()) continue;
    drawWorldArrow(canvas, camera, body.position, settings.velocityScale * body.velocity,
                   settings.colours.velocity, settings);
  }
}

void drawHeadsUp(Canvas& canvas, const std::vector<std::string>& lines,
                 const RenderSettings& settings) {
  const double lineHeight = headsUpHeight(settings);
  const double room = canvas.width() - 2.0 * settings.textMargin;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const double top = double(i) * lineHeight;
    fillRectangle(canvas, Vec2(0.0, top), Vec2(canvas.width(), lineHeight),
                  settings.colours.labelBackground);
    // A line too long for the image is drawn smaller rather than cut off.
    const double width = textWidth(lines[i], settings.textScale);
    const double scale = width > room ? settings.textScale * room / width : settings.textScale;
    drawText(canvas, lines[i], Vec2(settings.textMargin, top + settings.textMargin), scale,
             settings.colours.text);
  }
}

FrameRenderer::FrameRenderer(const Camera& camera, std::string scene,
                             const RenderSettings& settings)
    : camera_(camera), scene_(std::move(scene)), settings_(settings) {}

const Canvas& FrameRenderer::draw(const Simulation& simulation) {
  return draw(simulation.bodies(), simulation.manifolds(),
              {headsUpLine(describe(simulation, scene_))});
}

const Canvas& FrameRenderer::draw(const std::vector<Body>& bodies,
                                  const std::vector<Manifold>& manifolds,
                                  const std::vector<std::string>& headsUp) {
  canvas_.reset(camera_.width, camera_.height, settings_.colours.background);
  drawScene(canvas_, camera_, bodies, manifolds, settings_);
  if (settings_.overlays.headsUp) drawHeadsUp(canvas_, headsUp, settings_);
  return canvas_;
}

}  // namespace impulse2d::render
