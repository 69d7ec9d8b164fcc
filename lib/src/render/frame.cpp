// One frame of a simulation: bodies by state, what acts on them, the heads-up and legend strips.
#include "impulse2d/render/frame.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <utility>

#include "impulse2d/collide.h"
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

/// Arrow sizes of a frame: proportional to its text size.
struct ArrowSize {
  double width;
  double headLength;
  double headWidth;
};

ArrowSize arrowSize(const Camera& camera, const RenderSettings& settings) {
  return {settings.arrowWidth * camera.textSize, settings.arrowHeadLength * camera.textSize,
          settings.arrowHeadWidth * camera.textSize};
}

/// A body's fill, without its outline: every fill goes down before any outline, so a body's
/// neighbour never paints over its edge.
void drawBodyFill(Drawing& drawing, const Camera& camera, const Body& body, Color fill) {
  drawing.setRole("body");
  if (body.shape.type == ShapeType::Circle) {
    drawing.circle(camera.toPixels(body.position), camera.scale * body.shape.radius, fill, fill,
                   0.0);
    return;
  }
  std::vector<Vec2> corners;
  corners.reserve(body.shape.vertices.size());
  for (const Vec2& vertex : body.shape.vertices) {
    corners.push_back(camera.toPixels(body.toWorld(vertex)));
  }
  drawing.polygon(corners, fill, fill, 0.0);
}

/// A body's outline and, when it moves, the mark of its rotation.
void drawBodyOutline(Drawing& drawing, const Camera& camera, const Body& body,
                     const RenderSettings& settings) {
  const Color outline = settings.colours.outline;
  const double width = settings.outlineWidth * camera.textSize;
  const Vec2 centre = camera.toPixels(body.position);
  drawing.setRole("body outline");
  if (body.shape.type == ShapeType::Circle) {
    drawing.ring(centre, camera.scale * body.shape.radius, outline, width);
  } else {
    std::vector<Vec2> corners;
    corners.reserve(body.shape.vertices.size());
    for (const Vec2& vertex : body.shape.vertices) {
      corners.push_back(camera.toPixels(body.toWorld(vertex)));
    }
    drawing.outline(corners, outline, width);
  }
  if (settings.overlays.rotationMarks && !body.isStatic()) {
    drawing.setRole("rotation mark");
    // To the edge, but no longer than rotationMarkLength: on a long plank a mark to its end
    // would read as a crack.
    const double longest = settings.rotationMarkLength * camera.textSize / camera.scale;  // m
    const double reach = std::min(rotationMarkReach(body.shape), longest);
    const Vec2 edge = camera.toPixels(body.toWorld(Vec2(reach, 0.0)));
    drawing.line(centre, edge, settings.rotationMarkWidth, settings.colours.rotationMark);
  }
}

/// The gauge under a contact: a bar filled to |Σλt| / (μ Σλn), in the static-friction colour
/// below the limit and the dynamic one on it.
void drawFrictionGauge(Drawing& drawing, const Vec2& at, double use, double length, double textSize,
                       const RenderSettings& settings) {
  const Palette& colours = settings.colours;
  const Vec2 size(length, settings.gaugeThickness * textSize);
  const Vec2 corner = at + Vec2(-0.5 * size.x(), settings.contactPointRadius + 2.0);
  const bool onLimit = use >= 1.0 - settings.gaugeLimitTolerance;
  drawing.setRole("friction gauge");
  // The frame as a dark rectangle under the empty bar: two fills, cheaper than a stroke.
  const Vec2 rim = Vec2::Constant(settings.swatchOutlineWidth);
  drawing.rectangle(corner - rim, size + 2.0 * rim, colours.outline);
  drawing.rectangle(corner, size, colours.gaugeBackground);
  const double filled = std::min(use, 1.0) * size.x();
  if (filled > 0.0) {
    drawing.rectangle(corner, Vec2(filled, size.y()),
                      onLimit ? colours.dynamicFriction : colours.staticFriction);
  }
}

