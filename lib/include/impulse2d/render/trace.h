// Step-by-step frames: a SolverObserver that draws one frame per solver event of a traced step,
// telling in the lecture's words what happened: which contact was resolved and why, its closing
// speed before and after, the impulse, the accelerative velocity, and whether friction held
// (|λt| against μλn); the point's velocity before and after are drawn as arrows.
#pragma once

#include <string>
#include <vector>

#include "impulse2d/render/event_story.h"
#include "impulse2d/render/frame.h"
#include "impulse2d/render/frame_writer.h"
#include "impulse2d/simulation.h"
#include "impulse2d/solver.h"

namespace impulse2d::render {

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
  EventTeller teller_;
};

/// Runs the simulation up to step N (N ≥ 1: the step that ends with stepCount() == N), drawing
/// one frame per solver event of step N to frames/SCENE/SCENE_stepNNNNN_00000.png ... under
/// `root`, and that trace's contact sheet (velocity events first). Returns the writer, which
/// knows the frames written. Simulations that cannot report solver events write no frames.
FrameWriter traceStep(Simulation& simulation, long step, const FrameRenderer& renderer,
                      const std::filesystem::path& root, ImageFormat format = ImageFormat::Png);

}  // namespace impulse2d::render
