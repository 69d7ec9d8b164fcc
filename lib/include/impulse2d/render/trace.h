// Step-by-step frames: a SolverObserver that draws one frame per solver event of a traced step,
// telling in the lecture's words what happened: which contact was resolved and why, its closing
// speed before and after, the impulse, the accelerative velocity, and whether friction held
// (|λt| against μλn); the point's velocity before and after are drawn as arrows.
#pragma once

#include <string>
#include <vector>

#include "impulse2d/render/frame.h"
#include "impulse2d/render/frame_writer.h"
#include "impulse2d/simulation.h"
#include "impulse2d/solver.h"

namespace impulse2d::render {

/// What one event did, in the lecture's words: the lines a trace frame adds under its heads-up.
struct EventStory {
  /// "velocity 3: contact 5.0" (soft step: "substep 3: ..."): the thumbnail's caption
  std::string label;
  std::vector<std::string> lines;  ///< the heads-up lines
};

/// The story of `event`, from the bodies before its impulse (`before`) and after it (`after`),
/// under `solver` ("micro" picks the worst point first; the others sweep in order) with time step
/// dt. `partner` is the other point of the same manifold that one impulse resolved with this one
/// (the micro-collision resolver's pair of corners), -1 when it was resolved alone. Only the point
/// that closes fastest is called "the worst closing speed"; a frictionless contact gets no
/// friction line.
EventStory tellEvent(const SolverEvent& event, const std::vector<Body>& before,
                     const std::vector<Body>& after, const std::vector<Manifold>& manifolds,
                     const std::string& solver, double dt, int partner = -1);

/// Watches one step of a simulation and writes a frame for every solver event in it.
class TraceRecorder : public SolverObserver {
 public:
  /// Frames of the step `simulation` is taking go to `writer`, drawn with the camera, scene and
  /// settings of `renderer` (velocity arrows always on: they are what an impulse changes).
  TraceRecorder(const Simulation& simulation, const FrameRenderer& renderer, FrameWriter& writer);

  void onSolverEvent(const SolverEvent& event, const std::vector<Body>& bodies,
                     const std::vector<Manifold>& manifolds) override;
  /// The first event's "before" is the step's velocities after its forces, as its contacts close.
  void onVelocitiesChanged(const std::vector<Body>& bodies) override;

 private:
  void drawHighlight(Drawing& drawing, DrawnKinds& drawn, const SolverEvent& event,
                     const std::vector<Body>& bodies, const std::vector<Manifold>& manifolds) const;

  const Simulation& simulation_;
  FrameRenderer renderer_;
  FrameWriter& writer_;
  std::vector<Body> before_;         ///< the bodies as the last event left them
  std::vector<Body> impulseBefore_;  ///< the bodies before the impulse the event belongs to
  SolverEvent last_;                 ///< the last event, to find a pair's second point
};

/// Runs the simulation up to step N (N ≥ 1: the step that ends with stepCount() == N), drawing
/// one frame per solver event of step N to frames/SCENE/SCENE_stepNNNNN_00000.png ... under
/// `root`, and that trace's contact sheet (velocity events first). Returns the writer, which
/// knows the frames written. Simulations that cannot report solver events write no frames.
FrameWriter traceStep(Simulation& simulation, long step, const FrameRenderer& renderer,
                      const std::filesystem::path& root, ImageFormat format = ImageFormat::Png);

}  // namespace impulse2d::render