/// The middle of a manifold's points (world).
Vec2 middleOf(const Manifold& manifold) {
  Vec2 middle = Vec2::Zero();
  for (int i = 0; i < manifold.pointCount; ++i) middle += manifold.points[i].point;
  return manifold.pointCount > 0 ? Vec2(middle / manifold.pointCount) : middle;
}

/// Pixels: where a point's force arrows start, relative to the point. A manifold's points lie
/// along its tangent; each arrow moves outward from their middle, so on a stack the normal
/// arrows stand beside the box's sides instead of on them.
Vec2 arrowShift(const Camera& camera, const Manifold& manifold, const ContactPoint& point,
                const RenderSettings& settings) {
  if (manifold.pointCount < 2) return Vec2::Zero();
  const Vec2 tangent = manifold.tangent();
  const double side = (point.point - middleOf(manifold)).dot(tangent) >= 0.0 ? 1.0 : -1.0;
  const Vec2 direction = camera.toPixelVector(side * tangent).normalized();
  return settings.contactArrowOffset * camera.textSize * direction;
}

/// The friction force arrow with its limit μN marked across its line: the student sees how
/// much of the cone is used.
void drawFriction(Drawing& drawing, const Camera& camera, const Manifold& manifold,
                  const ContactPoint& point, const ForceScale& forces, const Vec2& shift,
                  const RenderSettings& settings, DrawnKinds& drawn) {
  const Palette& colours = settings.colours;
  const double perImpulse = forces.metresPerNewton / forces.dt;  // m per N s
  const bool dynamic = point.friction == FrictionState::Dynamic;
  drawing.setRole(dynamic ? "dynamic friction" : "static friction");
  const double length = drawWorldArrow(
      drawing, camera, point.point, perImpulse * point.tangentImpulse * manifold.tangent(),
      dynamic ? colours.dynamicFriction : colours.staticFriction, settings, shift, false);
  if (length <= 0.0) return;
  (dynamic ? drawn.dynamicFriction : drawn.staticFriction) = true;
  const double limit = camera.scale * perImpulse * manifold.friction * point.normalImpulse;
  if (!(limit > 0.0) || limit > settings.maxArrowLength * camera.height) return;
  const double sign = point.tangentImpulse >= 0.0 ? 1.0 : -1.0;
  const Vec2 along = camera.toPixelVector(sign * manifold.tangent()).normalized();
  const Vec2 across(-along.y(), along.x());
  const Vec2 start = camera.toPixels(point.point) + shift;
  const Vec2 mark = start + limit * along;
  const double half = 0.5 * settings.limitMarkLength * camera.textSize;
  const double width = 0.5 * arrowSize(camera, settings).width;
  // A faint track from the point to the mark: the room friction has before the point slides.
  drawing.setRole("friction room");
  drawing.line(start, mark, width, withOpacity(colours.frictionLimit, 0.35));
  drawing.setRole("friction limit");
  drawing.line(mark - half * across, mark + half * across, width, colours.frictionLimit);
  drawn.frictionLimits = true;
}

/// Where the surfaces slip past each other at a point: B's velocity relative to A's there,
/// along the tangent.
Vec2 slipVelocity(const std::vector<Body>& bodies, const Manifold& manifold, const Vec2& point) {
  const Vec2 relative =
      bodies[manifold.bodyB].velocityAt(point) - bodies[manifold.bodyA].velocityAt(point);
  return relative.dot(manifold.tangent()) * manifold.tangent();
}

