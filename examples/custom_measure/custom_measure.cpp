// A measure of your own over a shipped lecture scene: how far the bodies creep from where they
// started (m) and the deepest penetration seen (m) over the whole run, for each contact method.
// A resting stack should score near zero on both; the methods differ in how near.
//   custom_measure [SCENE]    SCENE defaults to the shipped stack.toml
#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "impulse2d/scene/scene_file.h"
#include "impulse2d/simulation.h"

using namespace impulse2d;

namespace {

struct Measure {
  double largestCreep = 0.0;        // m, farthest any dynamic body got from its start
  double largestPenetration = 0.0;  // m, over every step
};

Measure runAndMeasure(Scene scene, const std::string& solver) {
  scene.solver = solver;
  auto world = buildWorld(scene);
  const std::vector<Body> start = world->bodies();
  Measure measure;
  for (int step = 0; step < scene.steps; ++step) {
    world->step();
    measure.largestPenetration = std::max(measure.largestPenetration, largestPenetration(*world));
    for (size_t index = 0; index < start.size(); ++index) {
      if (start[index].type != BodyType::Dynamic) continue;
      const double creep = (world->bodies()[index].position - start[index].position).norm();
      measure.largestCreep = std::max(measure.largestCreep, creep);
    }
  }
  return measure;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string path = argc > 1 ? argv[1] : SCENES_DIR "/stack.toml";
  try {
    const SceneFile scene = loadSceneFile(path);
    std::printf("%s: %d steps\n%-12s %14s %18s\n", scene.name.c_str(), scene.steps, "method",
                "creep (m)", "penetration (m)");
    for (const char* solver : {"micro", "sequential", "reference", "soft_step"}) {
      const Measure measure = runAndMeasure(scene, solver);
      std::printf("%-12s %14.6f %18.6f\n", solver, measure.largestCreep,
                  measure.largestPenetration);
    }
  } catch (const std::exception& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return 1;
  }
  return 0;
}
