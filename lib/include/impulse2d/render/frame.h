// What a frame shows: the bodies coloured by state with a mark of their rotation, and everything
// that acts on them drawn to one force scale: applied loads at their points with their values,
// the step's normal and friction forces at each contact point (λ/dt), the friction limit μN
// marked on each friction arrow, the slip velocity where a contact slides, optionally weights;
// a gauge of how close each contact's friction is to its limit; a heads-up strip on top and a
// legend strip below saying what it all means (legend.h).
// Draws any Simulation (ours or Box2D's), or bodies and manifolds caught mid-step by a trace.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "impulse2d/render/camera.h"
#include "impulse2d/render/drawing.h"
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
/// estimate restingForceLength of the camera's height, or less: so that no body's resting
/// contact arrows run into the next contact's, half the column weight of each dynamic body
/// another rests on (the force at each of its two bottom points) is drawn at most
/// settings.contactArrowRoom of its own height.
ForceScale fitForceScale(const std::vector<Body>& bodies, const Vec2& gravity, double dt,
                         const Camera& camera, const RenderSettings& settings);
/// How much of its friction a contact uses, |Σλt| / (μ Σλn) over its points: 0 for none, 1 on
/// the limit (the friction cone's edge); 0 when Σλn = 0. The gauge shows it.
double frictionUse(const Manifold& manifold);

/// What a frame showed, for its legend: which body states and which arrow kinds.
struct DrawnKinds {
  std::array<bool, kBodyStateCount> states{};  ///< by BodyState: a body drawn in it
  bool normalForces = false;                   ///< a normal force arrow
  bool staticFriction = false;                 ///< a friction arrow inside the cone
  bool dynamicFriction = false;                ///< a friction arrow on the cone
  bool frictionLimits = false;                 ///< a μN mark on a friction arrow
  bool loads = false;                          ///< an applied load's arrow
  bool weights = false;                        ///< a weight's arrow
  bool slidingVelocities = false;              ///< a slip velocity's arrow
  bool velocities = false;                     ///< a body velocity's arrow
  bool gauges = false;                         ///< a friction gauge
  bool highlight = false;                      ///< a trace frame's resolved contact and its impulse
  bool velocityChange = false;                 ///< a trace frame's point velocity before and after
};

/// Adds to `into` every kind `drawn` holds: what a sheet of several frames showed.
void addKinds(DrawnKinds& into, const DrawnKinds& drawn);

/// What the heads-up strip says.
struct FrameInfo {
  std::string scene;    ///< the scene's name
  std::string solver;   ///< the solver's name
  long step = 0;        ///< steps taken
  double time = 0.0;    ///< s, simulated
  double energy = 0.0;  ///< J, kinetic plus potential
};

/// The heads-up facts of a simulation as it stands.
FrameInfo describe(const Simulation& simulation, const std::string& scene);
/// Total kinetic plus potential energy (J) of the dynamic bodies in gravity g.
double totalEnergy(const std::vector<Body>& bodies, const Vec2& gravity);
/// {"scene · solver", "step 120   t = 2.000 s   E = 1234.5 J"}.
std::vector<std::string> headsUpLines(const FrameInfo& info);
/// "step 120   t = 2.00 s   E = 490.37 J": a sheet cell's caption, the heads-up's second line.
std::string caption(const FrameInfo& info);

/// The contacts of bodies set down before any step: pairs whose surfaces are within
/// `margin` (m), so a box placed at rest on the ground is drawn resting at step 0, not flying.
std::vector<Manifold> startingContacts(const std::vector<Body>& bodies, double margin);

/// What a scene shows besides its bodies and manifolds.
struct SceneState {
  /// s: the loads are drawn at their value at this time, the start of the (sub)step whose
  /// contact forces the frame shows.
  double time = 0.0;
  Vec2 gravity = Vec2(0.0, -9.81);  ///< for weights
};

/// The bodies and everything acting on them, in camera pixels; returns what it drew.
DrawnKinds drawScene(Drawing& drawing, const Camera& camera, const std::vector<Body>& bodies,
                     const std::vector<Manifold>& manifolds, const ForceScale& forces,
                     const SceneState& state, const RenderSettings& settings);
/// An arrow from world point `at` along the world displacement `vector` (m), starting `shift`
/// pixels off that point, cut to settings.maxArrowLength of the scene and left out under
/// settings.minArrowLength: how forces (scaled by ForceScale) and velocities (by velocityScale)
/// are drawn. With `halo`, a pale rim under it keeps it visible over bodies (contact forces,
/// which stand beside the bodies' edges and are many, go without). Returns the arrow's pixel
/// length (0: not drawn).
double drawWorldArrow(Drawing& drawing, const Camera& camera, const Vec2& at, const Vec2& vector,
                      Color colour, const RenderSettings& settings,
                      const Vec2& shift = Vec2::Zero(), bool halo = true);

/// Draws a frame's scene again through another camera (a sheet's cell, with its own text size),
/// its background included; returns what it drew.
using SceneRedraw = std::function<DrawnKinds(Drawing&, const Camera&)>;

