// What a frame shows: the bodies coloured by state with a mark of their rotation, each contact
// point with its normal, the step's normal and friction impulses as force arrows (λ/dt), a gauge
// of how close friction is to its limit, heads-up lines, and a legend strip saying what it all
// means (legend.h).
// Draws any Simulation (ours or Box2D's), or bodies and manifolds caught mid-step by a trace.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "impulse2d/render/camera.h"
#include "impulse2d/render/canvas.h"
#include "impulse2d/render/render_settings.h"
#include "impulse2d/simulation.h"

namespace impulse2d::render {

/// What a body is doing, which picks its colour.
enum class BodyState {
  Static,    ///< never moves
  Flying,    ///< no contact points: in flight
  Resting,   ///< in contact and slower than restingSpeed and restingAngularSpeed
  Touching,  ///< in contact and moving, no point sliding: rolling, bouncing or being pushed
  Sliding,   ///< all points of a contact in dynamic friction, or one slipping past slidingSpeed
  Sleeping,  ///< put to sleep by the world (Body::asleep; docs/sleeping.md)
};

/// The state of each body, by the thresholds of `settings`.
std::vector<BodyState> classifyBodies(const std::vector<Body>& bodies,
                                      const std::vector<Manifold>& manifolds,
                                      const RenderSettings& settings);

constexpr int kBodyStateCount = 6;

Color colourOf(BodyState state, const Palette& palette);
/// "static", "flying", "resting", "touching", "sliding", "asleep".
const char* nameOf(BodyState state);

/// How contact impulses become arrows: an impulse λ (N s) over a step dt is the force λ/dt (N),
/// drawn metresPerNewton long.
struct ForceScale {
  double dt = 1.0 / 60.0;        ///< s
  double metresPerNewton = 0.0;  ///< 0: not fitted yet
};

/// N. The largest contact force the bodies will rest on, estimated from their weight: the weight
/// of the tallest column of dynamic bodies (each with those whose centre lies above its bottom
/// over its width), shared by two contact points.
double restingForceEstimate(const std::vector<Body>& bodies, const Vec2& gravity);
/// The scale of a run: settings.forceScale if set, else the one that draws the resting force
/// estimate restingForceLength of the camera's height.
ForceScale fitForceScale(const std::vector<Body>& bodies, const Vec2& gravity, double dt,
                         const Camera& camera, const RenderSettings& settings);
/// How much of its friction a contact uses, |Σλt| / (μ Σλn) over its points: 0 for none, 1 on
/// the limit (the friction cone's edge); 0 when Σλn = 0. The gauge shows it.
double frictionUse(const Manifold& manifold);

/// What a frame showed, for its legend: which body states and which arrow kinds.
struct DrawnKinds {
  /// by BodyState: a body drawn in it
  std::array<bool, kBodyStateCount> states{};
  /// a normal force arrow
  bool normalForces = false;
  /// a friction arrow inside the cone
  bool staticFriction = false;
  /// a friction arrow on the cone
  bool dynamicFriction = false;
  /// a velocity arrow
  bool velocities = false;
  /// a friction gauge
  bool gauges = false;
};

/// What the heads-up line says.
struct FrameInfo {
  /// the scene's name
  std::string scene;
  /// the solver's name
  std::string solver;
  long step = 0;        ///< steps taken
  double time = 0.0;    ///< s, simulated
  double energy = 0.0;  ///< J, kinetic plus potential
};

/// The heads-up facts of a simulation as it stands.
FrameInfo describe(const Simulation& simulation, const std::string& scene);
/// Total kinetic plus potential energy (J) of the dynamic bodies in gravity g.
double totalEnergy(const std::vector<Body>& bodies, const Vec2& gravity);
/// {"scene  solver", "step 120  t = 2.000 s  E = 1234.5 J"}: two short lines, so they can be
/// drawn large enough to read on a contact sheet's thumbnail.
std::vector<std::string> headsUpLines(const FrameInfo& info);
/// Font pixels per pixel of the frame's text, for a frame `frameWidth` pixels wide.
double frameTextScale(const RenderSettings& settings, int frameWidth);
/// Height in pixels of one heads-up line with its background, in a frame that wide.
double headsUpHeight(const RenderSettings& settings, int frameWidth);

/// The bodies and contact overlays, over whatever the canvas holds; returns what it drew.
DrawnKinds drawScene(Canvas& canvas, const Camera& camera, const std::vector<Body>& bodies,
                     const std::vector<Manifold>& manifolds, const ForceScale& forces,
                     const RenderSettings& settings);
/// An arrow from world point `at` along the world displacement `vector` (m), cut to
/// settings.maxArrowLength and left out under settings.minArrowLength: how forces (scaled by
/// ForceScale) and velocities (by velocityScale) are drawn. Returns whether it was drawn.
bool drawWorldArrow(Canvas& canvas, const Camera& camera, const Vec2& at, const Vec2& vector,
                    Color color, const RenderSettings& settings);
/// Lines of text along the top of the canvas, each on a pale background.
void drawHeadsUp(Canvas& canvas, const std::vector<std::string>& lines,
                 const RenderSettings& settings);

/// Draws frames of one camera into a canvas it keeps, so a run allocates its image once. The
/// canvas is the camera's size plus the legend strip under it when the legend is on.
class FrameRenderer {
 public:
  /// Frames of `scene` seen by `camera`, drawn with `settings`.
  FrameRenderer(const Camera& camera, std::string scene, const RenderSettings& settings = {});

  /// The frame of a simulation as it stands. The first call fits the run's force scale to the
  /// simulation's bodies, gravity and dt, unless fitForces was called.
  const Canvas& draw(const Simulation& simulation);
  /// Fits the force scale every later frame uses (fitForceScale), with the substep's length as
  /// the time an impulse acts (a world's manifolds hold its last substep's impulses).
  void fitForces(const Simulation& simulation);
  /// The force scale the frames are drawn with.
  const ForceScale& forces() const { return forces_; }
  /// The frame of bodies and manifolds with the heads-up lines given (none: no heads-up).
  const Canvas& draw(const std::vector<Body>& bodies, const std::vector<Manifold>& manifolds,
                     const std::vector<std::string>& headsUp);

  /// The camera, the scene name and the settings the frames are drawn with.
  const Camera& camera() const { return camera_; }
  /// the scene's name
  const std::string& scene() const { return scene_; }
  /// how frames look
  const RenderSettings& settings() const { return settings_; }
  /// The last frame drawn, for drawing more on top of it.
  Canvas& canvas() { return canvas_; }

 private:
  Camera camera_;
  std::string scene_;
  RenderSettings settings_;
  ForceScale forces_;
  Canvas canvas_;
};

}  // namespace impulse2d::render
