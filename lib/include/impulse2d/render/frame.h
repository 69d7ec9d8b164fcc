// What a frame shows: the bodies coloured by state with a mark of their rotation, each contact
// point with its normal, the step's normal and friction impulses as arrows, and a heads-up line.
// Draws any Simulation (ours or Box2D's), or bodies and manifolds caught mid-step by a trace.
#pragma once

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
  Sliding,   ///< a contact point in dynamic friction or slipping faster than slidingSpeed
  Sleeping,  ///< put to sleep by the world (Body::asleep; docs/sleeping.md)
};

/// The state of each body, by the thresholds of `settings`.
std::vector<BodyState> classifyBodies(const std::vector<Body>& bodies,
                                      const std::vector<Manifold>& manifolds,
                                      const RenderSettings& settings);

Color colourOf(BodyState state, const Palette& palette);

/// What the heads-up line says.
struct FrameInfo {
  std::string scene;
  std::string solver;
  long step = 0;        ///< steps taken
  double time = 0.0;    ///< s, simulated
  double energy = 0.0;  ///< J, kinetic plus potential
};

/// The heads-up facts of a simulation as it stands.
FrameInfo describe(const Simulation& simulation, const std::string& scene);
/// Total kinetic plus potential energy (J) of the dynamic bodies in gravity g.
double totalEnergy(const std::vector<Body>& bodies, const Vec2& gravity);
/// "scene  solver  step 120  t = 2.000 s  E = 1234.5 J"
std::string headsUpLine(const FrameInfo& info);
/// Height in pixels of one heads-up line with its background.
double headsUpHeight(const RenderSettings& settings);

/// The bodies and contact overlays, over whatever the canvas holds.
void drawScene(Canvas& canvas, const Camera& camera, const std::vector<Body>& bodies,
               const std::vector<Manifold>& manifolds, const RenderSettings& settings);
/// An arrow from world point `at` along the world displacement `vector` (m), cut to
/// settings.maxArrowLength and left out under settings.minArrowLength: how impulses (scaled by
/// impulseScale) and velocities (by velocityScale) are drawn.
void drawWorldArrow(Canvas& canvas, const Camera& camera, const Vec2& at, const Vec2& vector,
                    Color color, const RenderSettings& settings);
/// Lines of text along the top of the canvas, each on a pale background.
void drawHeadsUp(Canvas& canvas, const std::vector<std::string>& lines,
                 const RenderSettings& settings);

/// Draws frames of one camera into a canvas it keeps, so a run allocates its image once.
class FrameRenderer {
 public:
  FrameRenderer(const Camera& camera, std::string scene, const RenderSettings& settings = {});

  /// The frame of a simulation as it stands.
  const Canvas& draw(const Simulation& simulation);
  /// The frame of bodies and manifolds with the heads-up lines given (none: no heads-up).
  const Canvas& draw(const std::vector<Body>& bodies, const std::vector<Manifold>& manifolds,
                     const std::vector<std::string>& headsUp);

  const Camera& camera() const { return camera_; }
  const std::string& scene() const { return scene_; }
  const RenderSettings& settings() const { return settings_; }
  /// The last frame drawn, for drawing more on top of it.
  Canvas& canvas() { return canvas_; }

 private:
  Camera camera_;
  std::string scene_;
  RenderSettings settings_;
  Canvas canvas_;
};

}  // namespace impulse2d::render
