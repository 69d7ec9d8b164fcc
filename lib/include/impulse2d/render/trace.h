// Step-by-step frames: a SolverObserver that draws one frame per solver event of a traced step.
// Each frame highlights the contact being resolved, labels the velocity change it wanted and the
// impulse applied, and shows every body with the velocity it has after that impulse.
#pragma once

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

 private:
  void drawHighlight(const SolverEvent& event, const std::vector<Manifold>& manifolds);

  const Simulation& simulation_;
  FrameRenderer renderer_;
  FrameWriter& writer_;
};

/// What one event did, for the trace frame's second heads-up line: "velocity 3: contact 5.0
/// dv = 0.123 m/s  J = (0.456, -0.010) N s" (the wanted velocity change along the normal, and the
/// impulse applied along the normal and the tangent), or for the position phase the penetration
/// removed. "contact 5.0" is point 0 of manifold 5.
std::string describe(const SolverEvent& event);

/// Runs the simulation up to step N (N ≥ 1: the step that ends with stepCount() == N), drawing
/// one frame per solver event of step N to frames/SCENE/SCENE_stepNNNNN_00000.png ... under
/// `root`, and that trace's contact sheet. Returns the writer, which knows the frames written.
/// Simulations that cannot report solver events write no frames (frameCount() == 0).
FrameWriter traceStep(Simulation& simulation, long step, const FrameRenderer& renderer,
                      const std::filesystem::path& root);

}  // namespace impulse2d::render
