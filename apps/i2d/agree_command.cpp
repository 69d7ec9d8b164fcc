// `i2d agree`: how far each of our methods strays from Box2D on one scene, as Markdown tables
// (impulse2d/box2d/agreement.h, docs/box2d-reference.md).
#include <iostream>

#include "commands.h"
#include "failures.h"
#include "impulse2d/box2d/agreement.h"
#include "scene_setup.h"

namespace i2d {

int agreeCommand(const AgreeOptions& options) {
  const impulse2d::SceneFile scene = loadScene(options.scene);
  const impulse2d::Agreement agreement = impulse2d::measureAgreement(scene, options.solvers);
  std::cout << (options.summaryOnly ? impulse2d::agreementSummary(agreement)
                                    : impulse2d::agreementTable(agreement));
  return kSuccess;
}

}  // namespace i2d
