// Frames as Cairo pictures: the frame's marks (FrameRenderer::drawOnto) painted into a recording.
#include "impulse2d/render/frame.h"

namespace impulse2d::render {

Frame FrameRenderer::draw(const Simulation& simulation) {
  return draw(captureFrame(simulation, scene_, settings_));
}

Frame FrameRenderer::draw(const FrameState& state) {
  if (forces_.metresPerNewton <= 0.0) fitForces(state);
  return draw(state.bodies, state.manifolds, state.scene, state.headsUp, state.caption);
}

Frame FrameRenderer::draw(const std::vector<Body>& bodies, const std::vector<Manifold>& manifolds,
                          const SceneState& state, const std::vector<std::string>& headsUp,
                          const std::string& caption, const SceneExtra& extra) {
  const Picture picture(camera_.width, frameHeight());
  Frame frame;
  {
    Drawing whole(picture, log_);
    frame = drawOnto(whole, bodies, manifolds, state, headsUp, caption, extra);
  }
  frame.picture = picture;
  return frame;
}

}  // namespace impulse2d::render