void drawContactPoint(Drawing& drawing, const Camera& camera, const std::vector<Body>& bodies,
                      const Manifold& manifold, const ContactPoint& point, const ForceScale& forces,
                      const RenderSettings& settings, DrawnKinds& drawn) {
  const Overlays& show = settings.overlays;
  const Palette& colours = settings.colours;
  const Vec2 at = camera.toPixels(point.point);
  const Vec2 shift = arrowShift(camera, manifold, point, settings);
  const double perImpulse = forces.metresPerNewton / forces.dt;  // m per N s
  if (show.contactNormals) {
    drawing.setRole("contact normal");
    const Vec2 direction(manifold.normal.x(), -manifold.normal.y());
    drawing.line(at, at + settings.contactNormalLength * direction, settings.contactNormalWidth,
                 colours.contactNormal);
  }
  if (show.normalImpulses) {
    drawing.setRole("normal force");
    drawn.normalForces |= drawWorldArrow(drawing, camera, point.point,
                                         perImpulse * point.normalImpulse * manifold.normal,
                                         colours.normalForce, settings, shift, false) > 0.0;
  }
  if (show.frictionImpulses) {
    drawFriction(drawing, camera, manifold, point, forces, shift, settings, drawn);
  }
  const Vec2 slip = slipVelocity(bodies, manifold, point.point);
  if (show.slidingVelocities && slip.norm() > settings.slidingSpeed) {
    drawing.setRole("sliding velocity");
    const Vec2 below = -camera.textSize * 0.5 * camera.toPixelVector(manifold.normal).normalized();
    drawn.slidingVelocities |=
        drawWorldArrow(drawing, camera, point.point, settings.velocityScale * slip,
                       colours.velocity, settings, below) > 0.0;
  }
  if (show.contactPoints) {
    drawing.setRole("contact point");
    drawing.circle(at, settings.contactPointRadius, colours.contactPoint, colours.outline,
                   settings.swatchOutlineWidth);
  }
}

/// One gauge per contact, under the middle of its points.
void drawContactGauge(Drawing& drawing, const Camera& camera, const Manifold& manifold,
                      const ForceScale& forces, const RenderSettings& settings, DrawnKinds& drawn) {
  double normal = 0.0;
  for (int i = 0; i < manifold.pointCount; ++i) normal += manifold.points[i].normalImpulse;
  if (manifold.friction <= 0.0 || normal / forces.dt <= settings.gaugeMinimumNormalForce) return;
  // No longer than the contact is wide, so the gauges of a row of small boxes stay apart.
  double length = settings.gaugeLength * camera.textSize;
  if (manifold.pointCount == 2) {
    const double span =
        (camera.toPixels(manifold.points[0].point) - camera.toPixels(manifold.points[1].point))
            .norm();
    length = std::min(length, 0.8 * span);
  }
  drawFrictionGauge(drawing, camera.toPixels(middleOf(manifold)), frictionUse(manifold), length,
                    camera.textSize, settings);
  drawn.gauges = true;
}

/// "3.20 N": a force's value, with three significant figures.
std::string newtons(double force) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g N", force);
  return text;
}

/// Each applied load as an arrow whose tip is at its point (it pushes there), labelled F = value;
/// each weight, when asked for, from the centre of mass.
void drawLoads(Drawing& drawing, const Camera& camera, const std::vector<Body>& bodies,
               const ForceScale& forces, const SceneState& state, const RenderSettings& settings,
               DrawnKinds& drawn) {
  const Palette& colours = settings.colours;
  for (const Body& body : bodies) {
    if (body.isStatic()) continue;
    if (settings.overlays.weights) {
      drawing.setRole("weight");
      drawn.weights |= drawWorldArrow(drawing, camera, body.position,
                                      forces.metresPerNewton * body.mass * state.gravity,
                                      colours.load, settings) > 0.0;
    }
    const Vec2 force = body.load.forceAt(state.time);
    if (!settings.overlays.loads || force == Vec2::Zero()) continue;
    const Vec2 point = body.toWorld(body.load.point);
    const Vec2 vector = forces.metresPerNewton * force;
    drawing.setRole("load");
    const double length =
        drawWorldArrow(drawing, camera, point - vector, vector, colours.load, settings);
    if (length <= 0.0) continue;
    drawn.loads = true;
    const Vec2 tail = camera.toPixels(point) - length * camera.toPixelVector(force).normalized();
    drawing.text("F = " + newtons(force.norm()),
                 tail + Vec2(-0.5 * camera.textSize, -1.3 * camera.textSize), camera.textSize,
                 colours.text);
  }
}