/// A frame: its picture, where the scene area lies in it, and what a sheet needs to show it in a
/// cell of its own: its caption, its camera and force scale, and a way to draw its scene again.
struct Frame {
  Picture picture;                  ///< the whole frame: heads-up strip, scene, legend strip
  Vec2 sceneCorner = Vec2::Zero();  ///< pixels: the scene area's top left corner
  Vec2 sceneSize = Vec2::Zero();    ///< pixels
  std::string caption;              ///< under its cell on a sheet
  std::string title;                ///< the heads-up's first line: scene and solver
  Camera camera;                    ///< of the scene area
  ForceScale forces;                ///< the run's
  DrawnKinds drawn;                 ///< what the scene showed, for a sheet's legend
  /// The scene drawn again at a cell's size; empty when only the picture can show it (a trace
  /// frame, whose highlight is drawn once), and a sheet then shrinks the picture.
  SceneRedraw redraw;
  /// A comparison's frame: its panels, left to right, each with its label (composePanels).
  std::vector<Frame> panels;
  std::vector<std::string> panelLabels;  ///< one per panel
};

/// Extra drawing over a frame's scene (a trace frame's highlight), in camera pixels; it marks
/// what it drew in DrawnKinds so the legend names it.
using SceneExtra = std::function<void(Drawing&, DrawnKinds&)>;

/// What a frame of a simulation shows, taken as the simulation stands, so that it can be drawn
/// once the run is over and its camera known.
struct FrameState {
  std::vector<Body> bodies;          ///< the bodies as the simulation stands
  std::vector<Manifold> manifolds;   ///< at step 0, the starting contacts (startingContacts)
  SceneState scene;                  ///< the time and gravity its loads are drawn at
  std::vector<std::string> headsUp;  ///< headsUpLines
  std::string caption;               ///< the frame's caption on a contact sheet
  Vec2 gravity = Vec2::Zero();       ///< m/s², for the force scale
  double impulseTime = 0.0;          ///< s: a (sub)step, over which the manifolds' impulses act
};

/// The frame state of a simulation as it stands, for a scene of that name.
FrameState captureFrame(const Simulation& simulation, const std::string& scene,
                        const RenderSettings& settings);

/// Draws frames of one camera. The picture is the frame's width × height: the heads-up strip,
/// the scene area (the camera's), the legend strip.
class FrameRenderer {
 public:
  /// Frames of `scene` through `camera`, drawn with `settings`.
  FrameRenderer(const Camera& camera, std::string scene, const RenderSettings& settings = {});

  /// The frame of a simulation as it stands. The first call fits the run's force scale to the
  /// simulation's bodies, gravity and dt, unless fitForces was called.
  Frame draw(const Simulation& simulation);
  /// The frame of a captured state; the first call fits the force scale to it, unless fitForces
  /// was called.
  Frame draw(const FrameState& state);
  /// Fits the force scale every later frame uses (fitForceScale), with the substep's length as
  /// the time an impulse acts (a world's manifolds hold its last substep's impulses).
  void fitForces(const Simulation& simulation);
  /// The same from a captured state.
  void fitForces(const FrameState& state);
  /// The camera of the frames that follow (a run's camera follows a body from frame to frame).
  void setCamera(const Camera& camera) { camera_ = camera; }
  /// The run's force scale (fitted by the first frame or fitForces).
  const ForceScale& forces() const { return forces_; }
  /// The frame of bodies and manifolds, with the heads-up lines and caption given.
  Frame draw(const std::vector<Body>& bodies, const std::vector<Manifold>& manifolds,
             const SceneState& state, const std::vector<std::string>& headsUp,
             const std::string& caption, const SceneExtra& extra = {});
  /// The frame of a captured state drawn onto `whole`, a canvas of the frame's size (the
  /// browser's MarkList): the Frame without its picture. draw() draws a picture this way.
  Frame drawOnto(Drawing& whole, const FrameState& state);
  /// The same for bodies and manifolds, with the heads-up lines and caption given.
  Frame drawOnto(Drawing& whole, const std::vector<Body>& bodies,
                 const std::vector<Manifold>& manifolds, const SceneState& state,
                 const std::vector<std::string>& headsUp, const std::string& caption,
                 const SceneExtra& extra = {});

  /// The camera of every frame.
  const Camera& camera() const { return camera_; }
  /// The scene's name, for the heads-up strip.
  const std::string& scene() const { return scene_; }
  /// The settings frames are drawn with.
  const RenderSettings& settings() const { return settings_; }
  /// pixels, of the whole frame
  int frameWidth() const { return camera_.width; }
  /// pixels, of the whole frame: the strips and the scene area
  int frameHeight() const;
  /// Every drawing call of the frames that follow goes to `log` too (for tests); null: none.
  void setLog(DrawingLog* log) { log_ = log; }
  /// The log drawing calls go to, or null.
  DrawingLog* log() const { return log_; }

 private:
  Camera camera_;
  std::string scene_;
  RenderSettings settings_;
  ForceScale forces_;
  DrawingLog* log_ = nullptr;
};

}  // namespace impulse2d::render