/// The weight (N) of the dynamic bodies standing on `base`: those whose centre is above its
/// bottom, each by the share of its width over the base's (a pyramid's box rests half on each of
/// two below it), itself included.
double columnWeight(const std::vector<Body>& bodies, const Body& base, double gravity) {
  double weight = 0.0;
  for (const Body& body : bodies) {
    if (body.isStatic() || body.position.y() < base.bounds.lower.y()) continue;
    const double width = body.bounds.upper.x() - body.bounds.lower.x();
    const double over = std::min(body.bounds.upper.x(), base.bounds.upper.x()) -
                        std::max(body.bounds.lower.x(), base.bounds.lower.x());
    if (over <= 0.0) continue;
    weight += body.mass * gravity * (width > 0.0 ? std::min(1.0, over / width) : 1.0);
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

void addKinds(DrawnKinds& into, const DrawnKinds& drawn) {
  for (std::size_t i = 0; i < into.states.size(); ++i) into.states[i] |= drawn.states[i];
  into.normalForces |= drawn.normalForces;
  into.staticFriction |= drawn.staticFriction;
  into.dynamicFriction |= drawn.dynamicFriction;
  into.frictionLimits |= drawn.frictionLimits;
  into.loads |= drawn.loads;
  into.weights |= drawn.weights;
  into.slidingVelocities |= drawn.slidingVelocities;
  into.velocities |= drawn.velocities;
  into.gauges |= drawn.gauges;
  into.highlight |= drawn.highlight;
  into.velocityChange |= drawn.velocityChange;
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
  // The room each body's arrows have where another rests on it: a contact's arrows point into
  // one of its two bodies, so each of the two points carrying a column's weight is drawn within
  // contactArrowRoom of that body's height. A body with nothing on it has open space above.
  for (const Body& body : bodies) {
    if (body.isStatic()) continue;
    const double own = body.mass * gravity.norm();
    const double weight = columnWeight(bodies, body, gravity.norm());
    const double height = body.bounds.upper.y() - body.bounds.lower.y();
    if (weight > own * (1.0 + 1e-9) && height > 0.0) {
      forces.metresPerNewton =
          std::min(forces.metresPerNewton, settings.contactArrowRoom * height / (0.5 * weight));
    }
  }
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

Palette printPalette() {
  Palette palette;
  palette.background = Color{255, 255, 255, 255};
  palette.staticBody = Color{200, 200, 200, 255};
  palette.outline = Color{0, 0, 0, 255};
  palette.rotationMark = Color{0, 0, 0, 255};
  palette.contactNormal = Color{0, 0, 0, 255};
  palette.text = Color{0, 0, 0, 255};
  palette.stripBackground = Color{255, 255, 255, 255};
  palette.sheetBackground = Color{255, 255, 255, 255};
  palette.sheetLabel = Color{255, 255, 255, 255};
  return palette;
}

std::vector<std::string> headsUpLines(const FrameInfo& info) {
  char numbers[128];
  std::snprintf(numbers, sizeof numbers, "step %ld    t = %.3f s    E = %.2f J", info.step,
                info.time, info.energy);
  return {info.scene + "  ·  " + info.solver, numbers};
}

std::string caption(const FrameInfo& info) {
  char text[96];
  std::snprintf(text, sizeof text, "step %ld   t = %.2f s   E = %.2f J", info.step, info.time,
                info.energy);
  return text;
}

std::vector<Manifold> startingContacts(const std::vector<Body>& bodies, double margin) {
  std::vector<Manifold> manifolds;
  for (std::size_t a = 0; a < bodies.size(); ++a) {
    for (std::size_t b = a + 1; b < bodies.size(); ++b) {
      if (bodies[a].isStatic() && bodies[b].isStatic()) continue;
      const Aabb grown{bodies[a].bounds.lower - Vec2::Constant(margin),
                       bodies[a].bounds.upper + Vec2::Constant(margin)};
      if (!grown.overlaps(bodies[b].bounds)) continue;
      Manifold manifold;
      manifold.bodyA = int(a);
      manifold.bodyB = int(b);
      if (collide(bodies[a], bodies[b], margin, manifold) > 0) manifolds.push_back(manifold);
    }
  }
  return manifolds;
}

double drawWorldArrow(Drawing& drawing, const Camera& camera, const Vec2& at, const Vec2& vector,
                      Color colour, const RenderSettings& settings, const Vec2& shift, bool halo) {
  Vec2 pixels = camera.toPixelVector(vector);
  const double length = pixels.norm();
  if (!(length >= settings.minArrowLength)) return 0.0;
  const double longest = settings.maxArrowLength * camera.height;
  if (length > longest) pixels *= longest / length;
  const ArrowSize size = arrowSize(camera, settings);
  const Vec2 from = camera.toPixels(at) + shift;
  drawing.arrow(from, from + pixels, size.width, size.headLength, size.headWidth, colour,
                halo ? settings.colours.arrowHalo : Color{0, 0, 0, 0});
  return std::min(length, longest);
}

DrawnKinds drawScene(Drawing& drawing, const Camera& camera, const std::vector<Body>& bodies,
                     const std::vector<Manifold>& manifolds, const ForceScale& forces,
                     const SceneState& state, const RenderSettings& settings) {
  DrawnKinds drawn;
  const std::vector<BodyState> states = classifyBodies(bodies, manifolds, settings);
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    drawBodyFill(drawing, camera, bodies[i], colourOf(states[i], settings.colours));
    drawn.states[std::size_t(states[i])] = true;
  }
  // Layers, each painted before the next: fills, outlines, contact arrows and points, gauges,
  // loads.
  drawing.flush();
  for (const Body& body : bodies) drawBodyOutline(drawing, camera, body, settings);
  drawing.flush();
  for (const Manifold& manifold : manifolds) {
    if (!validManifold(manifold, bodies.size())) continue;
    for (int i = 0; i < manifold.pointCount; ++i) {
      drawContactPoint(drawing, camera, bodies, manifold, manifold.points[i], forces, settings,
                       drawn);
    }
  }
  drawing.flush();
  for (const Manifold& manifold : manifolds) {
    if (settings.overlays.frictionGauges && validManifold(manifold, bodies.size())) {
      drawContactGauge(drawing, camera, manifold, forces, settings, drawn);
    }
  }
  drawing.flush();
  drawLoads(drawing, camera, bodies, forces, state, settings, drawn);
  if (!settings.overlays.velocities) return drawn;
  drawing.setRole("velocity");
  for (const Body& body : bodies) {
    if (body.isStatic()) continue;
    drawn.velocities |=
        drawWorldArrow(drawing, camera, body.position, settings.velocityScale * body.velocity,
                       settings.colours.velocity, settings) > 0.0;
  }
  return drawn;
}

namespace {

/// The heads-up strip: its lines on the strip's background, each made smaller only if it would
/// not fit the width.
void drawHeadsUp(Drawing& drawing, const std::vector<std::string>& lines, int width, double height,
                 double size, const RenderSettings& settings) {
  drawing.setRole("heads-up");
  drawing.rectangle(Vec2::Zero(), Vec2(width, height), settings.colours.stripBackground);
  const double margin = settings.textMargin * size;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const double room = width - 2.0 * margin;
    const double natural = drawing.textWidth(lines[i], size);
    const double fitted =
        natural > room ? std::max(settings.minimumTextSize, size * room / natural) : size;
    drawing.text(lines[i], Vec2(margin, margin + double(i) * lineHeight(size)), fitted,
                 settings.colours.text);
  }
}

}  // namespace

FrameRenderer::FrameRenderer(const Camera& camera, std::string scene,
                             const RenderSettings& settings)
    : camera_(camera), scene_(std::move(scene)), settings_(settings) {}

int FrameRenderer::frameHeight() const {
  return camera_.headsUpHeight + camera_.height + camera_.legendHeight;
}

FrameState captureFrame(const Simulation& simulation, const std::string& scene,
                        const RenderSettings& settings) {
  const WorldSettings& world = simulation.settings();
  const FrameInfo info = describe(simulation, scene);
  FrameState state;
  state.bodies = simulation.bodies();
  // A world with substeps reports the last substep's impulses, taken over dt / substeps.
  state.impulseTime = world.dt / std::max(1, world.substeps);
  state.gravity = world.gravity;
  // The loads as they acted in the last (sub)step, beside the contact forces they caused.
  state.scene = SceneState{std::max(0.0, info.time - state.impulseTime), world.gravity};
  state.manifolds = simulation.stepCount() == 0 && simulation.manifolds().empty()
                        ? startingContacts(state.bodies, settings.startingContactMargin)
                        : simulation.manifolds();
  state.headsUp = headsUpLines(info);
  state.caption = caption(info);
  return state;
}

void FrameRenderer::fitForces(const Simulation& simulation) {
  fitForces(captureFrame(simulation, scene_, settings_));
}

void FrameRenderer::fitForces(const FrameState& state) {
  forces_ = fitForceScale(state.bodies, state.gravity, state.impulseTime, camera_, settings_);
}

Frame FrameRenderer::drawOnto(Drawing& whole, const FrameState& state) {
  if (forces_.metresPerNewton <= 0.0) fitForces(state);
  return drawOnto(whole, state.bodies, state.manifolds, state.scene, state.headsUp, state.caption);
}

Frame FrameRenderer::drawOnto(Drawing& whole, const std::vector<Body>& bodies,
                              const std::vector<Manifold>& manifolds, const SceneState& state,
                              const std::vector<std::string>& headsUp, const std::string& caption,
                              const SceneExtra& extra) {
  if (forces_.metresPerNewton <= 0.0)
    forces_ = fitForceScale(bodies, Vec2::Zero(), forces_.dt, camera_, settings_);
  const int height = frameHeight();
  const double top = camera_.headsUpHeight;
  Frame frame;
  frame.sceneCorner = Vec2(0.0, top);
  frame.sceneSize = Vec2(camera_.width, camera_.height);
  frame.caption = caption;
  frame.title = headsUp.empty() ? scene_ : headsUp.front();
  frame.camera = camera_;
  frame.forces = forces_;
  // One drawing, the scene moved down under the heads-up strip: the strips are drawn after it
  // and cover whatever of it reaches past the scene area.
  whole.translate(Vec2(0.0, top));
  whole.rectangle(Vec2::Zero(), Vec2(camera_.width, camera_.height), settings_.colours.background);
  frame.drawn = drawScene(whole, camera_, bodies, manifolds, forces_, state, settings_);
  if (extra) {
    whole.flush();
    extra(whole, frame.drawn);
  } else {
    frame.redraw = [snapshot =
                        std::make_shared<const std::pair<std::vector<Body>, std::vector<Manifold>>>(
                            bodies, manifolds),
                    forces = forces_, state,
                    settings = settings_](Drawing& drawing, const Camera& camera) {
      drawing.rectangle(Vec2::Zero(), Vec2(camera.width, camera.height),
                        settings.colours.background);
      return drawScene(drawing, camera, snapshot->first, snapshot->second, forces, state, settings);
    };
  }
  whole.translate(Vec2(0.0, -top));
  if (settings_.overlays.headsUp) {
    drawHeadsUp(whole, headsUp, camera_.width, top, camera_.textSize, settings_);
  }
  if (settings_.overlays.legend) {
    drawLegend(whole, top + camera_.height, camera_.width, height, frame.drawn, forces_, camera_,
               settings_);
  }
  return frame;
}

}  // namespace impulse2d::render
